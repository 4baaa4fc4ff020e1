// SPDX-License-Identifier: BSD-3-Clause
// Generic Hamiltonian tracer against exact Schwarzschild and Kerr values (docs/PHYSICS.md section 7,
// computed independently with mpmath).
#include "core/spacetime/frame.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"
#include "core/spacetime/scattering.hpp"

#include <gtest/gtest.h>

using namespace lc;

namespace {

TraceOptions tight(StepperKind s = StepperKind::Dopri5) {
    TraceOptions o;
    o.stepper = s;
    o.absTol = 1e-14;
    o.relTol = 1e-13;
    o.initialStep = 1.0;
    o.escapeRadius = 1e6;
    o.maxAffine = 1e8;
    return o;
}

struct DeflectionCase {
    double b, alpha;
};

class SchwarzschildDeflection : public ::testing::TestWithParam<DeflectionCase> {};

TEST_P(SchwarzschildDeflection, MatchesExactIntegralAtTightTolerance) {
    const Schwarzschild bh(1.0);
    const auto c = GetParam();
    const PhasePoint start = impactParameterRay(bh, c.b, 1e6);
    const DeflectionResult d = measureDeflection(bh, start, tight());
    EXPECT_EQ(d.trace.reason, StopReason::Escaped);
    EXPECT_NEAR(d.impact, c.b, 1e-12 * c.b);
    EXPECT_NEAR(d.deflection, c.alpha, 1e-8);
    EXPECT_LT(d.trace.maxHamiltonianDrift, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(Exact, SchwarzschildDeflection,
                         ::testing::Values(DeflectionCase{20, 0.2361359953884699},
                                           DeflectionCase{10, 0.5903957876058273},
                                           DeflectionCase{6, 1.719388310230169}));

TEST(Schwarzschild, EveryStepperAgreesAtItsTolerance) {
    const Schwarzschild bh(1.0);
    const PhasePoint start = impactParameterRay(bh, 10, 1e6);
    for (StepperKind s :
         {StepperKind::CashKarp54, StepperKind::Dopri5, StepperKind::Dopri87, StepperKind::BulirschStoer}) {
        TraceOptions o = tight(s);
        o.absTol = o.relTol = 1e-11;
        const DeflectionResult d = measureDeflection(bh, start, o);
        EXPECT_EQ(d.trace.reason, StopReason::Escaped) << stepperName(s);
        EXPECT_NEAR(d.deflection, 0.5903957876058273, 1e-6) << stepperName(s);
    }
}

TEST(Schwarzschild, ClosestApproachMatchesExact) {
    const Schwarzschild bh(1.0);
    double rmin = 1e9;
    TraceOptions o = tight();
    traceGeodesic(bh, impactParameterRay(bh, 10, 1e6), o, [&](const Segment& s) {
        // Refine inside the step with the dense output.
        for (int k = 0; k <= 64; ++k) {
            const Vec4 x = s.at(s.l0 + (s.l1 - s.l0) * k / 64.0).x;
            rmin = std::min(rmin, x.tail<3>().norm());
        }
        return false;
    });
    EXPECT_NEAR(rmin, 8.788850662499728, 1e-6);
}

TEST(Schwarzschild, CircularPhotonOrbitStaysAtRadiusThree) {
    const Schwarzschild bh(1.0);
    // Tangential null ray at r = 3M: b = 3 sqrt(3) exactly, unstable circular orbit.
    const Vec4 x(0, 3, 0, 0);
    const LocalFrame f = LocalFrame::staticObserver(bh, x);
    PhasePoint q{x, -f.pastNullMomentum(bh, Vec3(0, 1, 0))};  // future-directed
    TraceOptions o = tight();
    o.maxAffine = 40;  // about two orbits before the instability grows beyond 1e-6
    double worst = 0;
    traceGeodesic(bh, q, o, [&](const Segment& s) {
        worst = std::max(worst, std::abs(s.s1.x.tail<3>().norm() - 3.0));
        return false;
    });
    EXPECT_LT(worst, 1e-6);
    const double L = x(1) * q.p(2) - x(2) * q.p(1);
    EXPECT_NEAR(std::abs(L / q.p(0)), 5.196152422706632, 1e-9);
}

TEST(Schwarzschild, PhotonSphereGrazerWindsAndEscapes) {
    const Schwarzschild bh(1.0);
    const double bc = 5.196152422706632;
    const DeflectionResult d = measureDeflection(bh, impactParameterRay(bh, bc + 1e-6, 1e6), tight());
    EXPECT_EQ(d.trace.reason, StopReason::Escaped);
    // Strong-field limit: alpha ~ -log(b - bc) + const; at 1e-6 above it winds more than once.
    EXPECT_GT(d.deflection, 2 * kPi);
    EXPECT_LT(d.trace.maxHamiltonianDrift, 1e-8);
    const DeflectionResult inside = measureDeflection(bh, impactParameterRay(bh, bc - 1e-6, 1e6), tight());
    EXPECT_EQ(inside.trace.reason, StopReason::Horizon);
}

// The far-field rule (TraceOptions::stepPerDistance): long steps where nothing happens, none
// that jumps over the hole. Without it a loose tolerance lets one step from 1e10 M carry the ray
// past the hole undeflected (its error estimate, sampled far away, stays small); with it every
// stepper keeps the deflection to its tolerance from any distance, and the cost grows only
// logarithmically: from 1e10 M a ray costs little more than from 1e3 M.
TEST(Schwarzschild, FarFieldStepsNeitherJumpTheHoleNorGrowWithDistance) {
    const Schwarzschild bh(1.0);
    for (StepperKind s : {StepperKind::Dopri5, StepperKind::Dopri87, StepperKind::CashKarp54})
        for (double tol : {1e-4, 1e-6})
            for (double b : {6.0, 10.0}) {
                TraceOptions o;
                o.stepper = s;
                o.absTol = o.relTol = tol;
                o.escapeRadius = 1e10;
                const DeflectionResult d = measureDeflection(bh, impactParameterRay(bh, b, 1e10), o);
                const double exact = b == 6 ? 1.719388310230169 : 0.5903957876058273;
                EXPECT_EQ(d.trace.reason, StopReason::Escaped);
                EXPECT_NEAR(d.deflection, exact, 300 * tol) << stepperName(s) << " tol " << tol << " b " << b;
            }
    auto steps = [&](double distance) {
        TraceOptions o;
        o.absTol = o.relTol = 1e-8;
        o.escapeRadius = distance;
        const DeflectionResult d = measureDeflection(bh, impactParameterRay(bh, 10, distance), o);
        EXPECT_NEAR(d.deflection, 0.5903957876058273, 1e-6 + 4 * 10 / (distance * distance));
        return static_cast<double>(d.trace.steps + d.trace.rejected);
    };
    const double near = steps(1e3), mid = steps(1e6), far = steps(1e10);
    // Logarithmic: each decade of distance adds the same few tries, accepted and rejected (about
    // 20 at 1e-8 in and out again, half of them rejected where the chord rule lets the step grow
    // past what the tolerance allows; 0.1 r steps took 2 x 24 accepted ones per decade).
    EXPECT_LT(far, 2 * near) << near << " " << mid << " " << far;
    EXPECT_LT(far - mid, 4 * 25.0) << near << " " << mid << " " << far;
    EXPECT_LT(mid - near, 3 * 25.0) << near << " " << mid << " " << far;
}

// An escaped ray's direction is settled to TraceOptions::escapeAngle: traced on to 1e9 M its
// direction turns by less than that.
TEST(Schwarzschild, EscapeDirectionIsSettledToTheEscapeAngle) {
    const Schwarzschild bh(1.0);
    for (double angle : {1e-4, 1e-7}) {
        TraceOptions o = tight();
        o.escapeRadius = 0;
        o.escapeAngle = angle;
        const DeflectionResult early = measureDeflection(bh, impactParameterRay(bh, 6, 1e3), o);
        ASSERT_EQ(early.trace.reason, StopReason::Escaped);
        // It stops where the bound 4 M b / r^2 first falls below the angle, not far beyond.
        const double stopRadius = early.trace.end.x.tail<3>().norm(), bound = std::sqrt(4 * 6 / angle);
        EXPECT_GT(stopRadius, 0.99 * bound) << "angle " << angle;
        EXPECT_LT(stopRadius, 2 * bound) << "angle " << angle;
        o.escapeRadius = 1e9;
        const DeflectionResult late = measureDeflection(bh, impactParameterRay(bh, 6, 1e3), o);
        EXPECT_LT(std::abs(late.deflection - early.deflection), angle) << "angle " << angle;
    }
}

TEST(Minkowski, StraightLineHasNoDeflectionAndNoDrift) {
    const Minkowski flat;
    const DeflectionResult d = measureDeflection(flat, impactParameterRay(flat, 3, 1e3), tight());
    EXPECT_EQ(d.trace.reason, StopReason::Escaped);
    EXPECT_NEAR(d.deflection, 0, 1e-14);
    EXPECT_EQ(d.trace.maxHamiltonianDrift, 0);
}

// Kerr a = 0.9: equatorial circular photon orbits at the exact Bardeen radii. At the
// equatorial point x = sqrt(R^2 + a^2), y = z = 0 the Boyer-Lindquist radius is R and
// dr/dl = (x/r) dx/dl, so a ray with p_t = 1, p_z = 0, g^{x nu} p_nu = 0 and H = 0 starts
// tangentially; only the exact orbit radius keeps it there.
double orbitDeviation(const KerrNewman& bh, double R, int root) {
    const double a = bh.spin();
    const Vec4 x(0, std::sqrt(R * R + a * a), 0, 0);
    const Mat4 gi = bh.inverseMetric(x);
    auto momentum = [&](double py) {
        const double px = -(gi(1, 0) + gi(1, 2) * py) / gi(1, 1);
        return Vec4(1, px, py, 0);
    };
    // H(p_y) is exactly quadratic: three samples give its coefficients.
    const double h0 = bh.hamiltonian(x, momentum(0)), hp = bh.hamiltonian(x, momentum(1)),
                 hm = bh.hamiltonian(x, momentum(-1));
    const double A = 0.5 * (hp + hm) - h0, B = 0.5 * (hp - hm), C = h0;
    const double py = (-B + (root > 0 ? 1 : -1) * std::sqrt(B * B - 4 * A * C)) / (2 * A);
    PhasePoint q{x, momentum(py)};
    TraceOptions o = tight();
    o.maxAffine = 6 * R;
    double worst = 0;
    traceGeodesic(bh, q, o, [&](const Segment& s) {
        const Vec4& y = s.s1.x;
        worst = std::max(worst, std::abs(bh.radius(y(1), y(2), y(3)) - R));
        return false;
    });
    return worst;
}

TEST(Kerr, EquatorialPhotonOrbitsAtBardeenRadii) {
    const KerrNewman bh(1.0, 0.9, 0.0);
    const double prograde = 1.557854627423380, retrograde = 3.910267939103040;
    // Which sign of the tangential direction is prograde depends on the chart's spin sense;
    // the exact radius must be circular for one sense and not the other.
    const double p1 = orbitDeviation(bh, prograde, +1), p2 = orbitDeviation(bh, prograde, -1);
    const double r1 = orbitDeviation(bh, retrograde, +1), r2 = orbitDeviation(bh, retrograde, -1);
    EXPECT_LT(std::min(p1, p2), 1e-6);
    EXPECT_LT(std::min(r1, r2), 1e-6);
    EXPECT_GT(std::max(p1, p2), 1e-2);
    EXPECT_GT(std::max(r1, r2), 1e-2);
    EXPECT_EQ(p1 < p2, r2 < r1);  // opposite senses
}

TEST(Kerr, RayIntoHorizonStopsCleanly) {
    const KerrNewman bh(1.0, 0.9, 0.0);
    // Past-directed camera ray aimed straight at the hole from r = 20.
    const Vec4 x(0, 20, 0, 0.5);
    const LocalFrame f = LocalFrame::staticObserver(bh, x);
    PhasePoint q{x, f.pastNullMomentum(bh, Vec3(-1, 0, 0))};
    for (StepperKind s : {StepperKind::RK4, StepperKind::CashKarp54, StepperKind::Dopri5, StepperKind::Dopri87,
                          StepperKind::BulirschStoer}) {
        TraceOptions o;
        o.stepper = s;
        o.initialStep = 0.01;
        o.absTol = o.relTol = 1e-10;
        const TraceResult r = traceGeodesic(bh, q, o);
        EXPECT_EQ(r.reason, StopReason::Horizon) << stepperName(s);
        for (int i = 0; i < 4; ++i) {
            EXPECT_TRUE(std::isfinite(r.end.x(i)));
            EXPECT_TRUE(std::isfinite(r.end.p(i)));
        }
        EXPECT_LT(bh.radius(r.end.x(1), r.end.x(2), r.end.x(3)), bh.outerHorizon() * 1.01);
    }
}

TEST(Kerr, RejectsNakedSingularity) { EXPECT_THROW(KerrNewman(1.0, 0.9, 0.5), std::invalid_argument); }

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
