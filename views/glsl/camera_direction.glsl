// mirrors lc::Camera::direction (core/camera.hpp): the frame direction of the pixel at
// gl_FragCoord (pixel centre; the camera's row 0 at the top is the window's last row).
vec3 lcCameraDirection()
{
  float sx = 2.0 * gl_FragCoord.x / lcWidth - 1.0;
  float sy = 2.0 * gl_FragCoord.y / lcHeight - 1.0;
  if (lcProjection == 0)
    return normalize(lcForward + sx * lcTanHalfX * lcRight + sy * lcTanHalfY * lcUp);
  float az = -sx * lcHalfX, el = sy * lcHalfY;
  return normalize(cos(el) * (cos(az) * lcForward - sin(az) * lcRight) + sin(el) * lcUp);
}
