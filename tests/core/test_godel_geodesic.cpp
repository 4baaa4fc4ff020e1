// SPDX-License-Identifier: BSD-3-Clause
// Closed-form Goedel geodesics through the origin against the independent oracle: numeric
// integration of Hamilton's equations (lc::traceGeodesic, dopri5, tol 1e-13) on the Cartesian
// chart, whose metric comes from core/metrics/godel.hpp, not from the closed forms.
#include "core/godel/geodesic.hpp"
#include "core/spacetime/integrator.hpp"
#include "core/metrics/godel.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace lc;
using lc::godel::OriginGeodesic;

namespace {

// Initial state at the origin built by hand: there the Cartesian metric is diag(1,-1,-1,-1), so
// p = (k0, -v cos phi0, -v sin phi0, -k3) with v = sqrt(k0^2 - mu - k3^2).
PhasePoint startAtOrigin(double k0, double k3, double phi0, int mu) {
    const double v = std::sqrt(std::max(0.0, k0 * k0 - mu - k3 * k3));
    PhasePoint s;
    s.x = Vec4::Zero();
    s.p = Vec4(k0, -v * std::cos(phi0), -v * std::sin(phi0), -k3);
    return s;
}

PhasePoint integrate(const GodelCartesian& st, const PhasePoint& s0, double l) {
    TraceOptions opt;
    opt.stepper = StepperKind::Dopri5;
    opt.absTol = opt.relTol = 1e-13;
    opt.initialStep = 1e-3;
    opt.maxAffine = l;
    opt.maxSteps = 10000000;
    opt.constraintTolerance = 1.0;
    const TraceResult r = traceGeodesic(st, s0, opt);
    EXPECT_EQ(r.reason, StopReason::MaxAffine);
    EXPECT_NEAR(r.affine, l, 1e-12);
    return r.end;
}

struct Case {
    double a, k0, k3, phi0;
    int mu;
};

void compareWithNumeric(const Case& c) {
    const GodelCartesian st(c.a);
    const OriginGeodesic g = c.mu ? OriginGeodesic::timelike(c.a, c.k0, c.k3, c.phi0)
                                  : OriginGeodesic::nullFromK3(c.a, c.k3, c.phi0, c.k0 > 0 ? 1 : -1);
    const PhasePoint s0 = startAtOrigin(c.k0, c.k3, c.phi0, c.mu);
    // Sample points spread over more than three full loops (omega l > 3 pi), including an
    // axis crossing region and the far points.
    for (double th : {0.37, 1.6, 2.9, 3.3, 4.9, 6.4, 8.0, 9.5, 10.6}) {
        const double l = th / g.omega();
        const PhasePoint num = integrate(st, s0, l);
        const Vec4 x = g.cartesian(l);
        const Vec4 p = g.momentumCartesian(l);
        const double scale = std::max(1.0, std::abs(num.x(0)));
        EXPECT_LT((x - num.x).cwiseAbs().maxCoeff(), 1e-9 * scale)
            << "a=" << c.a << " k0=" << c.k0 << " k3=" << c.k3 << " theta=" << th << "\nclosed " << x.transpose()
            << "\nnumeric " << num.x.transpose();
        EXPECT_LT((p - num.p).cwiseAbs().maxCoeff(), 1e-9) << "theta=" << th;
        // Tangent = g^{-1} p of the numeric state.
        const Vec4 v = st.metric(num.x).inverse() * num.p;
        EXPECT_LT((g.tangentCartesian(l) - v).cwiseAbs().maxCoeff(), 1e-8) << "theta=" << th;
        // H kept: 0 for light, 1/2 for proper time.
        const double H = 0.5 * p.dot(st.metric(x).inverse() * p);
        EXPECT_NEAR(H, c.mu ? 0.5 : 0.0, 1e-11);
        // Cylindrical chart: the same event (phi modulo 2 pi), off the axis.
        const Vec4 cy = g.cylindrical(l);
        const double r = std::hypot(num.x(1), num.x(2));
        EXPECT_NEAR(cy(1), r, 1e-9);
        if (r > 1e-6) {
            const double dphi = std::remainder(cy(2) - std::atan2(num.x(2), num.x(1)), 2 * kPi);
            EXPECT_NEAR(dphi, 0.0, 1e-8 / r) << "theta=" << th;
        }
        // Cylindrical tangent/momentum are consistent with the cylindrical metric.
        if (r > 1e-6) {
            const GodelCylindrical cyl(c.a);
            const Vec4 pc = cyl.metric(cy) * g.tangentCylindrical(l);
            EXPECT_LT((pc - g.momentumCylindrical(l)).cwiseAbs().maxCoeff(), 1e-11);
            // Covariant components transform with the chart Jacobian: p_X = p_r X/r - p_phi Y/r^2.
            const Vec4 pcy = g.momentumCylindrical(l);
            EXPECT_NEAR(pcy(1) * num.x(1) / r, p(1), 1e-9);
        }
    }
}

}  // namespace

