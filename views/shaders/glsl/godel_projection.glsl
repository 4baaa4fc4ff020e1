// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::Camera::project (core/scene/camera.hpp) in clip space, through the generated
// lcPinholeHomogeneous and lcPanoramaScreen. Two things are the GPU's own, with no core twin:
// the depth, lambda / lambdaMax mapped to [-1, 1] (times w for the pinhole, so that after the
// perspective divide every image of every layer shares one depth scale), and the panorama seam:
// a triangle's vertices are unwrapped next to its centroid (one turn is 2 pi / lcHalfX in screen
// offsets) and moved by a full turn when lcWrap asks for its twin (the CPU rasteriser instead
// draws a triangle straddling the seam twice, in pixels).
uniform float lcMaxLambda;
uniform int lcWrap;
vec4 lcProjectImageDirection(vec3 d, vec3 centroidDir, float lambda)
{
  float depth = 2.0 * lambda / lcMaxLambda - 1.0;
  if (lcProjection == 0)
  {
    vec3 h = lcPinholeHomogeneous(d, lcForward, lcRight, lcUp, lcTanHalfX, lcTanHalfY);
    return vec4(h.x, h.y, depth * h.z, h.z);
  }
  float turn = 6.28318530717958647 / lcHalfX;
  vec2 s = lcPanoramaScreen(d, lcForward, lcRight, lcUp, lcHalfX, lcHalfY);
  float centre = lcPanoramaScreen(centroidDir, lcForward, lcRight, lcUp, lcHalfX, lcHalfY).x;
  float delta = s.x - centre;
  delta -= turn * floor((delta + 0.5 * turn) / turn);
  s.x = centre + delta;
  if (lcWrap != 0) s.x += (centre <= 0.0 ? turn : -turn);
  return vec4(s, depth, 1.0);
}
