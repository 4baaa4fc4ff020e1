// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::shadePixels' disk colour (core/render/shading.cpp, diskColour) for a black body
// (emission 0) or the bolometric intensity alone (1), from a pixel's g and observed intensity
// g^4 F / F_max; shared by the tracer's and the post-renderer's pixel (geodesic_pixel,
// post_render_pixel). Calls the generated lcDiskLocalTemperature, lcShiftedTemperature,
// lcSrgbDecode and the Planck lookup.
vec3 lcDiskColour(int emission, float g, float intensity, float peakTemperature)
{
  if (emission == 1)
    return vec3(intensity);
  float local = lcDiskLocalTemperature(peakTemperature, intensity, g);
  return lcSrgbDecode(lcPlanckLookup(lcShiftedTemperature(g, local))) * intensity;
}
