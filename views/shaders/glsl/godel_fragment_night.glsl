// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::shadePixels' lit object colour with a night texture (core/render/shading.cpp), through
// lcDayNight; the coverage pass as in godel_fragment.
//VTK::TCoord::Impl
if (lcMode == 1)
  gl_FragData[0] = vec4(lcObjectId, 0.0, 0.0, 1.0);
else
  gl_FragData[0] = vec4(lcDayNight(texture(actortexture, tcoordVCVSOutput).rgb, texture(lcNight, tcoordVCVSOutput).rgb,
                                   lcLightVSOut), 1.0);
