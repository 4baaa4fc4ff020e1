#include "core/sr/camera.hpp"

#include "core/input/ranges.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lc::sr {

void PinholeCamera::validate() const {
    using namespace input;
    kImageSide.require(width, "SR camera width");
    kImageSide.require(height, "SR camera height");
    kImagePixels.require(double(width) * double(height), "SR camera width x height");
    kFieldOfView.require(fovYDeg, "SR camera vertical field of view");
    if (fovYDeg >= 180) throw std::invalid_argument("SR camera: a pinhole field of view must be below 180 degrees");
    for (int k = 0; k < 3; ++k) {
        kCoordinate.require(position(k), "SR camera position component");
        kDirectionComponent.require(forward(k), "SR camera forward component");
        kDirectionComponent.require(up(k), "SR camera up component");
    }
    if (!(forward.norm() > 1e-12 && up.norm() > 1e-12))
        throw std::invalid_argument("SR camera: forward and up must not be zero");
    if (forward.normalized().cross(up.normalized()).norm() < 1e-9)
        throw std::invalid_argument("SR camera: forward and up are parallel");
}

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
    const Vec3 h = pinholePixelHomogeneous<double>(d, focalPx, cx, cy, forward, right, up);
    if (!(h.z() > 0.0)) return false;
    px = h.x() / h.z();
    py = h.y() / h.z();
    return true;
}

}  // namespace lc::sr
