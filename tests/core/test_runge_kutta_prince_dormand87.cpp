// SPDX-License-Identifier: BSD-3-Clause
// core/spacetime/runge_kutta_prince_dormand87.hpp: the tableau typed in from Prince and Dormand
// (1981) checked by what it must do, not by its numbers: on Kepler's problem (exact through
// Kepler's equation) the global error falls as h^8 and the embedded solution's as h^7; its error
// estimate does not vanish on a quadrature (y' = f(t)), where Fehlberg's 7(8) estimate, the
// stepper it replaces, is zero; under step control the error follows the tolerance there.
#include "core/spacetime/runge_kutta_prince_dormand87.hpp"

#include <gtest/gtest.h>

#include <boost/numeric/odeint.hpp>

#include <array>
#include <vector>
#include <cmath>

namespace {

namespace odeint = boost::numeric::odeint;
using KeplerState = std::array<double, 4>;  // q_x, q_y, p_x, p_y
using Scalar = std::vector<double>;

constexpr double kEccentricity = 0.5;

void kepler(const KeplerState& s, KeplerState& ds, double /*t*/) {
    const double r3 = std::pow(s[0] * s[0] + s[1] * s[1], 1.5);
    ds = {s[2], s[3], -s[0] / r3, -s[1] / r3};
}

// The orbit of semi-major axis 1 from pericentre at t = 0: x = cos E - e, y = sqrt(1 - e^2) sin E
// with E - e sin E = t.
std::array<double, 2> keplerExact(double t) {
    double E = t;
    for (int i = 0; i < 50; ++i) E -= (E - kEccentricity * std::sin(E) - t) / (1 - kEccentricity * std::cos(E));
    return {std::cos(E) - kEccentricity, std::sqrt(1 - kEccentricity * kEccentricity) * std::sin(E)};
}

KeplerState keplerStart() {
    const double e = kEccentricity;
    return {1 - e, 0, 0, std::sqrt((1 + e) / (1 - e))};
}

// Position error after `steps` fixed steps over t in [0, 2]; with `embedded`, of the 7th-order
// solution (the 8th-order one minus the stepper's error estimate, step by step).
double keplerError(int steps, bool embedded) {
    lc::RungeKuttaPrinceDormand87<KeplerState> stepper;
    KeplerState s = keplerStart(), err;
    const double T = 2, h = T / steps;
    for (int i = 0; i < steps; ++i) {
        stepper.do_step(kepler, s, i * h, h, err);
        if (embedded)
            for (int k = 0; k < 4; ++k) s[k] -= err[k];
    }
    const auto x = keplerExact(T);
    return std::hypot(s[0] - x[0], s[1] - x[1]);
}

// A sharp step, like a ray crossing a warp drive's wall: y' = tanh'(sigma (t - 1/2)).
constexpr double kSigma = 60;
void wall(const Scalar& /*y*/, Scalar& dy, double t) {
    const double c = std::cosh(kSigma * (t - 0.5));
    dy[0] = kSigma / (c * c);
}
double wallExact(double t) { return std::tanh(kSigma * (t - 0.5)) - std::tanh(-kSigma * 0.5); }

TEST(RungeKuttaPrinceDormand87, GlobalErrorFallsAsTheEighthPower) {
    for (int n : {16, 32}) {
        const double order = std::log2(keplerError(n, false) / keplerError(2 * n, false));
        EXPECT_GT(order, 7.5) << n << " steps";
        EXPECT_LT(order, 9.5) << n << " steps";
    }
    EXPECT_LT(keplerError(64, false), 1e-12);
}

TEST(RungeKuttaPrinceDormand87, EmbeddedSolutionIsOfSeventhOrder) {
    for (int n : {16, 32}) {
        const double order = std::log2(keplerError(n, true) / keplerError(2 * n, true));
        EXPECT_GT(order, 6.5) << n << " steps";
        EXPECT_LT(order, 8.5) << n << " steps";
    }
}

TEST(RungeKuttaPrinceDormand87, ErrorEstimateSeesAQuadratureWhereFehlbergsIsZero) {
    // One step across the wall: the true error of the step is large; Fehlberg's estimate,
    // 41/840 h (k1 + k11 - k12 - k13), is exactly zero for any y' = f(t).
    const double h = 1.0;
    Scalar yPd{0}, errPd{0}, yRkf{0}, errRkf{0};
    lc::RungeKuttaPrinceDormand87<Scalar>().do_step(wall, yPd, 0.0, h, errPd);
    odeint::runge_kutta_fehlberg78<Scalar>().do_step(wall, yRkf, 0.0, h, errRkf);
    const double truePd = std::abs(yPd[0] - wallExact(h)), trueRkf = std::abs(yRkf[0] - wallExact(h));
    EXPECT_GT(trueRkf, 1e-3);
    EXPECT_EQ(errRkf[0], 0.0);  // why Fehlberg's pair was replaced
    EXPECT_GT(truePd, 1e-3);
    EXPECT_GT(std::abs(errPd[0]), 0.1 * truePd);
}

TEST(RungeKuttaPrinceDormand87, ControlledErrorFollowsTheToleranceAcrossAWall) {
    for (double tol : {1e-8, 1e-11, 1e-14}) {
        auto stepper = lc::controlledPrinceDormand87<Scalar>(tol, tol);
        Scalar y{0};
        const std::size_t steps = odeint::integrate_adaptive(stepper, wall, y, 0.0, 1.0, 0.5);
        EXPECT_LT(std::abs(y[0] - wallExact(1.0)), 100 * tol) << tol;
        EXPECT_GT(steps, 5u) << tol;  // the wall was resolved, not stepped over
    }
}

}  // namespace
