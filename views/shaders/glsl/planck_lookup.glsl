// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::colour::BlackbodyTable::lookup (core/colour/blackbody.cpp) on the table baked into
// the lcPlanck texture by lc::views::PlanckTexture: the sample index is the generated
// lcPlanckSampleIndex (lc::colour::blackbodySampleIndex); the rest is texel addressing (sample i
// has its texel centre at (i + 0.5) / n, so linear filtering interpolates as lookup does) and
// the row lcTexRow that picks the tone map.
uniform sampler2D lcPlanck;
vec3 lcPlanckLookup(float T)
{
  float s = lcPlanckSampleIndex(T, lcTMin, lcTMax, lcSamples);
  return texture(lcPlanck, vec2((s + 0.5) / lcSamples, lcTexRow)).rgb;
}
