// SPDX-License-Identifier: BSD-3-Clause
// Each pixel's magnification, shear and rotation from the ray bundle the numeric renderer carries
// (core/curvature/ray_bundle, RenderSettings::magnification), against independent oracles:
// - flat space: no lensing at all, for a ball and for the sky;
// - the Schwarzschild point lens in the weak field (Schneider, Ehlers & Falco 1992, eqs. 2.24-2.25;
//   Paczynski 1986): an image at angle theta from the lens has mu = 1/(1 - (theta_E/theta)^4) and
//   shear (theta_E/theta)^2, both images (theta > theta_E and the mirrored theta < theta_E), so a
//   point source's two images add up to |mu+| + |mu-| = (u^2 + 2)/(u sqrt(u^2 + 4)); for the sky
//   (a source at infinity, theta_E^2 = 4M/D_d) and for a ball behind the lens (theta_E^2 = 4M
//   D_ds/(D_d D_s), the ball's hit at D_s), seen from off the lens's axis;
// - Kerr's strong field from an inclined observer: the map's determinant, shear and rotation from
//   central differences of the escape directions of rays traced at a tight tolerance (no bundle).
#include "tests/common/test_camera.hpp"
#include "core/curvature/ray_bundle.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"
#include "core/render/render.hpp"
#include "core/render/special_relativity.hpp"
#include "core/scene/frame_camera.hpp"
#include "core/scene/scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace {
using namespace lc;

Scene lensingScene(SpacetimePtr st, const Vec4& observer, const Camera& camera) {
    Scene s;
    s.spacetime = std::move(st);
    s.observer = observer;
    s.camera = camera;
    s.settings.method = RenderSettings::Method::Numeric;
    s.settings.magnification = true;
    s.settings.threads = 2;
    s.settings.trace.absTol = s.settings.trace.relTol = 1e-10;
    return s;
}

SphereObject ballAt(const Vec3& centre, double radius) {
    SphereObject ball;
    ball.name = "source";
    ball.centre = Vec4(0, centre(0), centre(1), centre(2));
    ball.radius = radius;
    ball.placement = std::make_shared<TranslationPlacement>(centre);
    return ball;
}

TEST(RenderLensing, FlatSpaceLeavesEveryImageElementUnlensed) {
    Scene s =
        lensingScene(std::make_shared<Minkowski>(), Vec4(0, -5, 1, 2),
                     test::testCamera(Camera::Projection::Pinhole, 24, 16, 40, 30, Vec3(1, 0.2, -0.1), Vec3(0, 0, 1)));
    s.spheres.push_back(ballAt(Vec3(10, 3, 1), 3));
    const RenderResult r = render(s);
    ASSERT_TRUE(r.lensing);
    int objects = 0, sky = 0;
    for (const PixelRecord& p : r.pixels) {
        ASSERT_TRUE(p.kind == PixelRecord::Object || p.kind == PixelRecord::Sky);
        (p.kind == PixelRecord::Object ? objects : sky)++;
        EXPECT_NEAR(p.magnification, 1, 1e-6);
        EXPECT_NEAR(p.shear, 0, 1e-6);
        EXPECT_NEAR(p.rotation, 0, 1e-6);
    }
    EXPECT_GT(objects, 20);
    EXPECT_GT(sky, 20);
}

// A moving observer in flat space: aberration maps the sky conformally, so every sky pixel is
// unsheared and unturned, and its solid angle scales with the Doppler factor: mu = (nu_inf /
// nu_obs)^2 = 1 / g^2, g the pixel's frequency ratio (Rybicki & Lightman 1979, eq. 4.10), up to
// speeds close to light's (the sky squeezed ahead: mu 1/(gamma^2 (1 + beta)^2) = 5e-4 at 0.999 c).
TEST(RenderLensing, MovingObserverSeesTheSkyScaledByTheSquareOfTheDopplerFactor) {
    for (double beta : {0.6, 0.999}) {
        Scene s = lensingScene(
            std::make_shared<Minkowski>(), Vec4(0, 1, 2, 3),
            test::testCamera(Camera::Projection::Panorama, 36, 18, 360, 180, Vec3(1, 0, 0), Vec3(0, 0, 1)));
        const double gamma = 1 / std::sqrt(1 - beta * beta);
        s.observerVelocity = gamma * Vec4(1, beta * 0.6, beta * 0.8, 0);
        const RenderResult r = render(s);
        double brightest = 0;
        for (const PixelRecord& p : r.pixels) {
            ASSERT_EQ(p.kind, PixelRecord::Sky);
            EXPECT_NEAR(p.magnification * p.frequencyRatio * p.frequencyRatio, 1, 1e-5) << "beta " << beta;
            EXPECT_NEAR(p.shear, 0, 1e-5);
            EXPECT_NEAR(p.rotation, 0, 1e-5);
            brightest = std::max(brightest, double(p.frequencyRatio));
        }
        // The panorama's pixels near the direction of motion (within about 1/gamma of it at 0.999 c,
        // finer than a pixel) are blueshifted by much.
        EXPECT_GT(brightest, beta > 0.9 ? 5 : 1.5) << "the view holds the direction of motion";
    }
}

