// SPDX-License-Identifier: BSD-3-Clause
// The observer's world line for animations (core/scene/observer_world_line) against closed
// forms: straight lines in flat spacetime, the static observer's clock rate 1/sqrt(1 - 2M/r),
// the circular geodesic of Schwarzschild, and the cycloid of radial infall from rest.
#include "core/scene/observer_world_line.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace lc;

namespace {

TraceOptions tight() {
    TraceOptions opt;
    opt.absTol = opt.relTol = 1e-12;
    return opt;
}

TEST(ObserverWorldLine, FreeFallInFlatSpacetimeIsAStraightLineBothWaysInProperTime) {
    const Minkowski flat;
    const double v = 0.8, gamma = 1 / std::sqrt(1 - v * v);
    const Vec4 u(gamma, gamma * v, 0, 0), x0(1, 2, 3, 4);
    const std::vector<double> taus{0, 2.5, -1.5, 10};
    const auto line = observerWorldLine(flat, x0, u, ObserverMotion::FreeFall, taus, tight());
    for (std::size_t k = 0; k < taus.size(); ++k) {
        EXPECT_LT((line[k].position - (x0 + taus[k] * u)).norm(), 1e-9) << "tau " << taus[k];
        EXPECT_LT((line[k].velocity - u).norm(), 1e-9);
    }
}

TEST(ObserverWorldLine, StaticObserverClockRunsSlowDeepInTheWell) {
    const KerrNewman schwarzschild(1, 0, 0);
    const Vec4 x0(0, 10, 0, 0);
    const auto line = observerWorldLine(schwarzschild, x0, Vec4::Unit(0), ObserverMotion::Static, {4, -2}, tight());
    const double rate = 1 / std::sqrt(1 - 2.0 / 10);  // dt/dtau
    EXPECT_NEAR(line[0].position(0), 4 * rate, 1e-10);
    EXPECT_NEAR(line[1].position(0), -2 * rate, 1e-10);
    EXPECT_LT((line[0].position.tail<3>() - x0.tail<3>()).norm(), 1e-15);
    EXPECT_NEAR(line[0].velocity(0), rate, 1e-12);
    // Inside the horizon d/dt is spacelike: no static observer there.
    EXPECT_THROW(
        observerWorldLine(schwarzschild, Vec4(0, 1.5, 0, 0), Vec4::Unit(0), ObserverMotion::Static, {1}, tight()),
        std::invalid_argument);
    // A static observer has no spatial velocity.
    EXPECT_THROW(observerWorldLine(schwarzschild, x0, Vec4(1.2, 0, 0.1, 0), ObserverMotion::Static, {1}, tight()),
                 std::invalid_argument);
}

TEST(ObserverWorldLine, CircularGeodesicOfSchwarzschildKeepsItsRadiusAndAngularVelocity) {
    const double M = 1, r = 10;
    const KerrNewman schwarzschild(M, 0, 0);
    const double ut = 1 / std::sqrt(1 - 3 * M / r), omega = std::sqrt(M / (r * r * r));  // dt/dtau, dphi/dt
    const Vec4 u(ut, 0, ut * omega * r, 0);
    const double tau = 150;  // about three quarters of an orbit
    const auto line = observerWorldLine(schwarzschild, Vec4(0, r, 0, 0), u, ObserverMotion::FreeFall, {tau}, tight());
    const Vec4& x = line[0].position;
    EXPECT_NEAR(x.tail<3>().norm(), r, 1e-7);
    EXPECT_NEAR(std::atan2(x(2), x(1)), std::remainder(omega * ut * tau, 2 * M_PI), 1e-8);
    EXPECT_NEAR(x(3), 0, 1e-12);
    EXPECT_NEAR(line[0].velocity.dot(schwarzschild.metric(x) * line[0].velocity), 1, 1e-9);
}

TEST(ObserverWorldLine, RadialInfallFromRestFollowsTheCycloidAndEndsBeforeTheSingularity) {
    // r = r0 (1 + cos eta) / 2, tau = sqrt(r0^3 / 8M) (eta + sin eta) (MTW eq. 31.10).
    const double M = 1, r0 = 6;
    const KerrNewman schwarzschild(M, 0, 0);
    const Vec4 x0(0, 0, 0, r0);  // on the axis: the same in every Kerr-Schild form
    for (double eta : {0.5, 1.0, 1.5}) {
        const double tau = std::sqrt(r0 * r0 * r0 / (8 * M)) * (eta + std::sin(eta));
        const auto line = observerWorldLine(schwarzschild, x0, Vec4::Unit(0) / std::sqrt(1 - 2 * M / r0),
                                            ObserverMotion::FreeFall, {tau}, tight());
        EXPECT_NEAR(line[0].position.tail<3>().norm(), r0 * (1 + std::cos(eta)) / 2, 1e-7) << "eta " << eta;
    }
    // The whole fall takes pi sqrt(r0^3 / 8M) = 16.3: the world line cannot be continued past it.
    EXPECT_THROW(observerWorldLine(schwarzschild, x0, Vec4::Unit(0), ObserverMotion::FreeFall, {30}, tight()),
                 std::invalid_argument);
}

TEST(ObserverWorldLine, RejectsNonFiniteTimesAndVelocitiesThatAreNotFutureTimelike) {
    const Minkowski flat;
    EXPECT_THROW(observerWorldLine(flat, Vec4::Zero(), Vec4::Unit(0), ObserverMotion::Static, {NAN}, tight()),
                 std::invalid_argument);
    EXPECT_THROW(observerWorldLine(flat, Vec4::Zero(), Vec4(1, 1, 0, 0), ObserverMotion::FreeFall, {1}, tight()),
                 std::invalid_argument);
    EXPECT_THROW(observerWorldLine(flat, Vec4::Zero(), Vec4(-1, 0, 0, 0), ObserverMotion::FreeFall, {1}, tight()),
                 std::invalid_argument);
    EXPECT_EQ(parseObserverMotion("free_fall"), ObserverMotion::FreeFall);
    EXPECT_THROW(parseObserverMotion("hover"), std::invalid_argument);
}

}  // namespace
