// SPDX-License-Identifier: BSD-3-Clause
#include "sr_glsl.hpp"

#include "core/codegen/function_glsl.hpp"
#include "core/sr/local_ray_tracing.hpp"
#include "core/sr/renderer.hpp"

namespace lc::views {

using codegen::Expr;
using codegen::vectorSymbol;

std::string srTriangleHitsGlsl() {
    const auto origin = vectorSymbol<3>("origin"), dir = vectorSymbol<3>("dir");
    const auto p0 = vectorSymbol<3>("p0"), p1 = vectorSymbol<3>("p1"), p2 = vectorSymbol<3>("p2");
    // Float tolerances: an edge tolerance of ~20 ulp so that shared edges overlap instead of
    // cracking (the depth test decides), and a parallel test above float's rounding of det.
    const Eigen::Matrix<Expr, 4, 1> rest = sr::triangleLineHit<Expr>(origin, dir, p0, p1, p2, Expr(2e-6), Expr(1e-10));
    const Eigen::Matrix<Expr, 4, 1> flat =
        sr::triangleLineHit<Expr>(origin, dir, p0, p1, p2, Expr(0.0), Expr(1e-10), /*rasterised=*/true);
    const char* origin_ = "lc::sr::triangleLineHit (core/sr/local_ray_tracing.hpp)";
    return codegen::functionGlsl("vec4 lcRestTriangleHit(vec3 origin, vec3 dir, vec3 p0, vec3 p1, vec3 p2)",
                                 {rest(0), rest(1), rest(2), rest(3)}, std::string(origin_) + ", GPU tolerances") +
           codegen::functionGlsl("vec4 lcFlatTriangleHit(vec3 origin, vec3 dir, vec3 p0, vec3 p1, vec3 p2)",
                                 {flat(0), flat(1), flat(2), flat(3)},
                                 std::string(origin_) + ", clamped onto the rasterised triangle");
}

std::string srShadingGlsl() {
    const auto sym = [](const char* name) { return Expr::symbol(name); };
    const Eigen::Matrix<Expr, 2, 1> shade = sr::srShading<Expr>(
        vectorSymbol<3>("d"), sym("depth"), sym("D"), sym("u"), sym("v"), vectorSymbol<3>("n0"), vectorSymbol<3>("n1"),
        vectorSymbol<3>("n2"), vectorSymbol<3>("beta"), sym("T"), vectorSymbol<4>("mat"), vectorSymbol<3>("lightRel"),
        sym("lightT"), sym("shading"), sym("doppler"), sym("reflected"));
    return codegen::functionGlsl(
        "vec2 lcSrShading(vec3 d, float depth, float D, float u, float v, vec3 n0, vec3 n1, "
        "vec3 n2, vec3 beta, float T, vec4 mat, vec3 lightRel, float lightT, float shading, "
        "float doppler, float reflected)",
        {shade(0), shade(1)}, "lc::sr::srShading (core/sr/renderer.hpp)");
}

}  // namespace lc::views