// The angle of each pixel's viewing direction from the lens (at the chart's origin), for a static
// observer far away (its frame is the chart's to O(M/D)).
double angleFromLens(const Scene& s, const Camera& cam, int i, int j) {
    const Vec3 n = cam.direction(i, j), towardsLens = -s.observer.tail<3>().normalized();
    return std::atan2(n.cross(towardsLens).norm(), n.dot(towardsLens));
}

// Calls f(i, j, pixel) for every pixel of a render whose x = theta_E / theta (theta the pixel's
// angle from the lens) lies clear of the Einstein ring, where mu grows without bound, and of the
// lens itself (b < 0.3 theta_E D), where the weak-field formula's own second order shows.
template <class F>
void forPixelsClearOfTheRing(const RenderResult& r, const Camera& cam, const std::function<double(int, int)>& x, F f) {
    for (int j = 0; j < cam.height; ++j)
        for (int i = 0; i < cam.width; ++i) {
            const double xi = x(i, j);
            if ((xi > 1 / 1.3 && xi < 1.6) || xi > 3.3) continue;
            f(xi, r.pixels[static_cast<std::size_t>(j * cam.width + i)], i, j);
        }
}

// Observer 10^10 M from a unit mass (Einstein angle 2e-5 rad, impact parameters >= 6e4 M: the
// formula's own error, the second-order deflection 15 pi M^2 / 4 b^2, is 1e-5 to 1e-4 in mu there;
// measured 8e-6 on the outer image, 1.2e-4 on the inner, 6e-5 in the shear), the lens off the
// image's centre.
TEST(RenderLensing, SchwarzschildPointLensMagnifiesTheSkyAsTheWeakFieldFormula) {
    const double D = 1e10, thetaE = std::sqrt(4 / D);
    const double fov = 8 * thetaE * 180 / kPi;
    Scene s = lensingScene(std::make_shared<Schwarzschild>(1.0), Vec4(0, -D, 0, 0),
                           test::testCamera(Camera::Projection::Pinhole, 40, 30, fov, 0.75 * fov,
                                            Vec3(1, 0.9 * thetaE, -0.6 * thetaE), Vec3(0, 0, 1)));
    const RenderResult r = render(s);
    const Camera cam = frameCamera(s);
    int outer = 0, inner = 0;
    for (const PixelRecord& p : r.pixels) ASSERT_EQ(p.kind, PixelRecord::Sky);
    forPixelsClearOfTheRing(
        r, cam, [&](int i, int j) { return thetaE / angleFromLens(s, cam, i, j); },
        [&](double x, const PixelRecord& p, int i, int j) {
            const double mu = 1 / (1 - std::pow(x, 4));
            EXPECT_NEAR(p.magnification / mu, 1, x > 1 ? 4e-4 : 3e-5) << "pixel " << i << ", " << j << ", x " << x;
            EXPECT_NEAR(p.shear / (x * x), 1, 2.5e-4) << "pixel " << i << ", " << j;
            EXPECT_NEAR(p.rotation, 0, 1e-6);
            (x > 1 ? inner : outer)++;
        });
    EXPECT_GT(outer, 500);  // both images: the outer keeps its parity, the inner is mirrored
    EXPECT_GT(inner, 10);
}

