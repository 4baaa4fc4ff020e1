// mirrors lc::sr::SrRenderer::render's shading (core/sr/renderer.cpp): Phong in the emitter's
// rest frame (light and view aberrated there), the observed temperature D T (or the reflected
// light's, Doppler-shifted in and out), its Planck colour.
vec3 lcShade(vec3 d, float depth, float D, float u, float v, vec3 n0, vec3 n1, vec3 n2, vec3 beta,
             float T, vec4 mat)
{
  vec3 inS = normalize(depth * d - lcLightRel);  // light -> apparent hit, in S
  float f = 1.0;
  if (lcShading != 0)
  {
    vec3 vIn = lcAberrateToRest(beta, inS);
    vec3 vOut = lcAberrateToRest(beta, -d);
    vec3 n = normalize((1.0 - u - v) * n0 + u * n1 + v * n2);
    if (dot(n, vOut) < 0.0) n = -n;
    float diff = max(0.0, -dot(n, vIn));
    vec3 h = normalize(vOut - vIn);
    float spec = diff > 0.0 ? pow(max(0.0, dot(n, h)), mat.w) : 0.0;
    f = mat.x + mat.y * diff + mat.z * spec;
  }
  float Tobs = T;
  if (lcReflected != 0)
    Tobs = lcLightT * (lcDoppler != 0 ? (1.0 - dot(beta, inS)) / (1.0 - dot(beta, -d)) : 1.0);
  else if (lcDoppler != 0)
    Tobs = D * T;
  return clamp(f * lcPlanckLookup(Tobs), 0.0, 1.0);
}
