// SPDX-License-Identifier: BSD-3-Clause
// Black-body light of temperature T and brightness b seen with frequency ratio g: Planck's colour
// of g T, brightness g^4 b; none for g <= 0 or no light. Mirrors lc::shadePixels' sky colour
// (core/render/shading.cpp, shiftedBlackbodyLight) for a black-body or star sky, in the tracer's
// and the post-renderer's pixel. Calls the generated lcShiftedTemperature, lcShiftedBrightness
// (core/render/post_render.hpp), lcSrgbDecode and the Planck lookup.
vec3 lcShiftedBlackbodyLight(float g, float T, float b)
{
  return g > 0.0 && b > 0.0 ? lcSrgbDecode(lcPlanckLookup(lcShiftedTemperature(g, T))) * lcShiftedBrightness(g, b)
                            : vec3(0.0);
}
