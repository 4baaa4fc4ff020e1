// mirrors lc::sr::PinholeCamera::Basis::viewDirection (core/sr/camera.cpp) at window
// coordinates fragCoord (gl_FragCoord.xy; pixel row 0 of the camera at the top).
vec3 lcViewDir(vec2 fragCoord)
{
  float px = fragCoord.x, py = lcH - fragCoord.y;
  return normalize(lcFocal * lcFwdF + (px - lcCx) * lcRightF - (py - lcCy) * lcUpF);
}
