// SPDX-License-Identifier: BSD-3-Clause
// The constants of motion the tracer holds (core/spacetime/constants_of_motion, docs/PHYSICS.md
// section 7b): restored by the least change of p, only those the metric's symmetries give, only
// where light can orbit; and the deflection of rays near unstable photon orbits against the exact
// integrals of Schwarzschild and Kerr (tests/common/geodesic_oracles.hpp), held and not held.
#include "core/spacetime/constants_of_motion.hpp"

#include "core/formula/formula_metric.hpp"
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/spacetime/scattering.hpp"
#include "tests/common/geodesic_oracles.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace lc;

namespace {

// The constants written out independently of the class: p_t, the angular momentum x x p of the
// spatial parts (the rotations' p . xi), H.
struct HeldValues {
    double energy;
    Vec3 angularMomentum;
    double hamiltonian;
};
HeldValues heldValuesOf(const Spacetime& st, const PhasePoint& q) {
    return {q.p(0), q.x.tail<3>().cross(q.p.tail<3>()), st.hamiltonian(q.x, q.p)};
}

// A momentum at x with spatial part k and g^ab p_a p_b = 2 H (the larger root for p_t).
PhasePoint momentumWithHamiltonian(const Spacetime& st, const Vec4& x, const Vec3& k, double H) {
    const Mat4 gi = st.inverseMetric(x);
    const double A = gi(0, 0), B = gi.block<1, 3>(0, 1).dot(k), C = k.dot(gi.block<3, 3>(1, 1) * k) - 2 * H;
    PhasePoint q;
    q.x = x;
    q.p << (-B + std::sqrt(B * B - A * C)) / A, k;
    return q;
}

// ConstantsOfMotion::restore with v = g^-1 p at q, as the tracer passes it.
bool restoreWithItsVelocity(const ConstantsOfMotion& constants, const Spacetime& st, PhasePoint& q) {
    return constants.restore(q, st.inverseMetric(q.x) * q.p);
}

const Vec4 kNudge = 1e-7 * Vec4(0.3, -0.7, 0.2, 0.5);

// A metric typed as text with a far field of unit mass (what declares circular orbits).
formula::FormulaMetric typedWithFarField(const std::string& ds2, std::vector<std::string> definitions) {
    formula::FormulaMetricSource s;
    s.lineElement = formula::FormulaText{"ds2", ds2};
    for (std::size_t i = 0; i < definitions.size(); ++i)
        s.definitions.push_back({"define[" + std::to_string(i) + "]", definitions[i]});
    s.asymptoticallyFlat = true;
    s.farMass = formula::FormulaText{"far_field.mass", "1"};
    return formula::FormulaMetric(s, {});
}

// The deflection error of a ray of impact parameter b (b > 0 turns against a Kerr hole's spin)
// from and back to 10^6 M, against the exact integral with angular momentum L.
double deflectionError(const KerrNewman& hole, double b, double L, StepperKind stepper, double tolerance, bool hold) {
    TraceOptions o;
    o.stepper = stepper;
    o.absTol = o.relTol = tolerance;
    o.initialStep = 1;
    o.escapeRadius = 1e6;
    o.escapeAngle = 4;  // the turning measured along the whole ray
    o.holdConstants = hold;
    const DeflectionResult d = measureDeflection(hole, impactParameterRay(hole, b, 1e6), o);
    EXPECT_EQ(d.trace.reason, StopReason::Escaped);
    return std::abs(d.deflection - test::kerrEquatorialDeflection(hole.spin(), L).alpha);
}

}  // namespace

// Schwarzschild: d/dt and every rotation give four independent conditions on p at a point (three
// rotations give two), with H a fifth: p is restored to the true one, the change no larger than
// the nudge that moved it.
TEST(ConstantsOfMotion, SchwarzschildRestoresEnergyAngularMomentumAndTheNullCondition) {
    const Schwarzschild bh(1.0);
    const PhasePoint q = momentumWithHamiltonian(bh, Vec4(3, 3.5, 1.0, 0.5), Vec3(0.2, -0.9, 0.3), 0);
    const ConstantsOfMotion constants(bh, q);
    EXPECT_EQ(constants.count(), 5);
    PhasePoint nudged = q;
    nudged.p += kNudge;
    ASSERT_TRUE(restoreWithItsVelocity(constants, bh, nudged));
    EXPECT_EQ(nudged.x, q.x);
    const HeldValues want = heldValuesOf(bh, q), got = heldValuesOf(bh, nudged);
    EXPECT_NEAR(got.energy, want.energy, 1e-15);
    EXPECT_LT((got.angularMomentum - want.angularMomentum).norm(), 1e-14);
    EXPECT_NEAR(got.hamiltonian, want.hamiltonian, 1e-13);
    EXPECT_LT((nudged.p - q.p).norm(), 1e-13);
}

