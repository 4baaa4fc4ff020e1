// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: the post-renderer's inputs, per pixel the data of lc::PixelRecord as float textures (lcPixelA: kind, object, u, v; lcPixelB: frequency ratio, emission time, affine; lcPixelC: the light, or a disk pixel's observed intensity), per object lcObjects (day entry, night entry or -1, temperature or 0), and the settings of lc::PostRender.
//VTK::ValuePass::Dec
uniform sampler2D lcPixelA;
uniform sampler2D lcPixelB;
uniform sampler2D lcPixelC;
uniform sampler2D lcObjects;
uniform int lcHeight;
uniform vec3 lcBackground;
uniform int lcSkyEntry;
uniform int lcOtherSkyEntry;  // a two-ended metric's far side (kind 6), -1 when none
uniform float lcSkyTemperature;  // > 0: a black-body sky (lc::Scene::skyTemperature)
uniform int lcSkyStars;  // 1: a star sky, whose atlas entry holds (b, b T, 0) (lc::LightMap)
uniform int lcOutsideEntry;
uniform int lcWindowOn;
uniform vec2 lcWindow;
uniform vec4 lcBlink;
uniform vec2 lcUvOffset;
uniform vec2 lcUvScale;
uniform float lcTemperature;
uniform int lcLit;
uniform int lcDiskEmission;  // the scene's disk: 0 black body, 1 bolometric intensity, 2 texture
uniform float lcDiskTemperature;
uniform int lcDiskEntry;
uniform float lcAmbient;
