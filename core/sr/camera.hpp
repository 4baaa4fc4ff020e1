#pragma once
// Pinhole camera of an observer at rest in S. Pixel (i, j) has its centre at continuous
// coordinates (i + 0.5, j + 0.5); row 0 is the top of the image.
#include "core/numerics/types.hpp"

#include <cmath>

namespace lc::sr {

// The unit direction through continuous pixel coordinates (px, py) of a pinhole with focal length
// focalPx (pixels), centre (cx, cy) and orthonormal forward / right / up; row 0 at the top. For
// every scalar (double; codegen::Expr for the shaders' lcSrViewDirection).
template <class S>
Eigen::Matrix<S, 3, 1> pinholeViewDirection(const S& px, const S& py, const S& focalPx, const S& cx, const S& cy,
                                            const Eigen::Matrix<S, 3, 1>& forward, const Eigen::Matrix<S, 3, 1>& right,
                                            const Eigen::Matrix<S, 3, 1>& up) {
    using std::sqrt;
    const Eigen::Matrix<S, 3, 1> v = focalPx * forward + (px - cx) * right - (py - cy) * up;
    return v / sqrt(v.squaredNorm());
}

// Homogeneous pixel coordinates (px w, py w, w) of the direction d (relative to the eye) through a
// pinhole with focal length focalPx, centre (cx, cy) and orthonormal forward / right / up (row 0 at
// the top): w = d . forward, so d is in front of the camera only where w > 0. The inverse of
// pinholeViewDirection. For every scalar (double for Basis::project; codegen::Expr for the shaders'
// lcSrPixelHomogeneous, whose w lets GL clip what is behind the camera).
template <class S>
Eigen::Matrix<S, 3, 1> pinholePixelHomogeneous(const Eigen::Matrix<S, 3, 1>& d, const S& focalPx, const S& cx,
                                               const S& cy, const Eigen::Matrix<S, 3, 1>& forward,
                                               const Eigen::Matrix<S, 3, 1>& right, const Eigen::Matrix<S, 3, 1>& up) {
    const S w = d.dot(forward);
    return Eigen::Matrix<S, 3, 1>(cx * w + focalPx * d.dot(right), cy * w - focalPx * d.dot(up), w);
}

struct PinholeCamera {
    Vec3 position = Vec3::Zero();
    Vec3 forward = Vec3(0.0, 0.0, -1.0);  // look direction (need not be unit)
    Vec3 up = Vec3(0.0, 1.0, 0.0);        // approximate up; made orthogonal to forward
    double fovYDeg = 60.0;                // vertical field of view
    int width = 640;
    int height = 360;

    // Throws std::invalid_argument naming the value and its accepted range (core/input/ranges.hpp):
    // image sides and pixel count, the vertical field of view (below 180 degrees), a finite
    // position, forward and up neither zero nor parallel.
    void validate() const;

    // Orthonormal right / up / forward and the focal length in pixels.
    struct Basis {
        Vec3 right, up, forward;
        double focalPx, cx, cy;
        // Unit direction the observer looks along through continuous pixel coordinates.
        Vec3 viewDirection(double px, double py) const;
        // Pixel coordinates of a direction; false if it does not point in front of the camera.
        bool project(const Vec3& direction, double& px, double& py) const;
    };
    Basis basis() const;

    Vec3 viewDirection(double px, double py) const { return basis().viewDirection(px, py); }
    // Pixel coordinates of a point of S (uses position); false if behind the camera.
    bool projectPoint(const Vec3& point, double& px, double& py) const {
        return basis().project(point - position, px, py);
    }
};

}  // namespace lc::sr
