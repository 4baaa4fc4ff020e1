// mirrors lc::Camera::project (core/scene/camera.hpp) in clip space: pinhole or panorama. Depth is
// lambda / lambdaMax mapped to [-1, 1] (times w for the pinhole, so that after the perspective
// divide every image of every layer shares one depth scale); a panorama triangle is unwrapped
// next to its centroid's azimuth (and moved by a full turn when lcWrap asks for its twin).
vec4 lcProjectImageDirection(vec3 d, vec3 centroidDir, float lambda)
{
  const float twoPi = 6.28318530717958647;
  float depth = 2.0 * lambda / lcMaxLambda - 1.0;
  if (lcProjection == 0)
  {
    float w = dot(d, lcForward);
    return vec4(dot(d, lcRight) / lcTanHalfX, dot(d, lcUp) / lcTanHalfY, depth * w, w);
  }
  float azC = atan(-dot(centroidDir, lcRight), dot(centroidDir, lcForward));
  float az = atan(-dot(d, lcRight), dot(d, lcForward));
  float delta = az - azC;
  delta -= twoPi * floor((delta + 0.5 * twoPi) / twoPi);
  az = azC + delta;
  if (lcWrap != 0) az -= (azC >= 0.0 ? twoPi : -twoPi);
  float el = asin(clamp(dot(d, lcUp), -1.0, 1.0));
  return vec4(-az / lcHalfX, el / lcHalfY, depth, 1.0);
}
