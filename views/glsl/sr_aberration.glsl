// mirrors lc::sr::aberrateToRest (core/sr/doppler.cpp): the spatial part of Lambda(-beta) (1, k),
// normalised by its time part.
vec3 lcAberrateToRest(vec3 beta, vec3 k)
{
  float g = inversesqrt(1.0 - dot(beta, beta));
  float bk = dot(beta, k);
  return (k - g * beta + (g * g / (g + 1.0)) * bk * beta) / (g * (1.0 - bk));
}
