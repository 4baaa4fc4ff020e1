// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A GLSL function printed from expressions recorded on named arguments: a core formula written
// once as a template over the scalar (e.g. lc::skyUv<S>) is instantiated with codegen::Expr on
// vectorSymbol("d") and printed here, so the shader calls the formula the CPU runs.
#include "core/codegen/glsl_emitter.hpp"  // vectorSymbol

#include <string>
#include <vector>

namespace lc::codegen {

// `signature` (e.g. "vec2 lcSkyUv(vec3 d)") with a body returning `result`: one value as a
// float, 2 to 4 as a vecN. `origin` names the C++ it was generated from, in the first line.
std::string functionGlsl(const std::string& signature, const std::vector<Expr>& result, const std::string& origin);

}  // namespace lc::codegen
