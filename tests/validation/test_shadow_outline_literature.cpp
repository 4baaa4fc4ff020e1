// SPDX-License-Identifier: BSD-3-Clause
// The shadow's whole outline (lc::traceShadowOutline, lightcone sweep --outline) against the
// analytic finite-distance shadow of Kerr-Newman for Carter's observer (Grenzebach, Perlick &
// Lammerzahl 2014, Phys. Rev. D 89, 124004; Perlick & Tsupko 2022, Phys. Rep. 947, 1): every
// outline point in the observer's own frame, and the solid angle. Shadows larger than a
// hemisphere (observers inside the photon region and falling in) against Synge's radius and its
// aberration (docs/PHYSICS.md sections "Shadow outline" and "Validation against the literature").
#include "core/analysis/shadow.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/scene/frame_camera.hpp"
#include "core/spacetime/named_observer.hpp"
#include "tests/validation/carter_shadow_oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace lc::validation {
namespace {

constexpr double kOutlineDeg = kPiV / 180;

struct CarterCase {
    double a, Q, r, thetaDeg;
};

void checkCarterOutline(const CarterCase& c, int points, double tol, bool solidAngle) {
    Scene s;
    s.spacetime = std::make_shared<KerrNewman>(1, c.a, c.Q);
    const auto& kn = dynamic_cast<const KerrNewman&>(*s.spacetime);
    const KsPlacement at(kn, c.r, c.thetaDeg * kOutlineDeg);
    s.observer = at.event;
    s.camera.forward = -at.basis[1].tail<3>();
    s.camera.up = -at.basis[2].tail<3>();
    s.observerVelocity = namedObserverVelocity(kn, s.observer, NamedObserver::Carter);
    const CarterFrameBL carter(KerrNewmanBL{1, c.a, c.Q}, c.r, c.thetaDeg * kOutlineDeg);
    const std::string what = "a " + std::to_string(c.a) + " Q " + std::to_string(c.Q) + " r " + std::to_string(c.r) +
                             " theta " + std::to_string(c.thetaDeg);
    // The named observer is Carter's (the oracle's e0 carried to the Kerr-Schild chart).
    const Vec4 e0 = at.vector(carter.e[0]);
    ASSERT_LT((s.observerVelocity - e0).norm(), 1e-10 * e0.norm()) << what;

    const ShadowOutline o = traceShadowOutline(s, points, 1e-10);
    const LocalFrame frame = observerFrame(s);
    const Vec3 right = (o.right - o.right.dot(o.inside) * o.inside).normalized();
    const AnalyticOutline want{carter,   at,    kn.metric(s.observer), frame,
                               o.inside, right, right.cross(o.inside), carter.photonRegion()};
    double worst = 0;
    for (std::size_t k = 0; k < o.points.size(); ++k) {
        const double expected = want.radiusAt(o.positionAngles[k]);
        worst = std::max(worst, std::abs(o.radii[k] - expected) / expected);
        EXPECT_NEAR(o.radii[k], expected, tol * expected) << what << " point " << k;
    }
    std::printf("| Carter %-50s | %3d points | worst radius error %.1e |", what.c_str(), points, worst);
    if (solidAngle) {
        const double omega = want.solidAngle();
        std::printf(" solid angle %.10f sr, analytic %.10f, %.1e", o.solidAngle, omega,
                    std::abs(o.solidAngle - omega) / omega);
        EXPECT_NEAR(o.solidAngle, omega, 1e-6 * omega) << what;
    }
    std::printf("\n");
}

// Spins 0.5, 0.9, 0.998 at inclinations 17, 60 and 90 degrees, at 10 M; and at 60 degrees from
// just outside the horizon (a shadow covering all but a small cap of sky) to 10^5 M.
void checkSpin(double a) {
    const double rPlus = 1 + std::sqrt(1 - a * a);
    for (const double th : {17.0, 60.0, 90.0}) checkCarterOutline({a, 0, 10, th}, 16, 1e-7, false);
    for (const double r : {rPlus + 0.05, 3.0, 1e5}) checkCarterOutline({a, 0, r, 60}, 16, 1e-7, false);
}
TEST(CarterObserverShadow, OutlineOnTheAnalyticFiniteDistanceShadowSpinHalf) { checkSpin(0.5); }
TEST(CarterObserverShadow, OutlineOnTheAnalyticFiniteDistanceShadowSpin09) { checkSpin(0.9); }
TEST(CarterObserverShadow, OutlineOnTheAnalyticFiniteDistanceShadowSpin0998) { checkSpin(0.998); }
TEST(CarterObserverShadow, OutlineOnTheAnalyticFiniteDistanceShadowCharged) {
    checkCarterOutline({0.6, 0.7, 6, 45}, 16, 1e-7, false);
}

TEST(CarterObserverShadow, SolidAngleOfTheWholeOutline) {
    checkCarterOutline({0.9, 0, 10, 60}, 32, 1e-7, true);
    checkCarterOutline({0.998, 0, 1.2, 90}, 32, 1e-7, true);  // near the horizon: most of the sky
}

// Synge's radius beyond 90 degrees: inside the photon sphere (r < 3M) the static observer's
// shadow is larger than a hemisphere, sin(alpha) = 3 sqrt(3) M sqrt(1 - 2M/r) / r with alpha > pi/2.
TEST(WholeSkyShadow, StaticObserverInsideThePhotonSphereSeesMoreThanAHemisphere) {
    for (const double r : {2.05, 2.5, 2.95}) {
        Scene s;
        s.spacetime = std::make_shared<KerrNewman>(1, 0, 0);
        s.observer = Vec4(0, r * std::sin(1.1), 0, r * std::cos(1.1));
        s.camera.forward = -s.observer.tail<3>();
        s.camera.up = Vec3(0, 0, 1);
        const ShadowSize m = measureShadow(s);
        const double alpha = kPiV - std::asin(3 * std::sqrt(3.0) * std::sqrt(1 - 2 / r) / r);
        EXPECT_NEAR(m.leftDegrees * kOutlineDeg, alpha, 1e-8 * alpha) << r;
        EXPECT_NEAR(m.rightDegrees * kOutlineDeg, alpha, 1e-8 * alpha) << r;
        EXPECT_NEAR(m.heightDegrees * kOutlineDeg, 2 * alpha, 2e-8 * alpha) << r;
        const ShadowOutline o = traceShadowOutline(s, 16, 1e-10);
        for (const double rho : o.radii) EXPECT_NEAR(rho, alpha, 1e-8 * alpha) << r;
        EXPECT_NEAR(o.solidAngle, 2 * kPiV * (1 - std::cos(alpha)), 1e-7) << r;
        EXPECT_LT((o.centroid - o.forward).norm(), 1e-7) << r;
    }
}

// Falling from rest at infinity (the named free_fall observer) the static shadow is aberrated by
// the infall speed beta = sqrt(2M/r) towards the hole: cos(alpha') = (cos(alpha) + beta) /
// (1 + beta cos(alpha)), also where the static shadow exceeds a hemisphere.
TEST(WholeSkyShadow, FallingObserverSeesTheStaticShadowAberrated) {
    for (const double r : {2.2, 2.8, 4.0, 20.0}) {
        Scene s;
        s.spacetime = std::make_shared<KerrNewman>(1, 0, 0);
        s.observer = Vec4(0, 0, r, 0);
        s.observerVelocity = namedObserverVelocity(*s.spacetime, s.observer, NamedObserver::FreeFall);
        s.camera.forward = Vec3(0, -1, 0);
        s.camera.up = Vec3(0, 0, 1);
        const ShadowSize m = measureShadow(s);
        const double sinStatic = 3 * std::sqrt(3.0) * std::sqrt(1 - 2 / r) / r;
        const double staticAlpha = r < 3 ? kPiV - std::asin(sinStatic) : std::asin(sinStatic);
        const double beta = std::sqrt(2 / r);
        const double alpha = std::acos((std::cos(staticAlpha) + beta) / (1 + beta * std::cos(staticAlpha)));
        EXPECT_NEAR(m.leftDegrees * kOutlineDeg, alpha, 1e-8 * alpha) << r;
        EXPECT_NEAR(m.rightDegrees * kOutlineDeg, alpha, 1e-8 * alpha) << r;
    }
}

// The case: a static observer at r = 4M on the equator of Kerr a = 0.9, looking along -x
// with up along z, against the critical curve seen through the static observer's frame.
TEST(WholeSkyShadow, KerrStaticObserverAtFourM) {
    Scene s;
    s.spacetime = std::make_shared<KerrNewman>(1, 0.9, 0);
    const KsPlacement at(dynamic_cast<const KerrNewman&>(*s.spacetime), 4, kPiV / 2);
    s.observer = at.event;
    s.camera.forward = -at.basis[1].tail<3>();
    s.camera.up = -at.basis[2].tail<3>();
    const ShadowSize m = measureShadow(s);
    const OracleShadow want = oracleShadow(ObserverFrameBL(KerrNewmanBL{1, 0.9, 0}, 4, kPiV / 2));
    std::printf("| a 0.9 static r 4 M: left %.6f right %.6f width %.6f height %.6f deg |\n", m.leftDegrees,
                m.rightDegrees, m.widthDegrees(), m.heightDegrees);
    EXPECT_NEAR(m.rightDegrees * kOutlineDeg, want.right, 1e-7 * want.right);
    EXPECT_NEAR(m.leftDegrees * kOutlineDeg, want.left, 1e-7 * want.left);
    EXPECT_NEAR(m.heightDegrees * kOutlineDeg, want.height, 1e-7 * want.height);
}

TEST(WholeSkyShadow, OutlineRefusesBadArguments) {
    Scene s;
    s.spacetime = std::make_shared<KerrNewman>(1, 0, 0);
    s.observer = Vec4(0, 10, 0, 0);
    s.camera.forward = Vec3(-1, 0, 0);
    EXPECT_THROW(traceShadowOutline(s, 4, 1e-10), std::invalid_argument);
    EXPECT_THROW(traceShadowOutline(s, 360, 0.5), std::invalid_argument);
    s.camera.forward = Vec3(1, 0, 0);  // looking away: the inside point is not dark
    EXPECT_THROW(traceShadowOutline(s, 16, 1e-8), std::invalid_argument);
}

}  // namespace
}  // namespace lc::validation