// Kerr keeps d/dt and rotations about its spin axis, and Carter's constant: p_t, L_z, Carter's Q
// and H, four independent conditions, restore the true p; L_x and L_y are not constants.
TEST(ConstantsOfMotion, KerrRestoresEnergyAxialAngularMomentumCarterAndH) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    const PhasePoint q = momentumWithHamiltonian(kerr, Vec4(0, 2.5, -2.0, 1.5), Vec3(-0.4, 0.6, -0.5), 0);
    const ConstantsOfMotion constants(kerr, q);
    EXPECT_EQ(constants.count(), 4);
    PhasePoint nudged = q;
    nudged.p += kNudge;
    ASSERT_TRUE(restoreWithItsVelocity(constants, kerr, nudged));
    const HeldValues want = heldValuesOf(kerr, q), got = heldValuesOf(kerr, nudged);
    EXPECT_NEAR(got.energy, want.energy, 1e-15);
    EXPECT_NEAR(got.angularMomentum.z(), want.angularMomentum.z(), 1e-14);
    EXPECT_NEAR(got.hamiltonian, want.hamiltonian, 1e-13);
    EXPECT_LT((nudged.p - q.p).norm(), 1e-13);
}

// Carter's constant as written in the Kerr-Schild chart (ConstantsOfMotion::carterConstant) against
// the geodesic equations themselves: constant along Kerr-Newman rays traced at 1e-13 without
// holding anything, above and below the equator, while it differs by order one between them.
TEST(ConstantsOfMotion, CarterConstantIsConstantAlongRaysTracedWithoutHolding) {
    const KerrNewman hole(1.0, 0.8, 0.3);
    TraceOptions o;
    o.stepper = StepperKind::Dopri87;
    o.absTol = o.relTol = 1e-13;
    o.holdConstants = false;
    o.maxAffine = 40;
    std::vector<double> values;
    for (const auto& [x, k] :
         {std::pair{Vec4(0, 6, 0, 2), Vec3(0.05, -0.35, 0.1)}, std::pair{Vec4(0, -2, 5, -3), Vec3(0.3, 0.1, -0.2)}}) {
        const PhasePoint start = momentumWithHamiltonian(hole, x, k, 0);
        const double Q0 = *ConstantsOfMotion::carterConstant(0.8, 0, start);
        values.push_back(Q0);
        int compared = 0;
        for (const auto& [l, q] : sampleGeodesic(hole, start, o))
            if (const auto Q = ConstantsOfMotion::carterConstant(0.8, 0, q)) {
                EXPECT_NEAR(*Q, Q0, 1e-12 * (1 + std::abs(Q0))) << "l = " << l;
                ++compared;
            }
        EXPECT_GT(compared, 20);
    }
    EXPECT_GT(std::abs(values[0] - values[1]), 0.1);
}

// A body's world line: H is held at its own starting value (1/2 for unit mass), not at 0.
TEST(ConstantsOfMotion, ATimelikeGeodesicKeepsItsMass) {
    const KerrNewman kerr(1.0, 0.6, 0.3);
    const PhasePoint q = momentumWithHamiltonian(kerr, Vec4(0, 4, 0.5, -1), Vec3(0.1, 0.3, 0), 0.5);
    const ConstantsOfMotion constants(kerr, q);
    PhasePoint nudged = q;
    nudged.p += kNudge;
    ASSERT_TRUE(restoreWithItsVelocity(constants, kerr, nudged));
    EXPECT_NEAR(kerr.hamiltonian(nudged.x, nudged.p), 0.5, 1e-13);
}

