// mirrors lc::colour::BlackbodyTable::lookup (core/colour/blackbody.cpp), the table baked into
// the lcPlanck texture by lc::views::PlanckTexture: sample index s in [0, n - 1]; texel i has
// its centre at (i + 0.5) / n; row lcTexRow picks the tone map.
uniform sampler2D lcPlanck;
vec3 lcPlanckLookup(float T)
{
  float s = clamp((T - lcTMin) / (lcTMax - lcTMin), 0.0, 1.0) * (lcSamples - 1.0);
  return texture(lcPlanck, vec2((s + 0.5) / lcSamples, lcTexRow)).rgb;
}
