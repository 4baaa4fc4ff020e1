// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::views::PlanckTexture::setUniforms (views/shaders/planck_texture.cpp): the uniforms of
// glsl/planck_lookup, declared by the mappers that set them on their program themselves.
uniform float lcTMin;
uniform float lcTMax;
uniform float lcSamples;
uniform float lcTexRow;
