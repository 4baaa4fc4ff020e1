// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::shadePixels' object colour (core/render/shading.cpp): the texture or, for a black-body
// emitter, the linear Planck colour of the interpolated D T, lit as lc::dayNightLit (generated
// lcDayNight) without a night texture; or the flat object id (object index + 1 in red, exact in an
// 8-bit buffer) for the coverage pass (lcMode 1).
//VTK::TCoord::Impl
if (lcMode == 1)
  gl_FragData[0] = vec4(lcObjectId, 0.0, 0.0, 1.0);
else {
  vec3 lcBase = texture(actortexture, tcoordVCVSOutput).rgb;
  if (lcTemperatureVSOut > 0.0) lcBase = lcSrgbDecode(lcPlanckLookup(lcTemperatureVSOut));
  gl_FragData[0] = vec4(lcDayNight(lcBase, vec3(0.0), lcLightVSOut), 1.0);
}
