// mirrors lc::Camera::direction (core/scene/camera.hpp) up to its screen coordinates: sx, sy of
// the pixel whose centre is at window coordinates fragCoord (gl_FragCoord.xy: origin at the
// bottom left; the camera's row 0 at the top is the window's last row). The directions
// themselves, lcPinholeDirection and lcPanoramaDirection, are generated from the core's.
vec3 lcCameraDirection(vec2 fragCoord)
{
  float sx = 2.0 * fragCoord.x / lcWidth - 1.0;
  float sy = 2.0 * fragCoord.y / lcHeight - 1.0;
  if (lcProjection == 0)
    return lcPinholeDirection(sx * lcTanHalfX, sy * lcTanHalfY, lcForward, lcRight, lcUp);
  return lcPanoramaDirection(-sx * lcHalfX, sy * lcHalfY, lcForward, lcRight, lcUp);
}