TEST(GodelGeodesic, NullMatchesNumericIntegration) {
    compareWithNumeric({1.0, -1.0, 0.3, 0.4, 0});
    compareWithNumeric({1.0, -1.0, 0.0, -1.2, 0});
    compareWithNumeric({1.0, +1.0, -0.7, 2.0, 0});
    compareWithNumeric({0.8, -1.0, 0.95, 0.1, 0});
    compareWithNumeric({2.5, +1.0, 0.5, -2.9, 0});
}

TEST(GodelGeodesic, TimelikeMatchesNumericIntegration) {
    compareWithNumeric({1.0, 1.4, 0.2, 0.3, 1});
    compareWithNumeric({1.0, 1.05, 0.0, 1.1, 1});
    compareWithNumeric({1.0, -2.0, 0.5, -0.6, 1});
    compareWithNumeric({1.7, 2.0, -1.2, 0.9, 1});
}

TEST(GodelGeodesic, PlanarRayReturnsToAxis) {
    for (double a : {1.0, 0.6, 3.0}) {
        const OriginGeodesic g = OriginGeodesic::null(a, kPi / 2, 0.3, -1);
        const Vec4 x = g.cartesian(2 * kPi * a);
        EXPECT_NEAR(std::hypot(x(1), x(2)), 0.0, 1e-12 * a);
        // Past-directed: the coordinate time elapsed is -2 pi a (sqrt2 - 1).
        EXPECT_NEAR(x(0), -2 * kPi * a * (kSqrt2 - 1), 1e-12 * a);
        EXPECT_NEAR(g.cartesian(kPi * a).segment(1, 2).norm(), 2 * a, 1e-12 * a);  // reaches r = 2a
        EXPECT_NEAR(g.rMax(), 2 * a, 1e-14);
    }
}

TEST(GodelGeodesic, LaterWindingsRetraceTheLoop) {
    const OriginGeodesic g = OriginGeodesic::null(1.0, 1.2, 0.5, -1);
    const double period = kPi / g.omega();
    for (double l : {0.3, 1.1, 2.0}) {
        const Vec4 x0 = g.cartesian(l), x1 = g.cartesian(l + period), x5 = g.cartesian(l + 5 * period);
        EXPECT_LT((x1.segment(1, 2) - x0.segment(1, 2)).norm(), 1e-12);
        EXPECT_LT((x5.segment(1, 2) - x0.segment(1, 2)).norm(), 1e-12);
        EXPECT_LT(x1(0), x0(0));  // at earlier times
    }
}

