#pragma once
// A GLSL function printed from expressions recorded on named arguments: a core formula written
// once as a template over the scalar (e.g. lc::skyUv<S>) is instantiated with codegen::Expr on
// vectorSymbol("d") and printed here, so the shader calls the formula the CPU runs.
#include "core/codegen/expression.hpp"

#include <string>
#include <vector>

namespace lc::codegen {

// Symbols name.x, name.y, ... for a GLSL vector argument of N components.
template <int N>
Eigen::Matrix<Expr, N, 1> vectorSymbol(const std::string& name) {
    static const char* const components[4] = {"x", "y", "z", "w"};
    Eigen::Matrix<Expr, N, 1> v;
    for (int i = 0; i < N; ++i) v(i) = Expr::symbol(name + "." + components[i]);
    return v;
}

// `signature` (e.g. "vec2 lcSkyUv(vec3 d)") with a body returning `result`: one value as a
// float, 2 to 4 as a vecN. `origin` names the C++ it was generated from, in the first line.
std::string functionGlsl(const std::string& signature, const std::vector<Expr>& result, const std::string& origin);

}  // namespace lc::codegen
