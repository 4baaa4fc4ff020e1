#include "core/sr/camera.hpp"

#include <cmath>

namespace lc::sr {

PinholeCamera::Basis PinholeCamera::basis() const {
    Basis b;
    b.forward = forward.normalized();
    b.right = b.forward.cross(up).normalized();
    b.up = b.right.cross(b.forward);
    b.focalPx = 0.5 * height / std::tan(0.5 * fovYDeg * kPi / 180.0);
    b.cx = 0.5 * width;
    b.cy = 0.5 * height;
    return b;
}

Vec3 PinholeCamera::Basis::viewDirection(double px, double py) const {
    return pinholeViewDirection<double>(px, py, focalPx, cx, cy, forward, right, up);
}

bool PinholeCamera::Basis::project(const Vec3& d, double& px, double& py) const {
    const double z = d.dot(forward);
    if (!(z > 0.0)) return false;
    px = cx + focalPx * d.dot(right) / z;
    py = cy - focalPx * d.dot(up) / z;
    return true;
}

}  // namespace lc::sr
