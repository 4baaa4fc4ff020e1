// SPDX-License-Identifier: BSD-3-Clause
#include "core_formula_glsl.hpp"

#include "lightcone_glsl_atan2_finite.h"
#include "lightcone_glsl_planck_lookup.h"

#include "core/accretion/thin_disk.hpp"
#include "core/codegen/function_glsl.hpp"
#include "core/numerics/bessel.hpp"
#include "core/colour/blackbody.hpp"
#include "core/colour/srgb.hpp"
#include "core/render/post_render.hpp"
#include "core/scene/camera.hpp"
#include "core/spacetime/frame.hpp"
#include "core/spacetime/spacetime.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/sky.hpp"
#include "core/scene/texture.hpp"
#include "core/sr/doppler.hpp"

namespace lc::views {

using codegen::Expr;
using codegen::vectorSymbol;

std::string skyUvGlsl() {
    const Eigen::Matrix<Expr, 2, 1> uv = skyUv(vectorSymbol<3>("d"));
    return std::string(lightcone_glsl_atan2_finite) +
           codegen::functionGlsl("vec2 lcSkyUv(vec3 d)", {uv(0), uv(1)}, "lc::skyUv (core/scene/sky.hpp)");
}

std::string otherEndDirectionGlsl() {
    const Eigen::Matrix<Expr, 3, 1> d = inversionReflected(vectorSymbol<3>("x"), vectorSymbol<3>("k"));
    return codegen::functionGlsl("vec3 lcOtherEndDirection(vec3 x, vec3 k)", {d(0), d(1), d(2)},
                                 "lc::inversionReflected (core/spacetime/spacetime.hpp)");
}

std::string besselGlsl() {
    const Expr x = Expr::symbol("x");
    return codegen::functionGlsl("float lcBesselJ0(float x)", {besselJ0Approximation(x)},
                                 "lc::besselJ0Approximation (core/numerics/bessel.hpp)") +
           codegen::functionGlsl("float lcBesselJ1(float x)", {besselJ1Approximation(x)},
                                 "lc::besselJ1Approximation (core/numerics/bessel.hpp)");
}

std::string srgbDecodeGlsl() {
    const Eigen::Matrix<Expr, 3, 1> e = vectorSymbol<3>("e");
    return codegen::functionGlsl("vec3 lcSrgbDecode(vec3 e)",
                                 {colour::srgbToLinear(e(0)), colour::srgbToLinear(e(1)), colour::srgbToLinear(e(2))},
                                 "lc::colour::srgbToLinear (core/colour/srgb.hpp), per channel");
}

std::string aberrationGlsl() {
    const Eigen::Matrix<Expr, 3, 1> k = sr::boostDirection<Expr>(-vectorSymbol<3>("beta"), vectorSymbol<3>("k"));
    return codegen::functionGlsl("vec3 lcAberrateToRest(vec3 beta, vec3 k)", {k(0), k(1), k(2)},
                                 "lc::sr::boostDirection(-beta, k) (core/sr/doppler.hpp)");
}

std::string restRayGlsl() {
    const auto u = vectorSymbol<3>("u"), k = vectorSymbol<3>("k");
    const Eigen::Matrix<Expr, 3, 1> dir = sr::boostDirection(u, k);
    return codegen::functionGlsl("vec3 lcBoostDirection(vec3 u, vec3 k)", {dir(0), dir(1), dir(2)},
                                 "lc::sr::boostDirection (core/sr/doppler.hpp)") +
           codegen::functionGlsl("float lcRestRayDoppler(vec3 beta, vec3 d)",
                                 {sr::restRayDoppler(vectorSymbol<3>("beta"), vectorSymbol<3>("d"))},
                                 "lc::sr::restRayDoppler (core/sr/doppler.hpp)");
}

std::string dayNightGlsl() {
    const Eigen::Matrix<Expr, 3, 1> c =
        dayNightLit(vectorSymbol<3>("day"), vectorSymbol<3>("night"), vectorSymbol<3>("lit"));
    return codegen::functionGlsl("vec3 lcDayNight(vec3 day, vec3 night, vec3 lit)", {c(0), c(1), c(2)},
                                 "lc::dayNightLit (core/scene/scene.hpp)");
}

std::string cameraDirectionsGlsl() {
    const auto f = vectorSymbol<3>("f"), r = vectorSymbol<3>("r"), u = vectorSymbol<3>("u");
    const Expr sx = Expr::symbol("sx"), sy = Expr::symbol("sy");
    const Eigen::Matrix<Expr, 2, 1> screen =
        screenCoordinates(Expr::symbol("x"), Expr::symbol("yDown"), Expr::symbol("width"), Expr::symbol("height"));
    const Eigen::Matrix<Expr, 3, 1> pinhole =
        pinholeScreenDirection(sx, sy, Expr::symbol("tx"), Expr::symbol("ty"), f, r, u);
    const Eigen::Matrix<Expr, 3, 1> panorama =
        panoramaScreenDirection(sx, sy, Expr::symbol("hx"), Expr::symbol("hy"), f, r, u);
    return codegen::functionGlsl("vec2 lcScreenCoordinates(float x, float yDown, float width, float height)",
                                 {screen(0), screen(1)}, "lc::screenCoordinates (core/scene/camera.hpp)") +
           codegen::functionGlsl(
               "vec3 lcPinholeScreenDirection(float sx, float sy, float tx, float ty, vec3 f, vec3 r, vec3 u)",
               {pinhole(0), pinhole(1), pinhole(2)}, "lc::pinholeScreenDirection (core/scene/camera.hpp)") +
           codegen::functionGlsl(
               "vec3 lcPanoramaScreenDirection(float sx, float sy, float hx, float hy, vec3 f, vec3 r, vec3 u)",
               {panorama(0), panorama(1), panorama(2)}, "lc::panoramaScreenDirection (core/scene/camera.hpp)");
}

std::string pastNullMomentumGlsl() {
    const std::array<Eigen::Matrix<Expr, 4, 1>, 4> e{vectorSymbol<4>("e0"), vectorSymbol<4>("e1"),
                                                     vectorSymbol<4>("e2"), vectorSymbol<4>("e3")};
    Eigen::Matrix<Expr, 4, 4> g;
    for (int row = 0; row < 4; ++row) g.row(row) = vectorSymbol<4>("g" + std::to_string(row)).transpose();
    const Eigen::Matrix<Expr, 4, 1> p = pastNullMomentumAlong(vectorSymbol<3>("n"), e, g);
    return codegen::functionGlsl(
        "vec4 lcPastNullMomentum(vec3 n, vec4 e0, vec4 e1, vec4 e2, vec4 e3, vec4 g0, vec4 g1, vec4 g2, vec4 g3)",
        {p(0), p(1), p(2), p(3)}, "lc::pastNullMomentumAlong (core/spacetime/frame.hpp); g0..g3 are the rows of g");
}

std::string planckLookupGlsl() {
    const Expr index = colour::blackbodySampleIndex(Expr::symbol("T"), Expr::symbol("tMin"), Expr::symbol("tMax"),
                                                    Expr::symbol("samples"));
    return codegen::functionGlsl("float lcPlanckSampleIndex(float T, float tMin, float tMax, float samples)", {index},
                                 "lc::colour::blackbodySampleIndex (core/colour/blackbody.hpp)") +
           lightcone_glsl_planck_lookup;
}

std::string textureSampleGlsl() {
    const auto uv = vectorSymbol<2>("uv"), size = vectorSymbol<2>("size"), f = vectorSymbol<2>("f");
    const Eigen::Matrix<Expr, 2, 1> position = texelPosition(uv(0), uv(1), size(0), size(1));
    const Eigen::Matrix<Expr, 3, 1> c = bilinear<Expr>(vectorSymbol<3>("c00"), vectorSymbol<3>("c10"),
                                                       vectorSymbol<3>("c01"), vectorSymbol<3>("c11"), f(0), f(1));
    const auto xy = vectorSymbol<2>("xy");
    const Eigen::Matrix<Expr, 2, 1> index = texelIndex(xy(0), xy(1), size(0), size(1));
    return codegen::functionGlsl("vec2 lcTexelPosition(vec2 uv, vec2 size)", {position(0), position(1)},
                                 "lc::texelPosition (core/scene/texture.hpp)") +
           codegen::functionGlsl("vec2 lcTexelIndex(vec2 xy, vec2 size)", {index(0), index(1)},
                                 "lc::texelIndex (core/scene/texture.hpp)") +
           codegen::functionGlsl("vec3 lcBilinear(vec3 c00, vec3 c10, vec3 c01, vec3 c11, vec2 f)", {c(0), c(1), c(2)},
                                 "lc::bilinear (core/scene/texture.hpp)");
}

std::string cameraProjectionGlsl() {
    const auto d = vectorSymbol<3>("d"), f = vectorSymbol<3>("f"), r = vectorSymbol<3>("r"), u = vectorSymbol<3>("u");
    const Eigen::Matrix<Expr, 3, 1> h =
        pinholeHomogeneous(d, f, r, u, Expr::symbol("tanHalfX"), Expr::symbol("tanHalfY"));
    const Eigen::Matrix<Expr, 2, 1> s = panoramaScreen(d, f, r, u, Expr::symbol("halfX"), Expr::symbol("halfY"));
    return std::string(lightcone_glsl_atan2_finite) +
           codegen::functionGlsl(
               "vec3 lcPinholeHomogeneous(vec3 d, vec3 f, vec3 r, vec3 u, float tanHalfX, float tanHalfY)",
               {h(0), h(1), h(2)}, "lc::pinholeHomogeneous (core/scene/camera.hpp)") +
           codegen::functionGlsl("vec2 lcPanoramaScreen(vec3 d, vec3 f, vec3 r, vec3 u, float halfX, float halfY)",
                                 {s(0), s(1)}, "lc::panoramaScreen (core/scene/camera.hpp)");
}

std::string postRenderGlsl() {
    const auto uv = vectorSymbol<2>("uv"), offset = vectorSymbol<2>("offset"), scale = vectorSymbol<2>("scale");
    const Eigen::Matrix<Expr, 2, 1> moved = retexturedUv(uv(0), uv(1), offset(0), offset(1), scale(0), scale(1));
    const auto w = vectorSymbol<2>("w");
    const auto blink = vectorSymbol<4>("blink");
    const Expr t = Expr::symbol("t");
    const Eigen::Matrix<Expr, 3, 1> c = vectorSymbol<3>("c");
    const char* origin = "core/render/post_render.hpp";
    return codegen::functionGlsl("vec2 lcRetexturedUv(vec2 uv, vec2 offset, vec2 scale)", {moved(0), moved(1)},
                                 std::string("lc::retexturedUv (") + origin + ")") +
           codegen::functionGlsl("float lcInsideTimeWindow(float t, vec2 w)", {insideTimeWindow(t, w(0), w(1))},
                                 std::string("lc::insideTimeWindow (") + origin + ")") +
           codegen::functionGlsl("float lcBlinkLevel(float t, vec4 blink)",
                                 {blinkLevel(t, blink(0), blink(1), blink(2), blink(3))},
                                 std::string("lc::blinkLevel (") + origin + ")") +
           codegen::functionGlsl("float lcShiftedTemperature(float d, float T)",
                                 {shiftedTemperature(Expr::symbol("d"), Expr::symbol("T"))},
                                 std::string("lc::shiftedTemperature (") + origin + ")") +
           codegen::functionGlsl("float lcShiftedBrightness(float g, float b)",
                                 {shiftedBrightness(Expr::symbol("g"), Expr::symbol("b"))},
                                 std::string("lc::shiftedBrightness (") + origin + ")") +
           codegen::functionGlsl(
               "vec3 lcSrgbEncodeDisplay(vec3 c)",
               {colour::srgbEncodeDisplay(c(0)), colour::srgbEncodeDisplay(c(1)), colour::srgbEncodeDisplay(c(2))},
               "lc::colour::srgbEncodeDisplay (core/colour/srgb.hpp), per channel");
}

std::string diskRadiusGlsl(const Expr& radius) {
    return codegen::functionGlsl("float lcDiskRadius(vec4 X)", {radius},
                                 "the metric's equatorial radius (lc::Spacetime::equatorialRadius)");
}

std::string diskGlsl() {
    const auto X = vectorSymbol<4>("x"), p = vectorSymbol<4>("p");
    return codegen::functionGlsl(
               "float lcKeplerianRedshift(vec4 x, vec4 p, float omega, float ut, float e)",
               {keplerianRedshift(X, p, Expr::symbol("omega"), Expr::symbol("ut"), Expr::symbol("e"))},
               "lc::keplerianRedshift (core/accretion/thin_disk.hpp)") +
           codegen::functionGlsl(
               "float lcDiskLocalTemperature(float peak, float intensity, float g)",
               {diskLocalTemperature(Expr::symbol("peak"), Expr::symbol("intensity"), Expr::symbol("g"))},
               "lc::diskLocalTemperature (core/render/post_render.hpp)");
}

}  // namespace lc::views
