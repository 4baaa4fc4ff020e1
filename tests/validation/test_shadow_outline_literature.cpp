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
#include "tests/validation/ks_placement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace lc::validation {
namespace {

constexpr double kOutlineDeg = kPiV / 180;

// Carter's frame in Boyer-Lindquist components (GPL 2014, eq. 13 with Lambda = 0):
// e0 = ((r^2 + a^2) d_t + a d_phi) / sqrt(rho^2 Delta), e1 = sqrt(Delta / rho^2) d_r,
// e2 = d_theta / rho, e3 = (d_phi + a sin^2 theta d_t) / (rho sin theta).
struct CarterFrameBL {
    KerrNewmanBL bh;
    double rO, thetaO;
    M4 g;
    std::array<V4, 4> e;
    CarterFrameBL(KerrNewmanBL b, double r, double th) : bh(b), rO(r), thetaO(th), g(b.metric(r, th)) {
        const double a = b.a, s = std::sin(th), rho = std::sqrt(r * r + a * a * std::cos(th) * std::cos(th));
        const double d = b.delta(r);
        e[0] = V4(r * r + a * a, 0, 0, a) / (rho * std::sqrt(d));
        e[1] = V4(0, std::sqrt(d) / rho, 0, 0);
        e[2] = V4(0, 0, 1 / rho, 0);
        e[3] = V4(a * s * s, 0, 0, 1) / (rho * s);
    }
    // The past-directed tangent (BL components) of the ray on the shadow's edge that comes from
    // the spherical photon orbit rp, with p_theta of sign `side`: covariant momentum
    // (E, p_r, p_theta, p_phi) = (-1, +-sqrt(R(rO)) / Delta(rO), side sqrt(Theta(thetaO)), xi), with
    // Bardeen's beta^2 = Theta = eta + a^2 cos^2 - xi^2 cot^2. It runs inwards (p_r > 0) when the
    // orbit lies inside the observer, outwards when outside.
    V4 edgeTangent(double rp, int side) const {
        double xi, eta;
        bh.critical(rp, xi, eta);
        const double c = std::cos(thetaO), s = std::sin(thetaO);
        const double theta2 = std::max(0.0, eta + bh.a * bh.a * c * c - xi * xi * c * c / (s * s));
        const double R = std::max(0.0, bh.radial(rO, xi, eta));
        const V4 p(-1, (rO > rp ? 1 : -1) * std::sqrt(R) / bh.delta(rO), side * std::sqrt(theta2), xi);
        return g.inverse() * p;
    }
    // The photon orbits seen from thetaO: beta^2 >= 0 between these radii.
    std::array<double, 2> photonRegion() const {
        const double c = std::cos(thetaO), s = std::sin(thetaO);
        auto beta2 = [&](double rp) {
            double xi, eta;
            bh.critical(rp, xi, eta);
            return eta + bh.a * bh.a * c * c - xi * xi * c * c / (s * s);
        };
        const double r0 = bh.horizon() * (1 + 1e-9), r1 = 4.5 * bh.M;
        std::array<double, 2> out{};
        int found = 0;
        const int samples = 20000;
        for (int k = 0; k < samples && found < 2; ++k) {
            double lo = r0 + (r1 - r0) * k / samples, hi = r0 + (r1 - r0) * (k + 1) / samples;
            if ((beta2(lo) > 0) == (beta2(hi) > 0)) continue;
            const bool loPositive = beta2(lo) > 0;
            for (int it = 0; it < 200; ++it) ((beta2(0.5 * (lo + hi)) > 0) == loPositive ? lo : hi) = 0.5 * (lo + hi);
            out[found++] = 0.5 * (lo + hi);
        }
        if (found != 2) throw std::runtime_error("oracle: no photon region seen from thetaO");
        return out;
    }
};

// The analytic outline seen in the code's frame: angles about the outline's inside point c, from
// the inside point's right (the camera's right made orthogonal to c) towards its up.
struct AnalyticOutline {
    const CarterFrameBL& carter;
    const KsPlacement& at;
    const Mat4 g;
    const LocalFrame& frame;
    Vec3 c, right, up;
    std::array<double, 2> region;

    Vec3 direction(double rp, int side) const {
        const Vec4 k = at.vector(carter.edgeTangent(rp, side));
        const double k0 = k.dot(g * frame.e[0]);
        return Vec3(k.dot(g * frame.e[1]), k.dot(g * frame.e[2]), k.dot(g * frame.e[3])) / k0;
    }
    double psi(const Vec3& d) const { return std::atan2(d.dot(up), d.dot(right)); }
    double rho(const Vec3& d) const { return std::atan2(d.cross(c).norm(), d.dot(c)); }
    double rpAt(double t) const { return region[0] + (region[1] - region[0]) * (0.5 - 0.5 * std::cos(kPiV * t)); }

    // The closed curve as u in [0, 2): the p_theta > 0 half out, the p_theta < 0 half back.
    Vec3 onLoop(double u) const {
        u = u - 2 * std::floor(u / 2);
        return u < 1 ? direction(rpAt(u), 1) : direction(rpAt(2 - u), -1);
    }
    // The analytic edge's angle from c at position angle psiK: a root in u of the wrapped angle
    // difference.
    double radiusAt(double psiK) const {
        auto diff = [&](double u) { return std::remainder(psi(onLoop(u)) - psiK, 2 * kPiV); };
        const int samples = 4000;
        for (int k = 0; k < samples; ++k) {
            double lo = 2.0 * k / samples, hi = 2.0 * (k + 1) / samples;
            const double dlo = diff(lo), dhi = diff(hi);
            if (!((dlo <= 0) != (dhi <= 0)) || std::abs(dlo - dhi) > 1) continue;
            for (int it = 0; it < 100; ++it) {
                const double mid = 0.5 * (lo + hi);
                ((diff(mid) <= 0) == (dlo <= 0) ? lo : hi) = mid;
            }
            return rho(onLoop(0.5 * (lo + hi)));
        }
        throw std::runtime_error("oracle: no analytic edge point at this position angle");
    }
    // The solid angle inside the closed analytic curve: sum of (1 - cos rho) dpsi over a dense
    // polygon (both halves, the photon region swept out and back).
    double solidAngle() const {
        const int samples = 40000;
        std::vector<Vec3> loop;
        for (int k = 0; k <= samples; ++k) loop.push_back(direction(rpAt(double(k) / samples), 1));
        for (int k = samples; k >= 0; --k) loop.push_back(direction(rpAt(double(k) / samples), -1));
        double omega = 0;
        for (std::size_t k = 0; k + 1 < loop.size(); ++k) {
            const double dpsi = std::remainder(psi(loop[k + 1]) - psi(loop[k]), 2 * kPiV);
            omega += (1 - std::cos(0.5 * (rho(loop[k]) + rho(loop[k + 1])))) * dpsi;
        }
        return std::abs(omega);
    }
};

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
