// SPDX-License-Identifier: BSD-3-Clause
// core/spacetime/integrator: the generic Hamiltonian tracer on the Goedel metric (axis-regular
// Cartesian chart) against the closed-form null geodesics of docs/PHYSICS.md section 2
// (tests/common/godel_null_oracle.hpp, independent of the library's own closed-form module).
#include "core/spacetime/frame.hpp"
#include "core/spacetime/integrator.hpp"
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/scene/observer_ray.hpp"
#include "tests/common/godel_null_oracle.hpp"

#include <gtest/gtest.h>

using namespace lc;
using lc::test::closedFormNull;
using lc::test::pastRay;

namespace {

TraceOptions tight(double maxAffine) {
    TraceOptions o;
    o.stepper = StepperKind::Dopri5;
    o.absTol = o.relTol = 1e-14;
    o.initialStep = 1e-3;
    o.maxAffine = maxAffine;
    return o;
}

// Worst deviation from the closed form over the whole ray, at every accepted step.
double worstDeviation(double a, double psi, double phi0, const TraceOptions& o, TraceResult* res = nullptr) {
    const GodelCartesian g(a);
    double worst = 0;
    const TraceResult r = traceGeodesic(g, pastRay(g, psi, phi0), o, [&](const Segment& s) {
        worst = std::max(worst, (s.s1.x - closedFormNull(a, psi, phi0, s.l1)).cwiseAbs().maxCoeff());
        return false;
    });
    if (res) *res = r;
    return worst;
}

TEST(GodelNumeric, ObserverFrameAtOriginIsTheCoordinateFrame) {
    const GodelCartesian g(1.0);
    const LocalFrame f = LocalFrame::staticObserver(g, Vec4::Zero());
    for (int i = 0; i < 4; ++i) EXPECT_NEAR((f.e[i] - Vec4::Unit(i)).norm(), 0, 1e-15);
}

TEST(GodelNumeric, CartesianChartIsTheCylindricalMetric) {
    // Pull the cylindrical metric back through (t, r, phi, z) -> (t, r cos phi, r sin phi, z).
    const double a = 0.7;
    const GodelCylindrical cyl(a);
    const GodelCartesian cart(a);
    for (double r : {0.1, 0.9, 1.4, 2.5}) {
        const double phi = 0.3 + r;
        Mat4 J = Mat4::Identity();  // d(t,X,Y,z)/d(t,r,phi,z)
        J(1, 1) = std::cos(phi);
        J(1, 2) = -r * std::sin(phi);
        J(2, 1) = std::sin(phi);
        J(2, 2) = r * std::cos(phi);
        const Mat4 pulled = J.transpose() * cart.metric(Vec4(0, r * std::cos(phi), r * std::sin(phi), 0.2)) * J;
        EXPECT_LT((pulled - cyl.metric(Vec4(0, r, phi, 0.2))).cwiseAbs().maxCoeff(), 1e-13) << r;
    }
}

TEST(GodelNumeric, ClosedFormOverThreeWindingsAtOneEMinusNine) {
    for (double psi : {0.4, 1.1, kPi / 2, 2.3}) {
        const double w = std::sqrt(1 + std::cos(psi) * std::cos(psi)) / 2;
        TraceResult r;
        EXPECT_LT(worstDeviation(1.0, psi, 0.4, tight(3 * kPi / w), &r), 1e-9) << psi;
        EXPECT_EQ(r.reason, StopReason::MaxAffine);
        EXPECT_LT(r.maxHamiltonianDrift, 1e-10);  // null condition kept
    }
}

TEST(GodelNumeric, PlanarRayTouchesHorizonAndReturnsThroughAxis) {
    // psi = pi/2 is tangent to the Goedel horizon at r = 2a and passes the axis r = 0 each winding.
    const double a = 1.0;
    const GodelCartesian g(a);
    // Half a winding (w l = pi/2) ends on the horizon r = 2a, tangent to it.
    const TraceResult half = traceGeodesic(g, pastRay(g, kPi / 2, 0.0), tight(kPi * a));
    EXPECT_NEAR(half.end.x.segment<2>(1).norm(), 2 * a, 1e-9);
    const Vec4 k = g.inverseMetric(half.end.x) * half.end.p;
    EXPECT_NEAR(half.end.x.segment<2>(1).dot(k.segment<2>(1)), 0, 1e-9);  // no radial motion
    const TraceResult r = traceGeodesic(g, pastRay(g, kPi / 2, 0.0), tight(2 * kPi * a));
    EXPECT_NEAR(r.end.x.segment<2>(1).norm(), 0, 1e-9);          // back on the axis at 2 pi a
    EXPECT_NEAR(r.end.x(0), -2 * kPi * a * (kSqrt2 - 1), 1e-9);  // after 2 pi a (sqrt2 - 1)
}

TEST(GodelNumeric, RayAlongTheAxisStaysOnIt) {
    // psi -> 0: k3 -> 1, r_max -> 0; the ray runs up the axis with t = -lambda.
    for (double psi : {0.0, 1e-8}) {
        TraceResult r;
        EXPECT_LT(worstDeviation(1.0, psi, 0.0, tight(20.0), &r), 1e-9) << psi;
        EXPECT_NEAR(r.end.x(3), 20.0 * std::cos(psi), 1e-9);
    }
}

TEST(GodelNumeric, HundredWindingsStayBoundedAndNull) {
    // Coarser tolerance, long ray: the drift of H and the orbit stay bounded (no blow-up).
    const double a = 1.0, psi = 1.2;
    const double w = std::sqrt(1 + std::cos(psi) * std::cos(psi)) / (2 * a);
    TraceOptions o = tight(100 * kPi / w);
    o.absTol = o.relTol = 1e-13;
    TraceResult r;
    const double dev = worstDeviation(a, psi, 0.0, o, &r);
    EXPECT_EQ(r.reason, StopReason::MaxAffine);
    EXPECT_LT(dev, 1e-6);
    EXPECT_LT(r.maxHamiltonianDrift, 1e-10);
}

TEST(GodelNumeric, EveryStepperReachesTheClosedForm) {
    const double psi = 1.0, w = std::sqrt(1 + std::cos(psi) * std::cos(psi)) / 2;
    for (const auto& name : stepperNames()) {
        TraceOptions o = tight(kPi / w);
        o.stepper = parseStepper(name);
        o.absTol = o.relTol = 1e-10;
        o.initialStep = 1e-2;
        EXPECT_LT(worstDeviation(1.0, psi, 0.0, o), name == "rk4" ? 1e-6 : 1e-6) << name;
    }
}

TEST(Integrator, UnknownStepperNamesTheChoices) {
    try {
        parseStepper("euler");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("dopri5"), std::string::npos);
    }
}

