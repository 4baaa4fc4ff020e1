// mirrors lc::Camera::direction (core/scene/camera.hpp): the frame direction through the pixel whose
// centre is at window coordinates fragCoord (gl_FragCoord.xy: origin at the bottom left; the
// camera's row 0 at the top is the window's last row).
vec3 lcCameraDirection(vec2 fragCoord)
{
  float sx = 2.0 * fragCoord.x / lcWidth - 1.0;
  float sy = 2.0 * fragCoord.y / lcHeight - 1.0;
  if (lcProjection == 0)
    return normalize(lcForward + sx * lcTanHalfX * lcRight + sy * lcTanHalfY * lcUp);
  float az = -sx * lcHalfX, el = sy * lcHalfY;
  return normalize(cos(el) * (cos(az) * lcForward - sin(az) * lcRight) + sin(el) * lcUp);
}
