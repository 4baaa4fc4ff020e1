// SPDX-License-Identifier: BSD-3-Clause
// The step growth written once over the scalar (lc::increasedStep, the source of the GPU
// tracer's lcIncreaseStep) against Boost.Odeint's own default_step_adjuster::increase_step, the
// independent oracle, at errors across [0, 1] (both sides of odeint's 0.5 branch and of its
// 5^-order bound) and at non-finite ones: bit for bit in double, and recorded on codegen::Expr
// then evaluated, as the shader generator records it.
#include "core/codegen/expression.hpp"
#include "core/numerics/step_control.hpp"

#include <gtest/gtest.h>

#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <limits>
#include <vector>

namespace {

std::vector<double> errors() {
    std::vector<double> e{
        0.0, 1e-12, std::pow(5.0, -5.0), 0.4999999, 0.5, 0.5000001, 1.0, std::numeric_limits<double>::quiet_NaN()};
    for (int k = 0; k <= 400; ++k) e.push_back(std::pow(10.0, -6.0 + 6.0 * k / 400));  // 1e-6 .. 1
    return e;
}

const boost::numeric::odeint::default_step_adjuster<double, double> odeintAdjuster;

TEST(StepControl, IncreasedStepEqualsOdeintsIncreaseStep) {
    for (int order : {4, 5, 8})
        for (double dt : {0.01, 1.0, 37.5})
            for (double e : errors()) {
                const double odeint = odeintAdjuster.increase_step(dt, e, order);
                const double ours = lc::increasedStep(dt, e, order);
                if (std::isnan(odeint)) {
                    EXPECT_TRUE(std::isnan(ours));
                    continue;
                }
                EXPECT_EQ(ours, odeint) << "order " << order << ", dt " << dt << ", error " << e;
            }
    // The branch and the bound are where odeint puts them: unchanged from 0.5, at most 4.5 x.
    EXPECT_EQ(lc::increasedStep(2.0, 0.5, 5), 2.0);
    EXPECT_DOUBLE_EQ(lc::increasedStep(2.0, 0.0, 5), 2.0 * 4.5);
}

TEST(StepControl, IncreasedStepRecordedOnExprEvaluatesLikeOdeint) {
    using lc::codegen::Expr;
    const Expr recorded = lc::increasedStep(Expr::symbol("h"), Expr::symbol("err"), 5);
    for (double e : errors()) {
        if (std::isnan(e)) continue;
        const double value = lc::codegen::evaluate(recorded, {0, 0, 0, 0}, {{"h", 0.25}, {"err", e}});
        EXPECT_DOUBLE_EQ(value, odeintAdjuster.increase_step(0.25, e, 5)) << "error " << e;
    }
}

}  // namespace
