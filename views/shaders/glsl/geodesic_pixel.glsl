// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::renderNumeric's pixel loop (core/render/numeric.cpp) for sky (either end), boundary, background and disk;
// lcMode 1 writes (class, steps / 8) for the id pass, 2 the escape direction.
//VTK::TCoord::Impl
{
  vec3 lcDir;
  int lcSteps;
  float lcLaunchPt;
  int lcClass = lcTrace(lcCameraDirection(gl_FragCoord.xy), lcDir, lcSteps, lcLaunchPt);
  if (lcMode == 1)
    gl_FragData[0] = vec4(float(lcClass) / 255.0, float(min(lcSteps / 8, 255)) / 255.0, 0.0, 1.0);
  else if (lcMode == 2)
    gl_FragData[0] = vec4(lcClass == 0 ? 0.5 * lcDir + vec3(0.5) : vec3(0.0), 1.0);
  else
  {
    vec3 lcC = vec3(1.0, 0.0, 1.0);  // failed rays: magenta, as the CPU
    if (lcClass == 1) lcC = vec3(0.0);
    else if (lcClass == 3) lcC = lcBackground;
    else if (lcClass == 0 || lcClass == 5)
    {
      vec2 lcUv = lcSkyUv(lcDir);
#ifdef LC_SKY_STARS
      vec2 lcStarUv = lcUv;  // this side's sky, before the far side's is put beside it
#endif
#ifdef LC_OTHER_END
      lcUv.x = 0.5 * fract(lcUv.x) + (lcClass == 5 ? 0.5 : 0.0);  // both skies side by side (bakeSkies)
#endif
      lcC = textureLod(actortexture, lcUv, 0.0).rgb;
#ifdef LC_SKY_BLACKBODY
      if (lcClass == 0)  // this side only, as lc::shadePixels' skyColour
      {
        // light at g T, brightness g^4 times the texture's luminance, g = 1 / |p_t| of the
        // camera ray (unit observed frequency; p_t conserved)
        float lcLuminance = dot(lcC, vec3(0.2126, 0.7152, 0.0722));
        lcC = lcShiftedBlackbodyLight(1.0 / abs(lcLaunchPt), lcSkyTemperature, lcLuminance);
      }
#endif
#ifdef LC_SKY_STARS
      if (lcClass == 0)  // as lc::shadePixels' skyColour for a star sky: each star at g T, g^4 b
      {
        vec2 lcLight = lcStarLightAt(lcStarUv);
        lcC = lcShiftedBlackbodyLight(1.0 / abs(lcLaunchPt), lcLight.y, lcLight.x);
      }
#endif
    }
#ifdef LC_DISK
    else if (lcClass == 4)  // as lc::shadePixels' disk colour (core/render/shading.cpp)
    {
      float lcG = lcDir.x;
      lcC = lcDiskColour(lcDiskEmission, lcG, lcG * lcG * lcG * lcG * lcDir.z, lcDiskTemperature);
    }
#endif
    gl_FragData[0] = vec4(lcC, 1.0);
  }
}
