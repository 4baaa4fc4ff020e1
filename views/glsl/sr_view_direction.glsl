// mirrors lc::sr::PinholeCamera::Basis::viewDirection (core/sr/camera.cpp) at the fragment's
// pixel centre (pixel row 0 at the top).
vec3 lcViewDir()
{
  float px = gl_FragCoord.x, py = lcH - gl_FragCoord.y;
  return normalize(lcFocal * lcFwdF + (px - lcCx) * lcRightF - (py - lcCy) * lcUpF);
}
