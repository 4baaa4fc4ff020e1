// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The special-relativity tests' camera: a pinhole at the origin looking along -z, y up, of width x
// height pixels, the given vertical field of view and square pixels (the horizontal field follows
// from the aspect ratio).
#include "core/sr/observer_camera.hpp"

#include <cmath>

namespace lc::test {

// The horizontal field of view (degrees) that makes a pinhole's pixels square.
inline double squarePixelFovX(int width, int height, double fovYDeg) {
    const double deg = kPi / 180;
    return 2 * std::atan(std::tan(0.5 * fovYDeg * deg) * width / height) / deg;
}

inline sr::ObserverCamera srCamera(int width, int height, double fovYDeg = 75.0) {
    sr::ObserverCamera c;
    c.width = width;
    c.height = height;
    c.fovYDeg = fovYDeg;
    c.fovXDeg = squarePixelFovX(width, height, fovYDeg);
    c.forward = Vec3(0, 0, -1);
    c.up = Vec3(0, 1, 0);
    return c;
}

}  // namespace lc::test
