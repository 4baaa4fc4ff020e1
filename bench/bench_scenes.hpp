// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Scenes shared by the Goedel render benches: one checkered sphere seen by a static observer
// on the axis through a 1024x512 full-sky panorama.
#include "core/scene/godel_placement.hpp"
#include "core/metrics/godel.hpp"
#include "core/scene/scene.hpp"

namespace lc::bench {

inline Scene godelBallPanorama(const Vec4& centre, double radius, int windings) {
    Scene s;
    s.spacetime = std::make_shared<GodelCartesian>(1.0);
    s.camera.projection = Camera::Projection::Panorama;
    s.camera.width = 1024;
    s.camera.height = 512;
    s.camera.fovXDeg = 360;
    s.camera.fovYDeg = 180;
    SphereObject ball;
    ball.name = "ball";
    ball.centre = centre;
    ball.radius = radius;
    ball.placement = std::make_shared<GodelPlacement>(1.0, ball.centre);
    ball.texture = std::make_shared<CheckerTexture>(16, 8, Vec3(0.9, 0.9, 0.9), Vec3(0.8, 0.2, 0.1));
    s.spheres.push_back(ball);
    s.settings.windings = windings;
    s.settings.trace.maxAffine = (windings + 1) * 2 * kPi;
    s.settings.progress = false;
    return s;
}

}  // namespace lc::bench
