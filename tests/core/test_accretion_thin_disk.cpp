// SPDX-License-Identifier: BSD-3-Clause
// The thin disk's orbits and flux, computed from the metric's own g<S>, against the closed forms
// of Bardeen, Press & Teukolsky (1972) and Page & Thorne (1974) (docs/PHYSICS.md section 12).
#include "core/accretion/thin_disk.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lc {
namespace {

SpacetimePtr kerr(double a, double q = 0) { return std::make_shared<KerrNewman>(1.0, a, q); }

// BPT (2.12)-(2.16), M = 1; s = +1 for orbits turning with the hole, -1 against it.
struct KerrOrbit {
    double omega, energy, angularMomentum;
};
KerrOrbit bardeenOrbit(double r, double a, int s) {
    const double r32 = std::pow(r, 1.5), den = std::pow(r, 0.75) * std::sqrt(r32 - 3 * std::sqrt(r) + s * 2 * a);
    return {s / (r32 + s * a), (r32 - 2 * std::sqrt(r) + s * a) / den,
            s * (r * r - s * 2 * a * std::sqrt(r) + a * a) / den};
}

// Page & Thorne (1974) eq. 15n, M = Mdot = 1: F = f / (4 pi r), x = sqrt(r), a* signed (a
// retrograde disk is a prograde one about -a*).
double pageThorneFlux(double r, double a) {
    const double x = std::sqrt(r), x0 = std::sqrt(ThinDiskModel::bardeenIsco(a, a >= 0));
    const double x1 = 2 * std::cos((std::acos(a) - kPi) / 3), x2 = 2 * std::cos((std::acos(a) + kPi) / 3),
                 x3 = -2 * std::cos(std::acos(a) / 3);
    auto term = [&](double xi, double xj, double xk) {
        if (std::abs(xi - a) < 1e-15) return 0.0;  // a = 0: the root x = 0 carries no term
        return 3 * (xi - a) * (xi - a) / (xi * (xi - xj) * (xi - xk)) * std::log((x - xi) / (x0 - xi));
    };
    const double bracket = x - x0 - 1.5 * a * std::log(x / x0) - term(x1, x2, x3) - term(x2, x1, x3) - term(x3, x1, x2);
    const double f = 1.5 / (x * x * (x * x * x - 3 * x + 2 * a)) * bracket;
    return f / (4 * kPi * r);
}

TEST(ThinDisk, IscoMatchesBardeenPressTeukolskyForEverySpinAndSense) {
    for (double a : {0.0, 0.3, 0.5, 0.9, 0.998, -0.7})
        for (bool prograde : {true, false}) {
            const ThinDiskModel disk(kerr(a), 0, 100, prograde);
            // The hole's spin sign decides which sense is prograde; BPT's formula takes |a|.
            EXPECT_NEAR(disk.isco(), ThinDiskModel::bardeenIsco(a, prograde), 1e-7 * disk.isco())
                << "a = " << a << (prograde ? " prograde" : " retrograde");
        }
    // Anchors from the literature: 6 M, 1.237 M (a = 0.998), 9 M (a -> 1 retrograde, here a = 0.998).
    EXPECT_DOUBLE_EQ(ThinDiskModel::bardeenIsco(0, true), 6.0);
    EXPECT_NEAR(ThinDiskModel::bardeenIsco(0.998, true), 1.2370, 1e-4);
    EXPECT_NEAR(ThinDiskModel::bardeenIsco(1.0, false), 9.0, 1e-12);
}

TEST(ThinDisk, KeplerianOrbitsMatchTheClosedFormsIncludingRetrograde) {
    for (double a : {0.0, 0.6, 0.95})
        for (int s : {1, -1}) {
            const ThinDiskModel disk(kerr(a), 0, 50, s > 0);
            for (double r : {disk.isco(), 1.3 * disk.isco(), 20.0, 49.0}) {
                const CircularOrbit o = disk.orbit(r);
                const KerrOrbit b = bardeenOrbit(r, a, s);
                ASSERT_TRUE(o.exists);
                EXPECT_NEAR(o.omega, b.omega, 1e-13) << "a " << a << " s " << s << " r " << r;
                EXPECT_NEAR(o.energy, b.energy, 1e-13);
                EXPECT_NEAR(o.angularMomentum, b.angularMomentum, 1e-12);
            }
        }
}

TEST(ThinDisk, KerrNewmanOrbitsMatchTheChargedClosedForm) {
    // Omega = sqrt(M r - Q^2) / (r^2 + a sqrt(M r - Q^2)) for the prograde orbit.
    const double a = 0.5, q = 0.6;
    const ThinDiskModel disk(kerr(a, q), 0, 40, true);
    for (double r : {disk.isco(), 8.0, 30.0}) {
        const double w = std::sqrt(r - q * q);
        EXPECT_NEAR(disk.orbit(r).omega, w / (r * r + a * w), 1e-13) << r;
    }
    // Charge pulls the ISCO in: below Kerr's for the same spin.
    EXPECT_LT(disk.isco(), ThinDiskModel::bardeenIsco(a, true));
}

// An extremal Kerr-Newman hole (a^2 + Q^2 = M^2, accepted by the ranges) with a = 0.6, Q = 0.8, where
// M^2 - a^2 - Q^2 rounds to -1.1e-16: its horizon is r_+ = M, and the ISCO is the minimum of the
// prograde circular orbits' energy (M = 1, E = 1 at infinity; Dadhich & Kale 1977):
// E(r) = (r^2 - 2 r + Q^2 + a sqrt(r - Q^2)) / (r sqrt(r^2 - 3 r + 2 Q^2 + 2 a sqrt(r - Q^2))),
// minimised here by golden section. Before, r_+ was NaN: the search started at 7e19 M and failed.
TEST(ThinDisk, ExtremalKerrNewmanHasItsHorizonAtMAndTheEnergyMinimumAsIsco) {
    const double a = 0.6, q = 0.8;
    const auto hole = kerr(a, q);
    EXPECT_EQ(std::dynamic_pointer_cast<const KerrNewman>(hole)->outerHorizon(), 1.0);
    auto energy = [&](double r) {
        const double w = std::sqrt(r - q * q);
        return (r * r - 2 * r + q * q + a * w) / (r * std::sqrt(r * r - 3 * r + 2 * q * q + 2 * a * w));
    };
    double lo = 1.2, hi = 6;  // the energy falls, then rises
    for (int i = 0; i < 200; ++i) {
        const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        (energy(m1) < energy(m2) ? hi : lo) = energy(m1) < energy(m2) ? m2 : m1;
    }
    const ThinDiskModel disk(hole, 0, 40, true);
    EXPECT_NEAR(disk.isco(), 0.5 * (lo + hi), 1e-6);
}

TEST(ThinDisk, PageThorneFluxMatchesItsClosedFormAcrossTheDisk) {
    for (double a : {0.0, 0.5, 0.9, 0.998}) {
        for (bool prograde : {true, false}) {
            const ThinDiskModel disk(kerr(a), 0, 1000, prograde);
            const double signedA = prograde ? a : -a;
            for (double fraction : {1.0001, 1.01, 1.1, 1.5, 2.0, 4.0, 10.0, 50.0, 150.0}) {
                const double r = fraction * disk.isco();
                if (r > 1000) continue;
                const double expected = pageThorneFlux(r, signedA);
                // 1e-7 of the value; within 1e-4 of a fast hole's ISCO, where the flux starts from 0
                // and the orbits change fast, 1e-10 of the peak.
                EXPECT_NEAR(disk.flux(r), expected, 1e-7 * std::abs(expected) + 1e-10 * disk.maxFlux())
                    << "a " << a << (prograde ? " pro" : " retro") << " r " << r;
            }
            EXPECT_EQ(disk.flux(disk.isco()), 0.0);  // no torque at the inner edge
            EXPECT_EQ(disk.flux(1001), 0.0);         // nothing beyond the outer edge
        }
    }
    // The Schwarzschild peak: F is largest at r = 9.55 M (Page & Thorne; Novikov & Thorne 1973).
    const ThinDiskModel schwarzschild(kerr(0), 0, 1000, true);
    EXPECT_NEAR(schwarzschild.peakRadius(), 9.55, 0.01);
    EXPECT_NEAR(schwarzschild.maxFlux(), pageThorneFlux(schwarzschild.peakRadius(), 0), 1e-7 * schwarzschild.maxFlux());
}

TEST(ThinDisk, TruncatedDiskStartsItsFluxAtItsOwnInnerEdge) {
    const ThinDiskModel disk(kerr(0.5), 10, 100, true);
    EXPECT_EQ(disk.innerRadius(), 10);
    EXPECT_EQ(disk.flux(10), 0.0);
    EXPECT_GT(disk.flux(11), 0.0);
    // A truncated disk radiates less at the same radius than one reaching the ISCO.
    const ThinDiskModel full(kerr(0.5), 0, 100, true);
    EXPECT_LT(disk.flux(20), full.flux(20));
}

TEST(ThinDisk, RedshiftOfTheMatterSeenFromFarAlongTheAxisIsTheClosedForm) {
    // A photon reaching the axis has p_phi = 0, so g = 1 / (u^t sqrt(g_tt(observer))) whatever its
    // path (BPT's u^t); the observer sits on the axis at z = D.
    const double a = 0.9, D = 1e4;
    const ThinDiskModel disk(kerr(a), 0, 30, true);
    for (double r : {disk.isco(), 5.0, 20.0}) {
        const double rho = std::sqrt(r * r + a * a);
        const Vec4 x(0, rho * std::cos(0.4), rho * std::sin(0.4), 0);
        // Any covariant momentum with p_phi = -y p_x + x p_y = 0: radial in (x, y), some p_z.
        const Vec4 p(-1, 0.3 * std::cos(0.4), 0.3 * std::sin(0.4), 0.8);
        const double gttObserver = 1 - 2 * D / (D * D + a * a);
        const double observedEnergy = p(0) / std::sqrt(gttObserver);  // static observer: p_t / sqrt(g_tt)
        const double r32 = std::pow(r, 1.5);
        const double expected = std::sqrt(1 - 3 / r + 2 * a / r32) / (1 + a / r32) / std::sqrt(gttObserver);
        EXPECT_NEAR(disk.redshift(x, p, observedEnergy), expected, 1e-13) << r;
    }
}

TEST(ThinDisk, RefusesMetricsWithoutHoleAndEdgesWithoutStableOrbits) {
    EXPECT_THROW(ThinDiskModel(std::make_shared<Minkowski>(), 0, 10, true), std::invalid_argument);
    try {
        ThinDiskModel(kerr(0), 4, 10, true);
        FAIL() << "an inner edge inside the ISCO must be refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("innermost stable circular orbit r = 6"), std::string::npos) << e.what();
    }
    EXPECT_THROW(ThinDiskModel(kerr(0), 8, 7, true), std::invalid_argument);
    // Nearly extremal spin: the prograde ISCO closes in on the horizon and is still found; at a = M
    // it meets the horizon, and the disk needs an inner radius.
    const ThinDiskModel nearlyExtremal(kerr(0.9999), 0, 10, true);
    EXPECT_NEAR(nearlyExtremal.isco(), ThinDiskModel::bardeenIsco(0.9999, true), 1e-6);
    EXPECT_THROW(ThinDiskModel(kerr(1.0), 0, 10, true), std::invalid_argument);
    EXPECT_GT(ThinDiskModel(kerr(1.0), 2, 10, true).flux(3), 0.0);
}

}  // namespace
}  // namespace lc
