// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Cases in formulas written once for every scalar: ifPositive(c, a, b) is c > 0 ? a : b. For
// double it is this function; for codegen::Expr (GLSL generation) the overload in
// core/codegen/expression.hpp, found by argument-dependent lookup.
namespace lc {

inline double ifPositive(double condition, double a, double b) { return condition > 0 ? a : b; }

}  // namespace lc
