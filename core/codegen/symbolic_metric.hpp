// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A metric as recorded expressions in the coordinates x^0..x^3, and the GLSL generated from it.
// CodedMetric::symbolic() records g<Expr>(x) from the metric's one C++ definition; the GPU
// tracer compiles metricGlsl() of it, so no metric formula is typed twice.
#include "core/codegen/expression.hpp"

#include <optional>
#include <string>

namespace lc::codegen {

struct SymbolicMetric {
    ExprMatrix4 g;                 // g_{mu nu}(x), symmetric
    std::optional<Expr> boundary;  // rays stop where it is <= the stop margin (Kerr: r / r_+ - 1)
    std::optional<Expr> otherEnd;  // two-ended metrics: rays have reached the far end where it is <= the margin
    std::string origin;            // the class and parameters it was generated from
};

struct GeneratedGlsl {
    std::string source;
    int temporaries = 0;  // distinct subexpressions after elimination of common ones
};

// GLSL (#version 150 and later) defining
//   void lcMetric(vec4 X, out mat4 g, out mat4 dg0, out mat4 dg1, out mat4 dg2, out mat4 dg3)
//     g_{mu nu} and its exact derivatives dgk = d g / d x^k (symbolic chain rule on the
//     recorded graph, the same derivatives Eigen's AutoDiffScalar gives the CPU), and
//   float lcBoundary(vec4 X)   (1.0 where the metric has no boundary), and
//   float lcOtherEnd(vec4 X)   (1.0 where the metric has one end).
// tanh is printed as lcTanh, which the GLSL that includes this code defines (views/shaders/glsl).
// Subexpressions that occur more than once, also across entries and derivatives, are
// computed once. Constants are folded in double and rounded once to float; a constant outside
// float's range throws std::invalid_argument naming it.
GeneratedGlsl metricGlsl(const SymbolicMetric& metric);

}  // namespace lc::codegen
