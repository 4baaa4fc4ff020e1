// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A metric that exists only in the tests, to show that a metric written once as code is all it
// takes: its derivatives (tests/core/test_codegen.cpp) and its GPU code
// (tests/views/test_glsl_functions.cpp) follow with nothing else written. A plane-wave-like
// ripple travelling along z, with sin, cos, exp and tanh and an off-diagonal entry.
#include "core/spacetime/spacetime.hpp"

namespace lc::test {

class RippleMetric final : public CodedMetric<RippleMetric> {
public:
    std::string name() const override { return "test-ripple"; }
    std::map<std::string, double> parameters() const override { return {}; }
    std::array<std::string, 4> coordinateNames() const override { return {"t", "x", "y", "z"}; }
    template <class S>
    Eigen::Matrix<S, 4, 4> g(const Eigen::Matrix<S, 4, 1>& X) const {
        using std::cos;
        using std::exp;
        using std::sin;
        using std::tanh;
        const S h = S(0.2) * sin(X(0) - X(3)) * exp(-X(1) * X(1)) + S(0.05) * tanh(S(3.0) * X(2)) * cos(X(1));
        Eigen::Matrix<S, 4, 4> m = Eigen::Matrix<S, 4, 4>::Zero();
        m(0, 0) = S(1.0) + h;
        m(0, 1) = m(1, 0) = S(0.1) * h;
        m(1, 1) = -(S(1.0) - h);
        m(2, 2) = S(-1.0);
        m(3, 3) = -(S(1.0) + S(0.5) * h * h);
        return m;
    }
};

}  // namespace lc::test
