// SPDX-License-Identifier: BSD-3-Clause
// lc::Camera::direction (core/scene/camera.hpp) for the pixel whose centre is at window
// coordinates fragCoord. Its formulas, lcScreenCoordinates, lcPinholeScreenDirection and
// lcPanoramaScreenDirection, are generated from the core's; only OpenGL's convention is here:
// gl_FragCoord.xy counts rows from the bottom, the camera from the top.
vec3 lcCameraDirection(vec2 fragCoord)
{
  vec2 s = lcScreenCoordinates(fragCoord.x, lcHeight - fragCoord.y, lcWidth, lcHeight);
  if (lcProjection == 0)
    return lcPinholeScreenDirection(s.x, s.y, lcTanHalfX, lcTanHalfY, lcForward, lcRight, lcUp);
  return lcPanoramaScreenDirection(s.x, s.y, lcHalfX, lcHalfY, lcForward, lcRight, lcUp);
}