// No symmetry declared (Goedel's universe, whose Killing fields the closed forms use but the metric
// does not declare): H alone, restored along its gradient v = g^-1 p, everywhere (not
// asymptotically flat). A warp drive, flat beyond its wall, has no orbit region: nothing held.
TEST(ConstantsOfMotion, WithoutDeclaredSymmetriesOnlyHIsHeldAlongItsGradient) {
    const GodelCartesian godel(1);
    const PhasePoint q = momentumWithHamiltonian(godel, Vec4(0, 0.9, 0.2, 0.1), Vec3(0.5, 0.2, -0.1), 0);
    const ConstantsOfMotion constants(godel, q);
    EXPECT_EQ(constants.count(), 1);
    PhasePoint nudged = q;
    nudged.p += kNudge;
    const PhasePoint before = nudged;
    ASSERT_TRUE(restoreWithItsVelocity(constants, godel, nudged));
    EXPECT_NEAR(godel.hamiltonian(nudged.x, nudged.p), 0, 1e-13);
    const Vec4 v = godel.inverseMetric(before.x) * before.p, change = nudged.p - before.p;
    EXPECT_LT((change - change.dot(v) / v.squaredNorm() * v).norm(), 1e-6 * change.norm());

    const Alcubierre warp(1.5, 1, 8);
    PhasePoint inBubble = momentumWithHamiltonian(warp, Vec4(0, 0.9, 0.2, 0), Vec3(0.5, 0.2, -0.1), 0);
    inBubble.p += kNudge;
    EXPECT_FALSE(restoreWithItsVelocity(ConstantsOfMotion(warp, inBubble), warp, inBubble));
}

// Only where light can orbit (1.5 capture radii): farther out nothing amplifies a drift.
TEST(ConstantsOfMotion, FarFromTheHoleNothingIsChanged) {
    const Schwarzschild bh(1.0);
    const PhasePoint q = momentumWithHamiltonian(bh, Vec4(0, 30, 20, 5), Vec3(0.2, -0.9, 0.3), 0);
    const ConstantsOfMotion constants(bh, q);
    PhasePoint nudged = q;
    nudged.p += kNudge;
    const PhasePoint before = nudged;
    EXPECT_FALSE(restoreWithItsVelocity(constants, bh, nudged));
    EXPECT_EQ(nudged.p, before.p);
}

// On the spin axis the rotation's field vanishes: its condition is dropped, not divided by zero.
TEST(ConstantsOfMotion, OnTheAxisTheRotationDropsOut) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    const PhasePoint q = momentumWithHamiltonian(kerr, Vec4(0, 0, 0, 3), Vec3(0.3, 0, -0.9), 0);
    const ConstantsOfMotion constants(kerr, q);
    PhasePoint nudged = q;
    nudged.p += kNudge;
    ASSERT_TRUE(restoreWithItsVelocity(constants, kerr, nudged));
    EXPECT_TRUE(nudged.p.allFinite());
    EXPECT_NEAR(kerr.hamiltonian(nudged.x, nudged.p), 0, 1e-13);
    EXPECT_NEAR(nudged.p(0), q.p(0), 1e-15);
}

// A metric typed as text declares what its formula is, checked at sample events: round
// (Schwarzschild's potential) is spherical, Kerr's Kerr-Schild form only axisymmetric.
TEST(ConstantsOfMotion, TypedMetricsDeclareTheSymmetriesTheirFormulaHas) {
    const formula::FormulaMetric round =
        typedWithFarField("-(1 - 2/sqrt(x^2+y^2+z^2+1))*dt^2 + dx^2 + dy^2 + dz^2", {});
    EXPECT_TRUE(round.symmetries().stationary);
    EXPECT_TRUE(round.symmetries().spherical);
    const formula::FormulaMetric kerr = typedWithFarField(
        "-dt^2 + dx^2 + dy^2 + dz^2 + f*(dt - ((r*x - a*y)*dx + (r*y + a*x)*dy)/(r^2 + a^2) - z*dz/r)^2",
        {"a = 0.9", "rho2 = x^2 + y^2 + z^2 - a^2", "r = sqrt(0.5*(rho2 + sqrt(rho2^2 + 4*a^2*z^2)))",
         "f = 2*r^3/(r^4 + a^2*z^2)"});
    EXPECT_TRUE(kerr.symmetries().axisymmetric);
    EXPECT_FALSE(kerr.symmetries().spherical);
    EXPECT_FALSE(Alcubierre(1.5, 1, 8).symmetries().stationary);
}

