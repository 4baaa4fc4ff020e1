// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A set of codegen::Expr graphs flattened into one instruction list for fast evaluation in
// double: each distinct subexpression (merged by structure, as the GLSL emitter merges them)
// is computed once, in an order where operands come first, into a register of its own. The
// interpreter's cost is a switch per instruction, with no allocation and no recursion, so a
// metric typed as text runs close to one compiled from C++.
#include "core/codegen/expression.hpp"

#include <cstdint>
#include <vector>

namespace lc::formula {

class ExpressionTape {
public:
    explicit ExpressionTape(const std::vector<codegen::Expr>& outputs);

    // out[i] = outputs[i] at the chart point x (4 coordinates). Thread-safe.
    void evaluate(const double* x, double* out) const;
    // The same with the exact gradient by forward-mode differentiation along the tape:
    // out[5 i] = outputs[i], out[5 i + 1 + k] = d outputs[i] / d x^k. One pass over the
    // instructions computes the value and its four derivatives together, so the interpreter's
    // dispatch is paid once for five numbers.
    void evaluateWithGradient(const double* x, double* out) const;

    std::size_t instructions() const { return code_.size(); }
    std::size_t registers() const { return initial_.size() + code_.size(); }

private:
    struct Instruction {
        codegen::Op op;
        std::int32_t a, b, c;
    };
    std::vector<double> initial_;  // the coordinates' slots (0..3), then every constant
    std::vector<Instruction> code_;
    std::vector<std::int32_t> outputs_;
};

}  // namespace lc::formula
