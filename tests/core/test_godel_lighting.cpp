// SPDX-License-Identifier: BSD-3-Clause
// Lighting in the Goedel universe against the closed-form light rays of docs/PHYSICS.md section 2,
// typed in here: a static light on the axis, a sphere on the x axis in the plane z = 0. The
// near point of the sphere is lit by the outbound ray; the inbound ray would have to pass
// through the sphere. At the far point it is the other way round.
#include "core/colour/blackbody.hpp"
#include "core/colour/srgb.hpp"
#include "core/render/godel_lighting.hpp"
#include "core/render/photo_scene.hpp"
#include "core/scene/godel_placement.hpp"
#include "core/metrics/godel.hpp"

#include <gtest/gtest.h>

using namespace lc;

namespace {

// A Goedel universe (a = 1) with one ball of radius 0.2 at `centre`, static, and one point
// light, a black body of `temperature` K.
Scene ballAndLight(const Vec4& centre, const Vec4& lightAt, double temperature) {
    Scene scene;
    scene.spacetime = std::make_shared<GodelCartesian>(1.0);
    SphereObject ball;
    ball.centre = centre;
    ball.radius = 0.2;
    ball.placement = std::make_shared<GodelPlacement>(1.0, ball.centre);
    scene.spheres.push_back(ball);
    PointLight light;
    light.position = lightAt;
    light.temperature = temperature;
    scene.lights.push_back(light);
    return scene;
}

// Future-directed planar (k3 = 0) null ray from the origin, a = 1: position at lambda.
Vec4 planarRay(double phi0, double l) {
    const double w = 0.5;
    const double Phi = std::atan(kSqrt2 * std::tan(w * l)) + kPi * std::floor(w * l / kPi + 0.5);
    const double r = 2 * std::sin(w * l), phi = phi0 + Phi;
    return Vec4(2 * kSqrt2 * Phi - l, r * std::cos(phi), r * std::sin(phi), 0);
}

// Expected Lambert cosine at surface point P (on the x axis) with outward normal +-x, for the
// ray that reaches r = |P| at w l = s (outbound s = h, inbound s = pi - h).
double expectedCosine(double xP, double s, double normalSign) {
    const double l = 2 * s;  // w = 1/2
    const double phi0 = (xP > 0 ? 0.0 : kPi) - (std::atan(kSqrt2 * std::tan(s)) + kPi * std::floor(s / kPi + 0.5));
    const double h = 1e-6;
    const Vec4 k = (planarRay(phi0, l + h) - planarRay(phi0, l - h)) / (2 * h);  // tangent, central difference
    const Vec4 x = planarRay(phi0, l);
    EXPECT_NEAR(x(1), xP, 1e-9);
    EXPECT_NEAR(x(2), 0, 1e-9);
    const GodelCartesian g(1.0);
    const Mat4 G = g.metric(x);
    const Vec4 u = Vec4::Unit(0);  // g_tt = 1: static observer
    auto spatial = [&](const Vec4& v) { return Vec4(v - v.dot(G * u) * u); };
    const Vec4 toward = -spatial(k);
    const Vec4 n = spatial(Vec4(0, normalSign, 0, 0));
    auto dot = [&](const Vec4& p, const Vec4& q) { return -p.dot(G * q); };
    return dot(n, toward) / std::sqrt(dot(n, n) * dot(toward, toward));
}

TEST(GodelLighting, NearAndFarPointsLitByTheRightRay) {
    const Scene scene = ballAndLight(Vec4(0, 1.0, 0, 0), Vec4::Zero(), 6500);
    const GodelLighting lighting(1.0, scene, 0);
    const Vec3 srgb = colour::blackbodySrgb(6500, colour::ToneMap::ColourOnly);
    const double white = colour::srgbDecode(srgb(1));

    // Surface points on the x axis: the sphere's own chart is symmetric about that axis, so the
    // surface points are where |local| = R along it. Find them by bisection on the placement.
    const SphereObject& ball = scene.spheres[0];
    auto surface = [&](double from, double to) {
        for (int i = 0; i < 100; ++i) {
            const double mid = 0.5 * (from + to);
            (ball.placement->toLocal(Vec4(0, mid, 0, 0)).norm() < ball.radius ? to : from) = mid;
        }
        return 0.5 * (from + to);
    };
    const double xNear = surface(0.5, 1.0), xFar = surface(1.5, 1.0);
    const double cNear = expectedCosine(xNear, std::asin(xNear / 2), -1);
    const double cFar = expectedCosine(xFar, kPi - std::asin(xFar / 2), +1);
    ASSERT_GT(cNear, 0.1);
    ASSERT_GT(cFar, 0.1);
    EXPECT_NEAR(lighting.at(Vec4(0, xNear, 0, 0), 0)(1) / white, cNear, 1e-5);
    EXPECT_NEAR(lighting.at(Vec4(0, xFar, 0, 0), 0)(1) / white, cFar, 1e-5);
}

TEST(GodelLighting, LightBeyondTheHorizonOfThePointAddsNothing) {
    // The light far more than 2a from the sphere in the hyperbolic plane.
    const Scene scene = ballAndLight(Vec4(0, -1.0, 0, 0), Vec4(0, 1.9, 0, 0), 6500);
    const GodelLighting lighting(1.0, scene, 1);
    EXPECT_EQ(lighting.at(Vec4(0, -0.8, 0, 0), 0).norm(), 0.0);
}

// The photo scene carries each lit sphere's light per vertex only when asked (the shader
// renderer's); the CPU renderers light per pixel and must not pay for the shadow rays. With the
// light beyond the sphere's horizon every vertex gets the ambient light alone.
TEST(GodelLighting, PhotoSceneLightsItsVerticesOnlyWhenAsked) {
    Scene scene = ballAndLight(Vec4(0, 1.0, 0, 0), Vec4::Zero(), 6500);
    PhotoSceneOptions options = photoSceneOptions(scene);
    options.latitudes = 12;
    options.longitudes = 24;
    for (const PhotoSceneObject& o : buildPhotoScene(scene, options)) EXPECT_TRUE(o.light.empty());

    options.vertexLight = true;
    const std::vector<PhotoSceneObject> lit = buildPhotoScene(scene, options);
    ASSERT_EQ(lit.size(), 1u);
    ASSERT_FALSE(lit[0].light.empty());
    double brightest = 0;
    for (const Vec3& l : lit[0].light) {
        EXPECT_GE(l.minCoeff(), kAmbientLight - 1e-12);
        brightest = std::max(brightest, l(1));
    }
    EXPECT_GT(brightest, kAmbientLight + 0.1);  // the side facing the light (cosine > 0.1 above)

    scene.lights[0].position = Vec4(0, -1.9, 0, 0);  // beyond the sphere's horizon
    const std::vector<PhotoSceneObject> dark = buildPhotoScene(scene, options);
    ASSERT_EQ(dark[0].light.size(), lit[0].light.size());
    for (const Vec3& l : dark[0].light) EXPECT_EQ(l, Vec3::Constant(kAmbientLight));
}

}  // namespace
