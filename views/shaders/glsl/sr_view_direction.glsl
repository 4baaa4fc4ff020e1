// calls lc::sr::pinholeViewDirection (core/sr/camera.hpp, generated lcSrViewDirection) at window
// coordinates fragCoord (gl_FragCoord.xy; pixel row 0 of the camera at the top).
vec3 lcViewDir(vec2 fragCoord)
{
  return lcSrViewDirection(fragCoord.x, lcHeight - fragCoord.y, lcFocal, lcCx, lcCy, lcSrForward, lcSrRight, lcSrUp);
}
