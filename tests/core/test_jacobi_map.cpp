// SPDX-License-Identifier: BSD-3-Clause
// The Jacobi map of a ray (core/curvature/jacobi_map): flat space gives D = affine distance times
// the identity, and a Schwarzschild point lens in the weak field the magnifications of its two
// images, mu = 1/(1 - (theta_E/theta)^4) each, |mu+| + |mu-| = (u^2 + 2)/(u sqrt(u^2 + 4)) and
// mu+ + mu- = 1 (Schneider, Ehlers & Falco 1992, eqs. 2.24-2.25; Paczynski 1986), with the
// source positions the traced rays themselves reach.
#include "core/curvature/jacobi_map.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {
using namespace lc;

TEST(JacobiMap, FlatSpaceSpreadsABundleByItsDistance) {
    const Minkowski flat;
    const LocalFrame observer = LocalFrame::staticObserver(flat, Vec4(0, -5, 1, 2));
    SourcePlane plane;
    plane.point = Vec3(20, 0, 0);
    const Vec3 n = Vec3(1, 0.3, -0.2).normalized();
    const JacobiRayResult r = traceJacobiRay(flat, observer, n, plane);
    ASSERT_TRUE(r.reached);
    const double distance = 25 / n(0);
    EXPECT_NEAR(r.affine, distance, 1e-9 * distance);
    // Oblique incidence stretches the bundle's footprint on the plane by 1/cos: det D = L^2 / n_x.
    EXPECT_NEAR(r.map.determinant() / (distance * distance / n(0)), 1, 1e-9);
}

// Observer and source plane 10^10 M on either side of a unit mass (impact parameters 10^5 M: the
// second-order deflection, 15 pi M^2 / 4 b^2, changes mu by about 10^-5): theta_E^2 = 4 M D_ds/(D_d D_s).
TEST(JacobiMap, SchwarzschildPointLensMagnifiesBothImagesAsTheWeakFieldFormula) {
    const double M = 1, Dd = 1e10, Dds = 1e10, Ds = Dd + Dds;
    const Schwarzschild lens(M);
    const LocalFrame observer = LocalFrame::staticObserver(lens, Vec4(0, -Dd, 0, 0));
    SourcePlane plane;
    plane.point = Vec3(Dds, 0, 0);
    const double thetaE = std::sqrt(4 * M * Dds / (Dd * Ds));
    for (double u : {0.3, 1.0, 2.5}) {
        const double beta = u * thetaE;
        // The two images of the lens equation beta = theta - theta_E^2 / theta.
        const double plus = 0.5 * (beta + std::sqrt(beta * beta + 4 * thetaE * thetaE));
        const double minus = 0.5 * (beta - std::sqrt(beta * beta + 4 * thetaE * thetaE));
        double mu[2], reached[2];
        int k = 0;
        for (double theta : {plus, minus}) {
            const JacobiRayResult r =
                traceJacobiRay(lens, observer, Vec3(std::cos(theta), std::sin(theta), 0), plane, {1e-12, 1e12, 100000});
            ASSERT_TRUE(r.reached);
            reached[k] = r.x(2) / Ds;  // the source position this ray reaches, as an angle
            mu[k] = r.magnification(Ds);
            // Each image against its own traced source position: mu = 1/(1 - (theta_E/theta)^4).
            EXPECT_NEAR(mu[k] * (1 - std::pow(thetaE / theta, 4)), 1, 3e-4) << "u = " << u << " theta = " << theta;
            ++k;
        }
        EXPECT_NEAR(reached[0] / beta, 1, 3e-4) << "both rays reach the source the lens equation says";
        EXPECT_NEAR(reached[1] / beta, 1, 3e-4);
        const double total = (u * u + 2) / (u * std::sqrt(u * u + 4));
        EXPECT_NEAR((std::abs(mu[0]) + std::abs(mu[1])) / total, 1, 3e-4) << "u = " << u;
        EXPECT_GT(mu[0], 0);  // the outer image keeps its parity, the inner one is mirrored
        EXPECT_LT(mu[1], 0);
        EXPECT_NEAR(mu[0] + mu[1], 1, 3e-4);
    }
}

// The first relativistic image (the ray that circles the hole once): Bozza (2002, Phys. Rev. D 66,
// 103001, eqs. 35-36 and 41) in the strong-deflection limit, for Schwarzschild a_bar = 1,
// b_bar = ln(216 (7 - 4 sqrt 3)) - pi, u_m = 3 sqrt(3) M, e_n = exp((b_bar - 2 n pi)/a_bar):
// theta_n = (u_m / D_d)(1 + e_n) and mu_n = u_m^2 (1 + e_n) e_n D_s / (a_bar beta D_ds D_d^2). The limit
// drops terms of order e_n (1e-3 for n = 1): agreement to 1 %.
TEST(JacobiMap, FirstRelativisticImageOfSchwarzschildAsBozzasStrongDeflectionLimit) {
    const double M = 1, Dd = 1e6, Dds = 1e6, Ds = Dd + Dds, beta = 2e-4;
    const Schwarzschild lens(M);
    const LocalFrame observer = LocalFrame::staticObserver(lens, Vec4(0, -Dd, 0, 0));
    SourcePlane plane;
    plane.point = Vec3(Dds, 0, 0);
    const double um = 3 * std::sqrt(3.0) * M, bBar = std::log(216 * (7 - 4 * std::sqrt(3.0))) - kPi;
    const double e1 = std::exp(bBar - 2 * kPi);
    const double thetaBozza = um / Dd * (1 + e1);
    const double muBozza = um * um * (1 + e1) * e1 * Ds / (beta * Dds * Dd * Dd);
    const JacobiRayOptions tight{1e-13, 1e12, 200000};
    auto reachedAngle = [&](double theta) {
        const JacobiRayResult r =
            traceJacobiRay(lens, observer, Vec3(std::cos(theta), std::sin(theta), 0), plane, tight);
        return r.reached ? r.x(2) / Ds : NAN;
    };
    // The image: where the traced ray reaches beta, bisected between the angles whose rays are
    // deflected by 2 pi -/+ 0.5 rad (b/u_m - 1 = e_1 exp(+/-0.5); both reach the plane, far to
    // either side; the second relativistic image lies at e_2 ~ 2e-6, outside).
    double lo = um / Dd * (1 + e1 * std::exp(-0.5)), hi = um / Dd * (1 + e1 * std::exp(0.5));
    const double fLo = reachedAngle(lo) - beta;
    ASSERT_TRUE(std::isfinite(fLo) && std::isfinite(reachedAngle(hi)));
    ASSERT_LT(fLo * (reachedAngle(hi) - beta), 0) << "the bracket holds no image";
    for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        ((reachedAngle(mid) - beta) * fLo > 0 ? lo : hi) = mid;
    }
    const double theta = 0.5 * (lo + hi);
    EXPECT_NEAR(theta / thetaBozza, 1, 1e-4);
    const JacobiRayResult r = traceJacobiRay(lens, observer, Vec3(std::cos(theta), std::sin(theta), 0), plane, tight);
    ASSERT_TRUE(r.reached);
    EXPECT_NEAR(std::abs(r.magnification(Ds)) / muBozza, 1, 1e-2);
}

}  // namespace