TEST(RenderLensing, SchwarzschildPointLensMagnifiesABallBehindItAsTheThinLensFormula) {
    const double Dd = 1e8, Dds = 1e8, thetaE = std::sqrt(4 * Dds / (Dd * (Dd + Dds)));
    const double fov = 6 * thetaE * 180 / kPi;
    Scene s = lensingScene(std::make_shared<Schwarzschild>(1.0), Vec4(0, -Dd, 0, 0),
                           test::testCamera(Camera::Projection::Pinhole, 64, 48, fov, 0.75 * fov,
                                            Vec3(1, 0.3 * thetaE, 0.2 * thetaE), Vec3(0, 0, 1)));
    // A ball behind the lens 1 to 2 Einstein angles off its axis (seen from the observer), so that
    // both its images lie clear of the ring: the outer at 1.6 to 2.4 theta_E, the inner at 0.4 to 0.6.
    const double Ds = Dd + Dds;
    s.spheres.push_back(
        ballAt(Vec3(Dds, 1.5 * thetaE * Ds * std::cos(0.5), 1.5 * thetaE * Ds * std::sin(0.5)), 0.5 * thetaE * Ds));
    const RenderResult r = render(s);
    const Camera cam = frameCamera(s);
    int outer = 0, inner = 0;
    // Each pixel's own source plane, through where its ray met the ball (the affine length is the
    // distance there to O(M/D)); sky pixels are given an x beyond the range compared.
    auto x = [&](int i, int j) {
        const PixelRecord& p = r.pixels[static_cast<std::size_t>(j * cam.width + i)];
        return p.kind == PixelRecord::Object
                   ? std::sqrt(4 * (p.affine - Dd) / (Dd * p.affine)) / angleFromLens(s, cam, i, j)
                   : 10.0;
    };
    forPixelsClearOfTheRing(r, cam, x, [&](double xi, const PixelRecord& p, int i, int j) {
        EXPECT_NEAR(p.magnification * (1 - std::pow(xi, 4)), 1, 2e-3) << "pixel " << i << ", " << j;
        EXPECT_NEAR(p.shear / (xi * xi), 1, 2e-3);
        (xi > 1 ? inner : outer)++;
    });
    EXPECT_GT(outer, 50);
    EXPECT_GT(inner, 3);
}

// The escape direction (chart) of the ray the observer sees along frame direction n.
Vec3 escapeDirection(const Scene& s, const LocalFrame& frame, const Vec3& n) {
    const PhasePoint start{s.observer, frame.pastNullMomentum(*s.spacetime, n.normalized())};
    TraceOptions opt = s.settings.trace;
    opt.absTol = opt.relTol = 1e-13;
    opt.escapeAngle = 1e-13;
    const TraceResult r = traceGeodesic(*s.spacetime, start, opt);
    EXPECT_EQ(r.reason, StopReason::Escaped);
    return (s.spacetime->inverseMetric(r.end.x) * r.end.p).tail<3>().normalized();
}

// A black hole (a = 0: Schwarzschild, a = 0.9: Kerr) from r = 15 M, 60 degrees above the
// equator, looking past the hole: pixels up to the photon ring (deflections past pi/2), against
// the escape directions' central differences (the magnification and shear do not depend on the
// axes the map is written on). Returns the largest |rotation| among the compared pixels and
// counts those deflected by more than 90 degrees.
double compareWithDifferences(double spin, int& compared, int& deflectedPastRightAngle) {
    const double r0 = 15, incl = 30 * kPi / 180;
    const Vec4 observer(0, r0 * std::sin(incl), 0, r0 * std::cos(incl));
    Scene s = lensingScene(std::make_shared<KerrNewman>(1.0, spin, 0.0), observer,
                           test::testCamera(Camera::Projection::Pinhole, 12, 8, 50, 34,
                                            Vec3(-std::sin(incl), 0.15, -std::cos(incl)), Vec3(0, 0, 1)));
    s.settings.trace.absTol = s.settings.trace.relTol = 1e-12;
    const RenderResult r = render(s);
    const Camera cam = frameCamera(s);
    const LocalFrame frame = observerFrame(s);
    const Camera::Axes screen = cam.axes();
    double largestRotation = 0, largestLensing = 0;
    compared = deflectedPastRightAngle = 0;
    for (int j = 0; j < cam.height; ++j)
        for (int i = 0; i < cam.width; ++i) {
            const PixelRecord& p = r.pixels[static_cast<std::size_t>(j * cam.width + i)];
            if (p.kind != PixelRecord::Sky) continue;
            // The same map by differences: turn the viewing direction by +-h along the pixel's
            // screen axes and difference the escape directions, written on any axes normal to k.
            const Vec3 n = cam.direction(i, j);
            const auto [s1, s2] = screenAxes(n, screen.right, screen.up);
            const double h = 1e-5;
            auto escapeAlong = [&](const Vec3& d) { return escapeDirection(s, frame, d); };
            const Vec3 k = escapeAlong(n);
            Eigen::Matrix<double, 3, 2> dk;
            dk.col(0) = (escapeAlong(n + h * s1) - escapeAlong(n - h * s1)) / (2 * h);
            dk.col(1) = (escapeAlong(n + h * s2) - escapeAlong(n - h * s2)) / (2 * h);
            const Vec3 a1 = k.unitOrthogonal(), a2 = k.cross(a1);
            Eigen::Matrix2d A;
            A << a1.dot(dk.col(0)), a1.dot(dk.col(1)), a2.dot(dk.col(0)), a2.dot(dk.col(1));
            const LensingDistortion expected = LensingDistortion::of(A);
            // Beside the shadow's edge the map changes too fast for differences of step h.
            if (std::abs(expected.magnification) > 20 || expected.shear > 20) continue;
            EXPECT_NEAR(p.magnification / expected.magnification, 1, 1e-4) << "pixel " << i << ", " << j;
            EXPECT_NEAR(p.shear, expected.shear, 1e-4 * (1 + expected.shear)) << "pixel " << i << ", " << j;
            largestRotation = std::max(largestRotation, double(std::abs(p.rotation)));
            largestLensing = std::max(largestLensing, std::abs(expected.magnification - 1));
            const Vec4 start = frame.e[1] * n(0) + frame.e[2] * n(1) + frame.e[3] * n(2);
            deflectedPastRightAngle += k.dot(start.tail<3>().normalized()) < 0;
            ++compared;
        }
    EXPECT_GT(largestLensing, 0.5) << "the view holds strongly lensed pixels";
    return largestRotation;
}

