// SPDX-License-Identifier: BSD-3-Clause
// Every image of a point source at infinity (core/analysis/point_source_images): for the
// Schwarzschild point lens in the weak field, two images at theta+- = (beta +- sqrt(beta^2 +
// 4 theta_E^2))/2 with magnifications 1/(1 - (theta_E/theta)^4), adding up to
// |mu+| + |mu-| = (u^2 + 2)/(u sqrt(u^2 + 4)) and mu+ + mu- = 1 (Paczynski 1986; Schneider, Ehlers &
// Falco 1992, eqs. 2.24-2.25), seen by an observer 10^10 M away (theta_E = 2e-5 rad).
#include "tests/common/test_camera.hpp"
#include "core/analysis/point_source_images.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {
using namespace lc;

Scene pointLens(double D, double thetaE) {
    Scene s;
    s.spacetime = std::make_shared<Schwarzschild>(1.0);
    s.observer = Vec4(0, -D, 0, 0);
    const double fov = 10 * thetaE * 180 / kPi;
    s.camera = test::testCamera(Camera::Projection::Pinhole, 64, 64, fov, fov, Vec3(1, 0.3 * thetaE, 0.2 * thetaE),
                                Vec3(0, 0, 1));
    s.settings.threads = 2;
    s.settings.trace.absTol = s.settings.trace.relTol = 1e-12;
    return s;
}

TEST(PointSourceImages, SchwarzschildPointLensHasTwoImagesWhoseMagnificationsAddAsPaczynskiFound) {
    const double D = 1e10, thetaE = std::sqrt(4 / D);
    const Scene s = pointLens(D, thetaE);
    for (double u : {0.5, 1.0, 2.0}) {
        // The source beta = u theta_E from the lens, off both of the camera's axes.
        const double beta = u * thetaE, phi = 0.6;
        const Vec3 source(std::cos(beta), std::sin(beta) * std::cos(phi), std::sin(beta) * std::sin(phi));
        const PointSourceImages found = findPointSourceImages(s, source);
        ASSERT_EQ(found.images.size(), 2u) << "u = " << u;
        const double thetaPlus = 0.5 * (beta + std::sqrt(beta * beta + 4 * thetaE * thetaE));
        const double thetaMinus = 0.5 * (std::sqrt(beta * beta + 4 * thetaE * thetaE) - beta);
        for (const PointSourceImage& im : found.images) {
            // Seen from the observer the lens is along +x: the image's angle from it and its side.
            const double theta = std::atan2(im.direction.cross(Vec3::UnitX()).norm(), im.direction(0));
            const bool outer = im.magnification > 0;
            EXPECT_NEAR(theta / (outer ? thetaPlus : thetaMinus), 1, 1e-4) << "u = " << u;
            EXPECT_NEAR(im.magnification * (1 - std::pow(thetaE / theta, 4)), 1, 2e-4) << "u = " << u;
            // The outer image lies on the source's side of the lens, the inner opposite.
            const double side = im.direction(1) * std::cos(phi) + im.direction(2) * std::sin(phi);
            EXPECT_EQ(side > 0, outer) << "u = " << u;
        }
        const double paczynski = (u * u + 2) / (u * std::sqrt(u * u + 4));
        EXPECT_NEAR(found.totalMagnification() / paczynski, 1, 1e-4) << "u = " << u;
        EXPECT_NEAR(found.signedMagnification(), 1, 2e-4) << "u = " << u;
    }
}

// Kerr a = 0.99 seen edge-on from 30 M (data/kerr.json's view), the source behind the hole in the
// equatorial plane: the reflection through that plane maps the images onto images, so each lies on
// the equator or has its mirror twin with the same magnification; the two primary images lie on
// either side of the hole with opposite parities, and the ones beside the shadow are faint.
TEST(PointSourceImages, KerrImagesOfAnEquatorialSourceAreTheirOwnMirrorImages) {
    Scene s;
    s.spacetime = std::make_shared<KerrNewman>(1.0, 0.99, 0.0);
    s.observer = Vec4(0, 30, 0, 0);
    s.camera = test::testCamera(Camera::Projection::Pinhole, 480, 240, 60, 32.2, Vec3(-1, 0, 0), Vec3(0, 0, 1));
    s.settings.threads = 2;
    s.settings.trace.absTol = s.settings.trace.relTol = 1e-10;
    const PointSourceImages found = findPointSourceImages(s, Vec3(-1, 0.06, 0));
    ASSERT_GE(found.images.size(), 2u);
    EXPECT_LT(found.images[0].magnification * found.images[1].magnification, 0) << "opposite parities";
    EXPECT_LT(found.images[0].direction(1) * found.images[1].direction(1), 0) << "either side of the hole";
    for (std::size_t k = 0; k < found.images.size(); ++k) {
        const PointSourceImage& im = found.images[k];
        if (k >= 2) {
            EXPECT_LT(std::abs(im.magnification), 1e-2) << "beside the shadow";
        }
        if (std::abs(im.direction(2)) < 1e-7) continue;  // on the equator
        const Vec3 mirrored(im.direction(0), im.direction(1), -im.direction(2));
        const auto twin = std::find_if(found.images.begin(), found.images.end(), [&](const PointSourceImage& other) {
            return (other.direction - mirrored).norm() < 1e-6;
        });
        ASSERT_NE(twin, found.images.end()) << "image " << k << " has no mirror twin";
        EXPECT_NEAR(twin->magnification / im.magnification, 1, 1e-5);
    }
}

TEST(PointSourceImages, FlatSpaceShowsTheSourceOnceUnmagnifiedAndNoneOutsideTheView) {
    Scene s;
    s.spacetime = std::make_shared<Minkowski>();
    s.observer = Vec4(0, 3, -2, 1);
    s.camera = test::testCamera(Camera::Projection::Pinhole, 32, 16, 60, 30, Vec3(1, 0, 0), Vec3(0, 0, 1));
    const PointSourceImages found = findPointSourceImages(s, Vec3(1, 0.2, -0.1));
    ASSERT_EQ(found.images.size(), 1u);
    EXPECT_NEAR(found.images[0].magnification, 1, 1e-9);
    EXPECT_NEAR(found.images[0].direction.dot(Vec3(1, 0.2, -0.1).normalized()), 1, 1e-12);
    EXPECT_TRUE(findPointSourceImages(s, Vec3(-1, 0, 0)).images.empty()) << "behind the camera";
    EXPECT_THROW(findPointSourceImages(s, Vec3(0, 0, 0)), std::invalid_argument);
}

}  // namespace
