// mirrors lc::sr::makeRestRay + lc::sr::intersectRest (core/sr/local_ray_tracing.cpp, seed 003
// eq. 15-16): the rest-frame ray x'(sigma) = obs' + sigma (-1, dir') with dir' and D from the
// generated lcBoostDirection and lcRestRayDoppler (D = 1 / (gamma (1 - beta.n)), n = -d the
// direction from the source to the observer); Moeller-Trumbore against the rest triangle
// p0 p1 p2 (hand-written, with a float-sized edge tolerance). False: no hit.
bool lcRestRayHit(vec3 d, vec3 beta, vec3 obs, vec3 p0, vec3 p1, vec3 p2, out float sigma, out float D, out float u, out float v)
{
  vec3 dir = lcBoostDirection(beta, d);
  vec3 e1 = p1 - p0, e2 = p2 - p0;
  vec3 pvec = cross(dir, e2);
  float det = dot(e1, pvec);
  sigma = D = u = v = 0.0;
  if (abs(det) < 1e-10 * length(e1) * length(e2)) return false;
  float inv = 1.0 / det;
  vec3 tvec = obs - p0;
  u = dot(tvec, pvec) * inv;
  // A float-sized tolerance: shared edges overlap instead of cracking; depth decides.
  const float eps = 2e-6;
  if (u < -eps || u > 1.0 + eps) return false;
  vec3 q = cross(tvec, e1);
  v = dot(dir, q) * inv;
  if (v < -eps || u + v > 1.0 + eps) return false;
  sigma = dot(e2, q) * inv;
  D = lcRestRayDoppler(beta, d);
  return sigma > 0.0;
}