TEST(GodelGeodesic, RayAlongTheAxisIsAFlatNullLine) {
    for (double k3 : {1.0, -1.0}) {
        const OriginGeodesic g = OriginGeodesic::nullFromK3(1.3, k3, 0.0, -1);
        EXPECT_EQ(g.rMax(), 0.0);
        for (double l : {0.5, 7.0, 40.0}) {
            const Vec4 x = g.cartesian(l);
            EXPECT_NEAR(x(0), -l, 1e-12 * l);
            EXPECT_EQ(x(1), 0.0);
            EXPECT_EQ(x(2), 0.0);
            EXPECT_NEAR(x(3), k3 * l, 1e-15);
            EXPECT_TRUE(g.tangentCartesian(l).allFinite());
            EXPECT_TRUE(g.cylindrical(l).allFinite());
        }
    }
    // Nearly along the axis: continuous limit.
    const OriginGeodesic g = OriginGeodesic::nullFromK3(1.0, 1 - 1e-12, 0.0, -1);
    EXPECT_LT(g.rMax(), 1e-5);
    EXPECT_NEAR(g.cartesian(3.0)(3), 3.0, 1e-11);
    EXPECT_NEAR(g.cartesian(3.0)(0), -3.0, 1e-5);
}

TEST(GodelGeodesic, AxisCrossingIsFinite) {
    // Exactly at omega l = pi and pi/2 (atan/tan edge cases): values stay finite and continuous.
    const OriginGeodesic g = OriginGeodesic::null(1.0, kPi / 2, 0.0, -1);
    for (double th : {kPi / 2, kPi, 3 * kPi / 2, 2 * kPi}) {
        const double l = th / g.omega();
        const Vec4 x = g.cartesian(l), xm = g.cartesian(l * (1 - 1e-12)), xp = g.cartesian(l * (1 + 1e-12));
        EXPECT_TRUE(x.allFinite());
        EXPECT_LT((x - xm).norm(), 1e-9);
        EXPECT_LT((x - xp).norm(), 1e-9);
        EXPECT_NEAR(g.phase(l), th, 1e-12);  // arctan(c tan) = theta at multiples of pi/2
        EXPECT_TRUE(g.tangentCylindrical(l).allFinite());
    }
    EXPECT_NEAR(g.phase(kPi / g.omega()), kPi, 1e-13);
    EXPECT_NEAR(g.phase(kPi / 2 / g.omega()), kPi / 2, 1e-13);
}

TEST(GodelGeodesic, BatchMatchesScalar) {
    std::vector<OriginGeodesic> rays;
    for (int i = 0; i < 7; ++i)
        rays.push_back(OriginGeodesic::null(1.2, 0.2 + 0.4 * i, 0.3 * i, i % 2 ? 1 : -1, 0.5, -1.0));
    rays.push_back(OriginGeodesic::timelike(1.2, 1.5, 0.3, 0.2, 0.0, 0.0));
    std::vector<double> lambdas;
    for (int j = 0; j < 50; ++j) lambdas.push_back(0.37 * j);
    godel::CartesianBatch b;
    godel::evaluateBatch(rays, lambdas, b);
    for (std::size_t i = 0; i < rays.size(); ++i)
        for (std::size_t j = 0; j < lambdas.size(); ++j) {
            const Vec4 x = rays[i].cartesian(lambdas[j]);
            const std::size_t k = i * lambdas.size() + j;
            EXPECT_NEAR(b.t[k], x(0), 1e-12);
            EXPECT_NEAR(b.X[k], x(1), 1e-12);
            EXPECT_NEAR(b.Y[k], x(2), 1e-12);
            EXPECT_NEAR(b.z[k], x(3), 1e-12);
        }
}

TEST(GodelGeodesic, RejectsInvalidParameters) {
    EXPECT_THROW(OriginGeodesic::timelike(1.0, 1.0, 0.5, 0.0), std::invalid_argument);
    EXPECT_THROW(OriginGeodesic::nullFromK3(1.0, 1.5, 0.0, -1), std::invalid_argument);
    EXPECT_THROW(OriginGeodesic::null(-1.0, 1.0, 0.0, -1), std::invalid_argument);
}
