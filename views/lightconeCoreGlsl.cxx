#include "lightconeCoreGlsl.h"

#include "lightcone_glsl_atan2_finite.h"

#include "core/codegen/function_glsl.hpp"
#include "core/colour/srgb.hpp"
#include "core/scene/sky.hpp"
#include "core/sr/doppler.hpp"

namespace lc::views {

using codegen::Expr;
using codegen::vectorSymbol;

std::string skyUvGlsl() {
    const Eigen::Matrix<Expr, 2, 1> uv = skyUv(vectorSymbol<3>("d"));
    return std::string(lightcone_glsl_atan2_finite) +
           codegen::functionGlsl("vec2 lcSkyUv(vec3 d)", {uv(0), uv(1)}, "lc::skyUv (core/scene/sky.hpp)");
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

}  // namespace lc::views
