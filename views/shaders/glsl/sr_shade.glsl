// SPDX-License-Identifier: BSD-3-Clause
// calls lc::sr::srShading (core/sr/renderer.hpp, SrRenderer's shading; generated lcSrShading) with
// the object's and the options' uniforms, then clamp(factor Planck(temperature)) as SrRenderer does.
vec3 lcShade(vec3 d, float depth, float D, float u, float v, vec3 n0, vec3 n1, vec3 n2)
{
  vec2 s = lcSrShading(d, depth, D, u, v, n0, n1, n2, lcBeta, lcTemperature, lcMaterial, lcLightRel, lcLightT,
                       float(lcShading), float(lcDoppler), float(lcReflected));
  return clamp(s.x * lcPlanckLookup(s.y), 0.0, 1.0);
}