TEST(RenderLensing, KerrInclinedObserverMatchesDifferencesOfTracedRays) {
    int compared = 0, bentBack = 0;
    const double rotation = compareWithDifferences(0.9, compared, bentBack);
    EXPECT_GT(compared, 25);
    EXPECT_GT(bentBack, 3);
    EXPECT_GT(rotation, 1e-4) << "frame dragging turns the images (measured against parallel-transported axes)";
}

// Without spin every ray stays in its plane through the hole: against axes parallel transported
// along the ray no image is turned, however far it is bent (the axes compared by direction alone
// would turn by up to the bending).
TEST(RenderLensing, SchwarzschildTurnsNoImageAgainstParallelTransportedAxes) {
    int compared = 0, bentBack = 0;
    EXPECT_LT(compareWithDifferences(0.0, compared, bentBack), 1e-5);  // the bundle's tolerance: 1.4e-6 here
    EXPECT_GT(compared, 25);
    EXPECT_GT(bentBack, 3);
}

TEST(RenderLensing, DistortionOfAKnownMap) {
    // A = R(w) [(1 - kappa) I - gamma (cos 2phi, sin 2phi; sin 2phi, -cos 2phi)].
    const double w = 0.3, kappa = 0.2, gamma = 0.15, phi = 0.7;
    Eigen::Matrix2d S;
    S << (1 - kappa) - gamma * std::cos(2 * phi), -gamma * std::sin(2 * phi), -gamma * std::sin(2 * phi),
        (1 - kappa) + gamma * std::cos(2 * phi);
    const Eigen::Matrix2d A = Eigen::Rotation2Dd(w).toRotationMatrix() * S;
    const LensingDistortion d = LensingDistortion::of(A);
    EXPECT_NEAR(d.rotation, w, 1e-14);
    EXPECT_NEAR(d.shear, gamma, 1e-14);
    EXPECT_NEAR(d.magnification, 1 / ((1 - kappa) * (1 - kappa) - gamma * gamma), 1e-13);
    // kappa > 1 turns S's trace negative: the rotation stays w (modulo a half turn).
    const Eigen::Matrix2d B = Eigen::Rotation2Dd(w).toRotationMatrix() * (-S);
    EXPECT_NEAR(LensingDistortion::of(B).rotation, w, 1e-14);
    EXPECT_NEAR(LensingDistortion::of(B).shear, gamma, 1e-14);
}

TEST(RenderLensing, MagnificationNeedsTheNumericTracer) {
    Scene s = lensingScene(std::make_shared<Minkowski>(), Vec4(0, 0, 0, 0),
                           test::testCamera(Camera::Projection::Pinhole, 4, 4, 40, 40, Vec3(1, 0, 0), Vec3(0, 0, 1)));
    s.settings.method = RenderSettings::Method::PerVertex;
    try {
        render(s);
        ADD_FAILURE() << "a per-vertex render with magnification was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("render.magnification"), std::string::npos) << e.what();
    }
    // Minkowski scenes are drawn by the special-relativity renderer, which has no bundles.
    try {
        renderColouredImage(s);
        ADD_FAILURE() << "a special-relativity render with magnification was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("1/g^2"), std::string::npos) << e.what();
    }
}

}  // namespace
