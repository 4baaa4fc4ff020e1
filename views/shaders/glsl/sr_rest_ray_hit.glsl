// SPDX-License-Identifier: BSD-3-Clause
// calls lc::sr::makeRestRay + lc::sr::intersectRest (core/sr/local_ray_tracing.cpp, seed 003
// eq. 15-16) through the generated lcBoostDirection, lcRestRayDoppler and lcRestTriangleHit
// (lc::sr::triangleLineHit with the GPU's float tolerances): the rest-frame ray
// x'(sigma) = obs' + sigma (-1, dir') against the rest triangle p0 p1 p2. False: no hit.
bool lcRestRayHit(vec3 d, vec3 beta, vec3 obs, vec3 p0, vec3 p1, vec3 p2, out float sigma, out float D, out float u, out float v)
{
  vec4 hit = lcRestTriangleHit(obs, lcBoostDirection(beta, d), p0, p1, p2);
  sigma = hit.x;
  u = hit.y;
  v = hit.z;
  D = lcRestRayDoppler(beta, d);
  return hit.w > 0.5;
}