TEST(Integrator, NonFiniteStartIsASingularityNotACrash) {
    const GodelCartesian g(1.0);
    PhasePoint q{Vec4(0, std::nan(""), 0, 0), Vec4(1, 0, 0, 0)};
    EXPECT_EQ(traceGeodesic(g, q, TraceOptions{}).reason, StopReason::Singularity);
}

TEST(Integrator, StepLimitStopsWithReason) {
    const GodelCartesian g(1.0);
    TraceOptions o = tight(1e9);
    o.maxSteps = 10;
    const TraceResult r = traceGeodesic(g, pastRay(g, 1.0, 0.0), o);
    EXPECT_EQ(r.reason, StopReason::MaxSteps);
    EXPECT_EQ(r.steps, 10u);
}

}  // namespace

// A warp bubble seen from outside it: rays towards the bubble cross its wall and leave; the one
// along the line of flight stays on it (symmetry). The far-field step rule once shrank steps to
// nothing as a ray approached the bubble's core, and every such ray ended by step underflow.
TEST(AlcubierreNumeric, RaysFromOutsideCrossTheBubbleAndEscape) {
    const Alcubierre bubble(0.5, 1.0, 8.0);
    TraceOptions opt;
    opt.absTol = opt.relTol = 1e-10;
    opt.escapeRadius = 1e3;
    for (const Vec3& dir : {Vec3(-1, 0, 0), Vec3(-1, 0.1, 0.05), Vec3(-1, -0.2, 0.1)}) {
        const PhasePoint start = staticObserverRay(bubble, Vec4(0, 4, 0, 0), dir, false);
        const TraceResult r = traceGeodesic(bubble, start, opt);
        EXPECT_EQ(stopReasonName(r.reason), "escaped") << dir.transpose();
        if (dir(1) == 0 && dir(2) == 0) {
            const Vec3 p = r.end.p.tail<3>();
            EXPECT_LT(std::hypot(p(1), p(2)), 1e-12 * p.norm());
        }
    }
}
