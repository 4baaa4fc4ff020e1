// mirrors lc::sr::makeRestRay + lc::sr::intersectRest (core/sr/local_ray_tracing.cpp, seed 003
// eq. 15-16): the rest-frame ray x'(sigma) = obs' + sigma (-1, dir'), dir' = k'/w, D = 1/w for
// the S generator (-1, d) boosted by Lambda(-beta): w = gamma (1 + beta.d), i.e.
// D = 1 / (gamma (1 - beta.n)) with n = -d the direction from the source to the observer;
// Moeller-Trumbore against the rest triangle p0 p1 p2. False: no hit.
bool lcRestRayHit(vec3 d, vec3 beta, vec3 obs, vec3 p0, vec3 p1, vec3 p2, out float sigma, out float D, out float u, out float v)
{
  float g = inversesqrt(1.0 - dot(beta, beta));
  float bd = dot(beta, d);
  float w = g * (1.0 + bd);
  vec3 dir = (g * beta + d + (g * g / (g + 1.0)) * bd * beta) / w;
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
  D = 1.0 / w;
  return sigma > 0.0;
}
