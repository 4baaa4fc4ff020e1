// SPDX-License-Identifier: BSD-3-Clause
// calls lc::sr::intersectFlat (core/sr/local_ray_tracing.cpp) through the generated
// lcFlatTriangleHit (lc::sr::triangleLineHit, clamped: the rasteriser decides coverage): the
// pixel's ray from the camera against the flat apparent triangle a0 a1 a2, distance s and
// barycentrics u, v.
void lcFlatHit(vec3 d, vec3 a0, vec3 a1, vec3 a2, out float s, out float u, out float v)
{
  vec4 hit = lcFlatTriangleHit(vec3(0.0), d, a0, a1, a2);
  s = hit.x;
  u = hit.y;
  v = hit.z;
}