// The point of holding them: a ray near an unstable photon orbit ends on a neighbouring orbit
// when L or H drift, its deflection off by the drift times e^(pi windings). Schwarzschild's
// grazer b = 3 sqrt 3 (1 + 1e-3) (alpha = 6.51, more than a winding) and Kerr a = 0.998's prograde
// photon turning at r = 1.2 (alpha = 19.6, three windings), against their exact integrals; rays
// that stay beyond 1.5 capture radii (b = 10, 20) are traced bit for bit as without.
TEST(ConstantsOfMotion, RaysNearUnstablePhotonOrbitsKeepTheirDeflection) {
    const KerrNewman schwarzschild(1.0, 0.0, 0.0);
    const double grazer = 3 * std::sqrt(3.0) * (1 + 1e-3);
    for (auto [stepper, tolerance, bound] :
         {std::tuple{StepperKind::Dopri5, 1e-8, 5e-7}, std::tuple{StepperKind::Dopri87, 1e-7, 5e-8}}) {
        const double held = deflectionError(schwarzschild, grazer, grazer, stepper, tolerance, true);
        const double free = deflectionError(schwarzschild, grazer, grazer, stepper, tolerance, false);
        EXPECT_LT(held, bound) << stepperName(stepper);
        EXPECT_LT(20 * held, free) << stepperName(stepper);
        for (double b : {10.0, 20.0})
            EXPECT_EQ(deflectionError(schwarzschild, b, b, stepper, tolerance, true),
                      deflectionError(schwarzschild, b, b, stepper, tolerance, false));
    }
    const KerrNewman kerr(1.0, 0.998, 0.0);
    const double L = test::kerrEquatorialAngularMomentum(0.998, 1.2, +1);
    const double held = deflectionError(kerr, -L, L, StepperKind::Dopri5, 1e-9, true);
    const double free = deflectionError(kerr, -L, L, StepperKind::Dopri5, 1e-9, false);
    EXPECT_LT(5 * held, free);
}

// Off the equator, where Carter's constant matters: Kerr a = 0.9, a ray from 10^3 M offset by 2 M
// beside the spin axis' plane and aimed 10^-3 (relative) outside the shadow's edge above it, so it
// passes over the pole near the spherical photon orbits. Its final direction against the same ray
// traced at 1e-13 with dopri87 and nothing held (the independent reference).
TEST(ConstantsOfMotion, KerrRaysOverThePoleNearThePhotonOrbitsKeepTheirDirection) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    constexpr double kD = 1e3;
    auto ray = [&kerr](double angle) {
        return momentumWithHamiltonian(kerr, Vec4(0, 2, -kD, 0), -Vec3(0, std::cos(angle), std::sin(angle)), 0);
    };
    auto options = [](StepperKind stepper, double tolerance, bool hold) {
        TraceOptions o;
        o.stepper = stepper;
        o.absTol = o.relTol = tolerance;
        o.initialStep = 1;
        o.escapeRadius = kD;
        o.escapeAngle = 4;
        o.holdConstants = hold;
        return o;
    };
    const TraceOptions reference = options(StepperKind::Dopri87, 1e-13, false);
    double captured = 0, escapes = 10 / kD;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (captured + escapes);
        (traceGeodesic(kerr, ray(mid), reference).reason == StopReason::Horizon ? captured : escapes) = mid;
    }
    const PhasePoint start = ray(escapes * (1 + 1e-3));
    auto direction = [&](const TraceOptions& o) {
        const TraceResult r = traceGeodesic(kerr, start, o);
        EXPECT_EQ(r.reason, StopReason::Escaped);
        return Vec3((kerr.inverseMetric(r.end.x) * r.end.p).tail<3>().normalized());
    };
    const Vec3 exact = direction(reference);
    auto error = [&](const TraceOptions& o) { return std::acos(std::min(1.0, direction(o).dot(exact))); };
    const double held = error(options(StepperKind::Dopri5, 1e-8, true));
    const double free = error(options(StepperKind::Dopri5, 1e-8, false));
    EXPECT_GT(std::acos(exact.y()), 2.5);  // turned back over the pole
    EXPECT_LT(held, 5e-6);
    EXPECT_LT(10 * held, free);
}
