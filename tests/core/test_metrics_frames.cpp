// Metrics written as code: exact AutoDiff derivatives against hand-derived ones, exact
// determinants, and orthonormal frames.
#include "core/spacetime/frame.hpp"
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/factory.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/spacetime/scattering.hpp"

#include <gtest/gtest.h>

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
        EXPECT_NEAR(m.determinant(), -r * r, 1e-12);                       // docs/PHYSICS.md section 1
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
    for (double x : {-0.5, 0.0, 0.97, 1.03, 3.0}) EXPECT_NEAR(w.metric(Vec4(0.2, x, 0.1, 0)).determinant(), -1.0, 1e-13);
    // Metric depends on x - v t only: d_t g = -v d_x g.
    Mat4 m;
    std::array<Mat4, 4> dg;
    w.metricAndDerivatives(Vec4(0.3, 1.3, 0.2, 0.1), m, dg);
    EXPECT_LT((dg[0] + 1.1 * dg[1]).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_GT(dg[1].cwiseAbs().maxCoeff(), 1.0);  // the wall is steep at sigma = 35
}

TEST(Frames, OrthonormalForStaticAndMovingObservers) {
    const Mat4 eta = Eigen::Vector4d(1, -1, -1, -1).asDiagonal();
    const auto check = [&](const Spacetime& st, const Vec4& x, const Vec4& u) {
        const LocalFrame f = LocalFrame::withVelocity(st, x, u);
        const Mat4 g = st.metric(x);
        Mat4 gram;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) gram(i, j) = f.e[i].dot(g * f.e[j]);
        EXPECT_LT((gram - eta).cwiseAbs().maxCoeff(), 1e-12) << st.name();
        // A viewing direction gives a null momentum that the frame maps back to the direction.
        const Vec3 n = Vec3(0.3, -0.5, 0.8).normalized();
        const Vec4 p = f.pastNullMomentum(st, n);
        EXPECT_NEAR(st.hamiltonian(x, p), 0, 1e-13);
        EXPECT_LT((f.directionOf(st, p) - n).norm(), 1e-12);
    };
    const KerrNewman kerr(1.0, 0.9, 0.2);
    check(kerr, Vec4(0, 6, 2, 1), Vec4::Unit(0));
    check(kerr, Vec4(0, 6, 2, 1), Vec4(1.3, 0.2, 0.5, -0.1));
    const GodelCartesian godel(1.0);
    check(godel, Vec4(0, 1.2, -0.7, 0.3), Vec4::Unit(0));
    check(godel, Vec4(0, 0.4, 0.1, 0), Vec4(1.2, 0.3, 0.1, 0.2));
    EXPECT_THROW(LocalFrame::withVelocity(godel, Vec4::Zero(), Vec4(1, 2, 0, 0)), std::invalid_argument);
}

TEST(Factory, BuildsEveryMetricAndRejectsUnknownParameters) {
    for (const auto& d : knownMetrics()) EXPECT_NO_THROW(makeSpacetime(d.name, {})) << d.name;
    EXPECT_THROW(makeSpacetime("schwarzschild", {{"a", 1}}), std::invalid_argument);
    EXPECT_THROW(makeSpacetime("nope", {}), std::invalid_argument);
}

// Kerr a = 0.9 seen edge-on from far away (Bardeen): the shadow is 9.676740633922840 M wide.
// Bisection on the screen's horizontal line between rays that fall in and rays that escape.
double shadowEdge(const KerrNewman& bh, double D, double side) {
    const Vec4 x(0, D, 0, 0);
    const LocalFrame f = LocalFrame::staticObserver(bh, x);
    TraceOptions o;
    o.absTol = o.relTol = 1e-12;
    o.initialStep = 1;
    o.escapeRadius = 2 * D;
    o.maxAffine = 1e9;
    auto captured = [&](double b) {
        const Vec3 n(-1, side * b / D, 0);
        return traceGeodesic(bh, {x, f.pastNullMomentum(bh, n)}, o).reason == StopReason::Horizon;
    };
    double in = 0, out = 10;
    EXPECT_TRUE(captured(in));
    EXPECT_FALSE(captured(out));
    for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (in + out);
        (captured(mid) ? in : out) = mid;
    }
    // The screen offset maps to the impact parameter as D tan(theta) -> b for D >> M.
    return 0.5 * (in + out);
}

TEST(Kerr, EdgeOnShadowWidthMatchesBardeen) {
    const KerrNewman bh(1.0, 0.9, 0.0);
    const double D = 1e5;
    const double width = shadowEdge(bh, D, +1) + shadowEdge(bh, D, -1);
    EXPECT_NEAR(width, 9.676740633922840, 2e-3);  // finite-distance corrections are O(M/D)
    // Asymmetric: the spin shifts the shadow sideways.
    EXPECT_GT(std::abs(shadowEdge(bh, D, +1) - shadowEdge(bh, D, -1)), 1.0);
}

}  // namespace
