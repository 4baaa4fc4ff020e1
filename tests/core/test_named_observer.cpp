// SPDX-License-Identifier: BSD-3-Clause
// Named observers against Boyer-Lindquist closed forms (docs/PHYSICS.md section "Named
// observers"): the ZAMO's angular velocity, the infall speed of an observer dropped from rest at
// infinity, Carter's observer, and the places where each does not exist.
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/spacetime/named_observer.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace lc;

namespace {

// The Kerr-Schild event of Boyer-Lindquist (r, theta) at phi = 0: x + i y = (r - i a) sin(theta).
Vec4 eventAt(double a, double r, double theta) {
    return Vec4(0, r * std::sin(theta), -a * std::sin(theta), r * std::cos(theta));
}

struct Hole {
    double M, a, Q;
    double delta(double r) const { return r * r - 2 * M * r + a * a + Q * Q; }
    double rho2(double r, double th) const { return r * r + a * a * std::cos(th) * std::cos(th); }
};

std::string errorOf(const Spacetime& st, const Vec4& x, NamedObserver o) {
    try {
        namedObserverVelocity(st, x, o);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

double radialRate(const KerrNewman& kn, const Vec4& x, const Vec4& u) {
    // A step of 1e-5 r in space: truncation (1e-10) and rounding (1e-11) both far below the tolerance.
    const double h = 1e-5 * kn.radius(x(1), x(2), x(3)) / u.tail<3>().norm();
    auto r = [&](const Vec4& p) { return kn.radius(p(1), p(2), p(3)); };
    return (r(x + h * u) - r(x - h * u)) / (2 * h);
}

TEST(NamedObserver, NamesRoundTripAndUnknownNamesAreRefused) {
    for (const std::string name : {"static", "zamo", "carter", "free_fall", "normal"})
        EXPECT_EQ(nameOf(*namedObserverFrom(name)), name);
    EXPECT_FALSE(namedObserverFrom("hovering"));
    EXPECT_EQ(namedObserverNames(), "static, zamo, carter, free_fall, normal");
}

// Bardeen, Press & Teukolsky (1972): the ZAMO turns with omega = a (2 M r - Q^2) / A,
// A = (r^2 + a^2)^2 - Delta a^2 sin^2(theta), i.e. u = u^t (d/dt + omega d/dphi).
TEST(NamedObserver, ZamoTurnsWithTheFrameDraggingRate) {
    for (const Hole h : {Hole{1, 0.9, 0}, Hole{1, 0.6, 0.5}, Hole{2, 1.99, 0}})
        for (const double r : {1.9 * h.M + 0.2, 5.0 * h.M, 1e3 * h.M})
            for (const double th : {0.3, 1.2, kPi / 2}) {
                const KerrNewman kn(h.M, h.a, h.Q);
                if (!(r > kn.outerHorizon() * 1.01)) continue;
                const Vec4 x = eventAt(h.a, r, th);
                const Vec4 u = namedObserverVelocity(kn, x, NamedObserver::Zamo);
                const double A = std::pow(r * r + h.a * h.a, 2) - h.delta(r) * h.a * h.a * std::pow(std::sin(th), 2);
                const double omega = h.a * (2 * h.M * r - h.Q * h.Q) / A;
                // u^x = -omega y u^t, u^y = omega x u^t, u^z = 0.
                EXPECT_NEAR(u(2) / (x(1) * u(0)), omega, 1e-10 * (1 + omega)) << r << " " << th;
                EXPECT_NEAR(u(1) / (-x(2) * u(0)), omega, 1e-10 * (1 + omega)) << r << " " << th;
                EXPECT_NEAR(u(3), 0, 1e-14);
                EXPECT_NEAR(u.dot(kn.metric(x) * u), 1, 1e-12);
            }
}

// Dropped from rest at infinity (E = 1, L_z = 0, Q = 0): rho^2 dr/dtau = -sqrt((r^2 + a^2)(2 M r - Q^2))
// (Carter's radial equation with R = (r^2 + a^2)^2 - Delta (r^2 + a^2)); Schwarzschild's
// dr/dtau = -sqrt(2M/r).
TEST(NamedObserver, FreeFallFromInfinityFallsAtTheClosedFormRate) {
    for (const Hole h : {Hole{1, 0, 0}, Hole{1, 0.9, 0}, Hole{1, 0.7, 0.3}, Hole{1, 0.998, 0}})
        for (const double r : {1.05 * (1 + std::sqrt(1 - h.a * h.a - h.Q * h.Q)), 3.0, 10.0, 1e4})
            for (const double th : {0.2, 1.0, kPi / 2}) {
                const KerrNewman kn(h.M, h.a, h.Q);
                const Vec4 x = eventAt(h.a, r, th);
                const Vec4 u = namedObserverVelocity(kn, x, NamedObserver::FreeFall);
                const Mat4 g = kn.metric(x);
                EXPECT_NEAR(u.dot(g * u), 1, 1e-12 * u(0) * u(0));
                EXPECT_NEAR(u.dot(g * Vec4::Unit(0)), 1, 1e-11) << "E";
                EXPECT_NEAR(u.dot(g * Vec4(0, -x(2), x(1), 0)), 0, 1e-10 * r) << "L_z";
                const double want = -std::sqrt((r * r + h.a * h.a) * (2 * h.M * r - h.Q * h.Q)) / h.rho2(r, th);
                EXPECT_NEAR(radialRate(kn, x, u), want, 1e-7 * std::abs(want))
                    << "a " << h.a << " r " << r << " th " << th;
            }
}

// Carter's observer ((r^2 + a^2) d/dt + a d/dphi) / sqrt(rho^2 Delta): normalised by the metric
// itself, the closed form's normalisation must come out.
TEST(NamedObserver, CarterObserverHasTheClosedFormNormalisation) {
    const Hole h{1, 0.9, 0.2};
    const KerrNewman kn(h.M, h.a, h.Q);
    for (const double r : {1.6, 4.0, 100.0})
        for (const double th : {0.3, kPi / 2}) {
            const Vec4 x = eventAt(h.a, r, th);
            const Vec4 u = namedObserverVelocity(kn, x, NamedObserver::Carter);
            const double n = 1 / std::sqrt(h.rho2(r, th) * h.delta(r));
            EXPECT_NEAR(u(0), (r * r + h.a * h.a) * n, 1e-10 * u(0)) << r << " " << th;
            EXPECT_NEAR(u(2), h.a * x(1) * n, 1e-10 * u(0)) << r << " " << th;
        }
}

TEST(NamedObserver, ObserversThatDoNotExistHereAreRefusedWithTheAlternatives) {
    const KerrNewman kerr(1, 0.9, 0);
    const Vec4 ergoregion = eventAt(0.9, 1.8, kPi / 2);  // between r+ = 1.436 and 2M
    EXPECT_NE(errorOf(kerr, ergoregion, NamedObserver::Static).find("exist here: zamo, carter, free_fall, normal"),
              std::string::npos);
    EXPECT_NO_THROW(namedObserverVelocity(kerr, ergoregion, NamedObserver::Zamo));
    EXPECT_NO_THROW(namedObserverVelocity(kerr, ergoregion, NamedObserver::Carter));
    EXPECT_NO_THROW(namedObserverVelocity(kerr, ergoregion, NamedObserver::FreeFall));
    EXPECT_NE(errorOf(kerr, eventAt(0.9, 1.2, 1.0), NamedObserver::Zamo).find("horizon"), std::string::npos);
    const Alcubierre warp(0.5, 1, 8);
    EXPECT_NE(errorOf(warp, Vec4(0, 3, 0, 0), NamedObserver::Carter).find("Kerr-Newman"), std::string::npos);
    EXPECT_NE(errorOf(warp, Vec4(0, 3, 0, 0), NamedObserver::Zamo).find("axial symmetry"), std::string::npos);
    // The warp drive's Eulerian observer is its normal one: u = d/dt + v f d/dx.
    const Vec4 u = namedObserverVelocity(warp, Vec4(0, 0.2, 0, 0), NamedObserver::Normal);
    EXPECT_NEAR(u(0), 1, 1e-12);
    EXPECT_GT(u(1), 0.4);
}

}  // namespace
