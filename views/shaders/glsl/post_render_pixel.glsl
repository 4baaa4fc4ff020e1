// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::shadePixels (core/render/shading.cpp) with an lc::PostRender: the pixel's colour from its stored data, written sRGB-encoded as the image writer encodes (lcSrgbEncodeDisplay).
//VTK::TCoord::Impl
{
  ivec2 lcPx = ivec2(int(gl_FragCoord.x), lcHeight - 1 - int(gl_FragCoord.y));
  vec4 lcA = texelFetch(lcPixelA, lcPx, 0);
  vec4 lcB = texelFetch(lcPixelB, lcPx, 0);
  int lcKind = int(lcA.x + 0.5);
  vec3 lcC = lcBackground;
  if (lcKind == 1)
  {
    vec4 lcObj = texelFetch(lcObjects, ivec2(int(lcA.y + 0.5), 0), 0);
    vec2 lcUv = lcRetexturedUv(lcA.zw, lcUvOffset, lcUvScale);
    bool lcInside = lcWindowOn == 0 || lcInsideTimeWindow(lcB.y, lcWindow) > 0.5;
    bool lcHidden = !lcInside && lcOutsideEntry < 0;
    if (!lcInside)
      lcC = lcOutsideEntry >= 0 ? lcAtlasSample(lcOutsideEntry, lcUv) : lcBackground;
    else if ((lcTemperature > 0.0 ? lcTemperature : lcObj.z) > 0.0)
      lcC = lcSrgbDecode(lcPlanckLookup(lcShiftedTemperature(lcB.x, lcTemperature > 0.0 ? lcTemperature : lcObj.z)));
    else
      lcC = lcObj.x >= 0.0 ? lcAtlasSample(int(lcObj.x + 0.5), lcUv) : vec3(0.8);
    if (lcBlink.x > 0.0) lcC *= lcBlinkLevel(lcB.y, lcBlink);
    if (lcLit == 1 && !lcHidden)
    {
      vec3 lcNight = lcObj.y >= 0.0 ? lcAtlasSample(int(lcObj.y + 0.5), lcUv) : vec3(0.0);
      lcC = lcDayNight(lcC, lcNight, vec3(lcAmbient) + texelFetch(lcPixelC, lcPx, 0).rgb);
    }
  }
  else if (lcKind == 2)
  {
    lcC = lcSkyEntry >= 0 ? lcAtlasSample(lcSkyEntry, lcA.zw) : lcBackground;
    if (lcSkyStars == 1)  // lc::shadePixels' skyColour for a star sky: each star at g T, g^4 b
      lcC = lcShiftedBlackbodyLight(lcB.x, lcC.x > 0.0 ? lcC.y / lcC.x : 0.0, lcC.x);
    else if (lcSkyTemperature > 0.0)  // lc::shadePixels' skyColour: at g T, brightness g^4 x luminance
      lcC = lcShiftedBlackbodyLight(lcB.x, lcSkyTemperature, dot(lcC, vec3(0.2126, 0.7152, 0.0722)));
  }
  else if (lcKind == 6)  // the far side's sky: lc::shadePixels' skyColour with Scene::otherSky, no temperature
    lcC = lcOtherSkyEntry >= 0 ? lcAtlasSample(lcOtherSkyEntry, lcA.zw) : lcBackground;
  else if (lcKind == 3)
    lcC = vec3(0.0);
  else if (lcKind == 4)
    lcC = vec3(1.0, 0.0, 1.0);
  else if (lcKind == 5)  // an accretion disk: lc::shadePixels' diskColour
  {
    float lcI = texelFetch(lcPixelC, lcPx, 0).r;
    if (lcWindowOn != 0 && lcInsideTimeWindow(lcB.y, lcWindow) < 0.5)
      lcC = lcOutsideEntry >= 0 ? lcAtlasSample(lcOutsideEntry, lcA.zw) : lcBackground;
    else
    {
      if (lcDiskEmission == 2)
        lcC = lcDiskEntry >= 0 ? lcAtlasSample(lcDiskEntry, lcA.zw) : vec3(0.8);
      else
        lcC = lcDiskColour(lcDiskEmission, lcB.x, lcI, lcTemperature > 0.0 ? lcTemperature : lcDiskTemperature);
      if (lcBlink.x > 0.0) lcC *= lcBlinkLevel(lcB.y, lcBlink);
    }
  }
  gl_FragData[0] = vec4(lcSrgbEncodeDisplay(lcC), 1.0);
}
