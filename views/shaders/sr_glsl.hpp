// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The special-relativity formulas the SR shaders call, generated from their C++ templates
// (core/codegen's functionGlsl on codegen::Expr), so that the GPU runs the formula the CPU runs.
#include <string>

namespace lc::views {

// vec4 lcRestTriangleHit(vec3 origin, vec3 dir, vec3 p0, vec3 p1, vec3 p2) and
// vec4 lcFlatTriangleHit(vec3 origin, vec3 dir, vec3 p0, vec3 p1, vec3 p2), (s, u, v, hit):
// lc::sr::triangleLineHit (core/sr/local_ray_tracing.hpp, intersectRest / intersectFlat) with the
// GPU's float tolerances, the second clamped (the rasteriser decides coverage);
// glsl/sr_rest_ray_hit and glsl/sr_flat_hit call them.
std::string srTriangleHitsGlsl();
// vec2 lcSrShading(vec3 d, float depth, float D, float u, float v, vec3 n0, vec3 n1, vec3 n2, vec3 beta,
// float T, vec4 mat, vec3 lightRel, float lightT, float shading, float doppler, float reflected),
// (Phong factor, observed temperature): lc::sr::srShading (core/sr/renderer.hpp, SrRenderer's
// shading), which glsl/sr_shade calls.
std::string srShadingGlsl();

}  // namespace lc::views
