// SPDX-License-Identifier: BSD-3-Clause
// The camera's chart directions seen in the observer's rest space (core/scene/frame_camera.hpp,
// docs/PHYSICS.md section 8). Oracles: the defining properties of the projection (orthogonal to u,
// differing from the chart vector by a multiple of u), the radial null ray of Schwarzschild
// written in closed form, and Minkowski, where a static observer's frame is the chart's.
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"
#include "core/scene/frame_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lc {
namespace {

Scene sceneAt(SpacetimePtr st, const Vec4& x, const Vec4& u = Vec4::Unit(0)) {
    Scene s;
    s.spacetime = std::move(st);
    s.observer = x;
    s.observerVelocity = u;
    return s;
}

TEST(FrameCamera, ProjectionIsOrthogonalToTheObserverAndInvertible) {
    const auto kerr = std::make_shared<KerrNewman>(1, 0.9, 0.3);
    const auto godel = std::make_shared<GodelCartesian>(1.0);
    for (const Scene& s :
         {sceneAt(kerr, Vec4(0, 4, -3, 2)), sceneAt(kerr, Vec4(0, 4, -3, 2), Vec4(1.4, 0.2, 0.5, -0.3)),
          sceneAt(godel, Vec4(0, 0.8, -0.9, 0.3)), sceneAt(godel, Vec4(0, 0.5, 0.2, 0), Vec4(1.2, 0.3, -0.4, 0.5))}) {
        const LocalFrame frame = observerFrame(s);
        const Mat4 g = s.spacetime->metric(s.observer);
        for (const Vec3& v : {Vec3(1, 0, 0), Vec3(0.3, -1, 0.2), Vec3(-2, 0.5, 7)}) {
            const Vec3 n = restSpaceComponents(*s.spacetime, frame, v);
            const Vec4 projected = n(0) * frame.e[1] + n(1) * frame.e[2] + n(2) * frame.e[3];
            EXPECT_NEAR(projected.dot(g * frame.e[0]), 0, 1e-12);
            // projected - (0, v) is a multiple of u: its components are proportional to e0's.
            const Vec4 diff = projected - Vec4(0, v(0), v(1), v(2));
            EXPECT_LT((diff - diff(0) / frame.e[0](0) * frame.e[0]).norm(), 1e-11 * (1 + v.norm()));
            const Vec3 back = chartVectorOf(*s.spacetime, frame, n);
            EXPECT_LT((back - v).norm(), 1e-11 * v.norm());
        }
    }
}

TEST(FrameCamera, MinkowskiStaticFrameIsTheChart) {
    const Scene s = sceneAt(std::make_shared<Minkowski>(), Vec4(3, 1, 2, -5));
    Camera c;
    c.forward = Vec3(0.2, -0.7, 0.4);
    c.up = Vec3(0, 0.3, 1);
    const Camera f = frameCamera(c, *s.spacetime, observerFrame(s));
    EXPECT_LT((f.forward - c.forward).norm(), 1e-15);
    EXPECT_LT((f.up - c.up).norm(), 1e-15);
}

// A static Schwarzschild observer off the equator: the radial chart direction is where the radial
// null ray comes from. That ray's tangent lies in span(d/dt, radial) and is null: k = d/dt + c R
// with g(k, k) = 0, solved in closed form.
TEST(FrameCamera, RadialChartDirectionIsTheRadialRayOfSchwarzschild) {
    const auto st = std::make_shared<KerrNewman>(1, 0, 0);
    for (const double incl : {0.2, 1.0, 2.5}) {
        const double r = 7;
        const Vec4 x(0, r * std::sin(incl) * std::cos(0.4), r * std::sin(incl) * std::sin(0.4), r * std::cos(incl));
        const Scene s = sceneAt(st, x);
        const Vec4 R(0, x(1) / r, x(2) / r, x(3) / r);
        const Mat4 g = st->metric(x);
        // g(T + cR, T + cR) = gtt + 2c gtR + c^2 gRR = 0: the root c > 0 is the light coming out
        // from the hole's side; its past-directed tangent, what the camera traces, points inwards.
        const double gtt = g(0, 0), gtR = Vec4::Unit(0).dot(g * R), gRR = R.dot(g * R);
        const double c = (-gtR - std::sqrt(gtR * gtR - gtt * gRR)) / gRR;
        ASSERT_GT(c, 0);
        const Vec4 kPast = -(Vec4::Unit(0) + c * R);
        const LocalFrame frame = observerFrame(s);
        const Vec3 seen = frame.directionOf(*st, g * kPast);
        Camera cam;
        cam.forward = -R.tail<3>();
        cam.up = Vec3(0.1, 0.9, 0.4);
        const Vec3 forward = frameCamera(cam, *st, frame).forward.normalized();
        EXPECT_LT((seen - forward).norm(), 1e-12) << "inclination " << incl;
    }
}

TEST(FrameCamera, LookAtAndTurnsInTheRestSpace) {
    Scene s = sceneAt(std::make_shared<KerrNewman>(1, 0.5, 0), Vec4(0, 6, 2, 3));
    s.camera.lookAt = Vec3(0, 0, 0);
    s.camera.up = Vec3(0, 0, 1);
    const LocalFrame frame = observerFrame(s);
    EXPECT_LT(
        (frameCamera(s).forward.normalized() - restSpaceComponents(*s.spacetime, frame, Vec3(-6, -2, -3)).normalized())
            .norm(),
        1e-14);
    // A turn by 0.3 rad to the left is 0.3 rad as the observer measures it, about its up.
    const Camera before = frameCamera(s);
    Scene turned = s;
    turned.camera.forward = turnedForward(s, 0.3);
    turned.camera.lookAt.reset();
    const Camera after = frameCamera(turned);
    EXPECT_NEAR(std::acos(before.forward.normalized().dot(after.forward.normalized())), 0.3, 1e-12);
    const Vec3 up = before.forward.normalized().cross(before.up).normalized().cross(before.forward.normalized());
    EXPECT_NEAR(after.forward.normalized().dot(up), 0, 1e-12);
    // Refusals: look_at at the observer; forward and up parallel in the rest space.
    s.camera.lookAt = Vec3(6, 2, 3);
    EXPECT_THROW(frameCamera(s), std::invalid_argument);
    s.camera.lookAt = Vec3(6, 2, 10);
    EXPECT_THROW(frameCamera(s), std::invalid_argument);
}

}  // namespace
}  // namespace lc
