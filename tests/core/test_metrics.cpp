// SPDX-License-Identifier: BSD-3-Clause
// Metrics written as code (core/metrics): exact AutoDiff derivatives against hand-derived ones,
// exact determinants; the factory builds every metric by name.
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/factory.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>
#include <stdexcept>

using namespace lc;

namespace {

TEST(AutoDiff, GodelCylindricalDerivativesMatchHandDerivation) {
    const double a = 0.8;
    const GodelCylindrical g(a);
    for (double r : {0.3, 1.0, 1.7, 2.4}) {
        Mat4 m;
        std::array<Mat4, 4> dg;
        g.metricAndDerivatives(Vec4(0.1, r, 0.4, -0.2), m, dg);
        const double u = r * r / (4 * a * a), du = r / (2 * a * a);
        EXPECT_NEAR(dg[1](0, 2), 2 * r / (kSqrt2 * a), 1e-14);
        EXPECT_NEAR(dg[1](1, 1), du / ((1 + u) * (1 + u)), 1e-14);
        EXPECT_NEAR(dg[1](2, 2), -2 * r + r * r * r / (a * a), 1e-13);
        for (int k : {0, 2, 3}) EXPECT_EQ(dg[k].cwiseAbs().maxCoeff(), 0.0);  // Killing directions
        EXPECT_NEAR(m.determinant(), -r * r, 1e-12);                          // docs/PHYSICS.md section 1
        EXPECT_LT((g.inverseMetric(Vec4(0, r, 0, 0)) * g.metric(Vec4(0, r, 0, 0)) - Mat4::Identity()).norm(), 1e-13);
    }
}

TEST(AutoDiff, SchwarzschildRadialDerivativeMatchesHandDerivation) {
    // On the x axis (y = z = 0) of outgoing Kerr-Schild, g = eta - f l l with f = 2M/x,
    // l = (1, -1, 0, 0): g_tt = 1 - 2M/x, g_tx = +2M/x, g_xx = -1 - 2M/x.
    const Schwarzschild bh(1.5);
    Mat4 m;
    std::array<Mat4, 4> dg;
    const double x = 7.0, M = 1.5;
    bh.metricAndDerivatives(Vec4(0, x, 0, 0), m, dg);
    EXPECT_NEAR(m(0, 0), 1 - 2 * M / x, 1e-15);
    EXPECT_NEAR(dg[1](0, 0), 2 * M / (x * x), 1e-15);
    EXPECT_NEAR(m(0, 1), 2 * M / x, 1e-15);
    EXPECT_NEAR(dg[1](0, 1), -2 * M / (x * x), 1e-15);
    EXPECT_NEAR(dg[1](1, 1), 2 * M / (x * x), 1e-15);
}

TEST(AutoDiff, AlcubierreHasUnitDeterminantAndMovingBubble) {
    const Alcubierre w(1.1, 1.0, 35.0);
    for (double x : {-0.5, 0.0, 0.97, 1.03, 3.0})
        EXPECT_NEAR(w.metric(Vec4(0.2, x, 0.1, 0)).determinant(), -1.0, 1e-13);
    // Metric depends on x - v t only: d_t g = -v d_x g.
    Mat4 m;
    std::array<Mat4, 4> dg;
    w.metricAndDerivatives(Vec4(0.3, 1.3, 0.2, 0.1), m, dg);
    EXPECT_LT((dg[0] + 1.1 * dg[1]).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_GT(dg[1].cwiseAbs().maxCoeff(), 1.0);  // the wall is steep at sigma = 35
}

// The Kerr-Schild closed forms (KerrSchildMetric) against the general path: the inverse
// against Eigen's inversion of g, Hamilton's equations against automatic derivatives of all
// of g (Spacetime::generalFlow), at points near the outer horizon, on the spin axis, close
// to the ring singularity's plane and far away, for Kerr-Newman and Schwarzschild.
TEST(KerrSchild, ClosedFormInverseAndFlowMatchTheGeneralPath) {
    const KerrNewman kn(1.0, 0.9, 0.3);
    const Schwarzschild bh(2.0);
    const double rPlus = kn.outerHorizon();
    const std::vector<Vec4> points{Vec4(0, rPlus * 1.000001, 0.0, 0.0),  // just outside r+ (equator)
                                   Vec4(3.0, 0.0, 0.0, rPlus * 1.0001),  // spin axis, near the horizon
                                   Vec4(0, 0.0, 0.0, -7.0),              // spin axis
                                   Vec4(0, 1.2, -0.4, 0.05),             // near the ring's plane
                                   Vec4(-4, 25.0, -13.0, 9.0),
                                   Vec4(0, 3e8, 1e8, -2e8),    // far field
                                   Vec4(1, 0.4, 0.3, -0.2),    // inside the horizons, over the ring's disk
                                   Vec4(0, -0.7, 0.9, 1e-3)};  // beside the ring
    const std::vector<Vec4> momenta{Vec4(1.0, 0.3, -0.4, 0.2), Vec4(-2.5, 1.0, 0.0, -3.0)};
    for (const Spacetime* st : {static_cast<const Spacetime*>(&kn), static_cast<const Spacetime*>(&bh)})
        for (const Vec4& x : points) {
            const Mat4 g = st->metric(x), gi = st->inverseMetric(x);
            EXPECT_LT((gi - g.inverse()).norm(), 1e-12 * gi.norm()) << st->name() << " at " << x.transpose();
            EXPECT_LT((gi * g - Mat4::Identity()).norm(), 1e-12) << st->name() << " at " << x.transpose();
            for (const Vec4& p : momenta) {
                const HamiltonianFlow fast = st->flow(x, p), general = st->generalFlow(x, p);
                // KerrNewman writes the gradients of f and l out; KerrSchildMetric differentiates
                // kerrSchild() automatically: the two must agree too.
                const HamiltonianFlow automatic = static_cast<const KerrNewman*>(st)->KerrSchildMetric::flow(x, p);
                EXPECT_LT((fast.dpdl - automatic.dpdl).norm(), 1e-12 * (automatic.dpdl.norm() + 1e-300))
                    << x.transpose();
                EXPECT_LT((fast.dxdl - automatic.dxdl).norm(), 1e-13 * automatic.dxdl.norm()) << x.transpose();
                const double scale = general.dpdl.norm() + 1e-300;
                EXPECT_LT((fast.dxdl - general.dxdl).norm(), 1e-12 * general.dxdl.norm()) << x.transpose();
                EXPECT_LT((fast.dpdl - general.dpdl).norm(), 1e-10 * scale) << x.transpose();
                EXPECT_NEAR(fast.H, general.H, 1e-12 * p.squaredNorm() * gi.norm());
            }
        }
}

TEST(Factory, BuildsEveryMetricAndRejectsUnknownParameters) {
    for (const auto& d : knownMetrics()) EXPECT_NO_THROW(makeSpacetime(d.name, {})) << d.name;
    EXPECT_THROW(makeSpacetime("schwarzschild", {{"a", 1}}), std::invalid_argument);
    EXPECT_THROW(makeSpacetime("nope", {}), std::invalid_argument);
}

}  // namespace
