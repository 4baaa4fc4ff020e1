// mirrors lc::sr::intersectFlat (core/sr/local_ray_tracing.cpp): the pixel's ray from the camera
// against the flat apparent triangle a0 a1 a2, for distance s and barycentrics u, v. The
// rasteriser decides coverage, so a marginal miss in float is clamped onto the triangle.
void lcFlatHit(vec3 d, vec3 a0, vec3 a1, vec3 a2, out float s, out float u, out float v)
{
  vec3 e1 = a1 - a0, e2 = a2 - a0;
  vec3 pvec = cross(d, e2);
  float det = dot(e1, pvec);
  float inv = abs(det) > 1e-30 ? 1.0 / det : 0.0;
  vec3 tvec = -a0;
  u = dot(tvec, pvec) * inv;
  vec3 q = cross(tvec, e1);
  v = dot(d, q) * inv;
  s = dot(e2, q) * inv;
  u = clamp(u, 0.0, 1.0);
  v = clamp(v, 0.0, 1.0 - u);
  if (!(s > 0.0)) s = length((1.0 - u - v) * a0 + u * a1 + v * a2);
}
