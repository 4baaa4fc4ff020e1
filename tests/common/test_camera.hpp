// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A camera for tests: projection, size, fields of view and the chart directions it looks along,
// every other field at its default. Shared by the core and view tests that place one by hand.
#include "core/scene/camera.hpp"

namespace lc::test {

inline Camera testCamera(Camera::Projection projection, int width, int height, double fovXDeg, double fovYDeg,
                         const Vec3& forward, const Vec3& up) {
    Camera c;
    c.projection = projection;
    c.width = width;
    c.height = height;
    c.fovXDeg = fovXDeg;
    c.fovYDeg = fovYDeg;
    c.forward = forward;
    c.up = up;
    return c;
}

}  // namespace lc::test
