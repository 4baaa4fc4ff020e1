#pragma once
// The special-relativity tests' camera: a pinhole at the origin looking along -z, y up, of width x
// height pixels and the given vertical field of view.
#include "core/sr/camera.hpp"

namespace lc::test {

inline sr::PinholeCamera srCamera(int width, int height, double fovYDeg = 75.0) {
    sr::PinholeCamera c;
    c.width = width;
    c.height = height;
    c.fovYDeg = fovYDeg;
    return c;
}

}  // namespace lc::test
