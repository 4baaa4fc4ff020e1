// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The step growth of Boost.Odeint's controlled steppers (default_step_adjuster::increase_step in
// boost/numeric/odeint/stepper/controlled_runge_kutta.hpp, without a maximal step), written once
// as a template over the scalar: odeint branches on the error (`if (error < 0.5)`), which an
// expression recorded on codegen::Expr cannot, so the branch is lc::ifPositive here and the GPU
// tracer's lcIncreaseStep is generated from this function (core/codegen/tracer_glsl). Tested
// against odeint's own increase_step at many errors (tests/core/test_step_control.cpp).
// The step decrease and the error norm have no branch on a value: the GPU's are recorded from
// odeint's own code directly.
#include "core/numerics/select.hpp"

#include <algorithm>
#include <cmath>

namespace lc {

// The step after an accepted step of error norm `error` (<= 1) by a stepper of order
// `stepperOrder`: grown by 0.9 error^(-1/order) where error < 0.5, the error bounded below by
// 5^-order (so by at most a factor 4.5); unchanged otherwise.
template <class S>
S increasedStep(const S& dt, const S& error, int stepperOrder) {
    using std::max;
    using std::pow;
    const S bounded = max(S(std::pow(5.0, -static_cast<double>(stepperOrder))), error);
    const S grown = dt * (S(9.0) / S(10.0) * pow(bounded, S(-1.0) / S(static_cast<double>(stepperOrder))));
    return ifPositive(S(0.5) - error, grown, dt);
}

}  // namespace lc
