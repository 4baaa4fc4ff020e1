// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Cameras map a pixel to a unit viewing direction in the observer's local frame.
#include "core/input/ranges.hpp"
#include "core/numerics/types.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace lc {

// The viewing direction through screen offsets x = sx tan(fov_x / 2), y = sy tan(fov_y / 2)
// of a pinhole, and at azimuth az (positive to the left) and elevation el of a panorama, in the
// frame (forward f, right r, up u). For every scalar: Camera::direction calls them in double
// (through pinholeScreenDirection and panoramaScreenDirection below), and the GPU's twins are
// generated from them.
template <class S>
Eigen::Matrix<S, 3, 1> pinholeDirection(const S& x, const S& y, const Eigen::Matrix<S, 3, 1>& f,
                                        const Eigen::Matrix<S, 3, 1>& r, const Eigen::Matrix<S, 3, 1>& u) {
    using std::sqrt;
    const Eigen::Matrix<S, 3, 1> v = f + x * r + y * u;  // |v| >= 1: no zero case to guard
    return v / sqrt(v.squaredNorm());
}
template <class S>
Eigen::Matrix<S, 3, 1> panoramaDirection(const S& az, const S& el, const Eigen::Matrix<S, 3, 1>& f,
                                         const Eigen::Matrix<S, 3, 1>& r, const Eigen::Matrix<S, 3, 1>& u) {
    using std::cos;
    using std::sin;
    using std::sqrt;
    const Eigen::Matrix<S, 3, 1> v = cos(el) * (cos(az) * f - sin(az) * r) + sin(el) * u;  // |v| = 1 up to rounding
    return v / sqrt(v.squaredNorm());
}

// Screen coordinates (sx, sy) in [-1, 1], right and up, of the image point (x, yDown) in pixels
// from the left and top edges (pixel (i, j)'s centre is (i + 0.5, j + 0.5)); then the viewing
// direction there: a pinhole with tangents (tx, ty) of its half fields of view, a panorama with
// half extents (hx, hy) in radians. Camera::direction calls them in double; the GPU tracer's
// lcScreenCoordinates, lcPinholeScreenDirection and lcPanoramaScreenDirection are generated.
template <class S>
Eigen::Matrix<S, 2, 1> screenCoordinates(const S& x, const S& yDown, const S& width, const S& height) {
    return Eigen::Matrix<S, 2, 1>(S(2.0) * x / width - S(1.0), S(1.0) - S(2.0) * yDown / height);
}
template <class S>
Eigen::Matrix<S, 3, 1> pinholeScreenDirection(const S& sx, const S& sy, const S& tx, const S& ty,
                                              const Eigen::Matrix<S, 3, 1>& f, const Eigen::Matrix<S, 3, 1>& r,
                                              const Eigen::Matrix<S, 3, 1>& u) {
    return pinholeDirection(S(sx * tx), S(sy * ty), f, r, u);
}
template <class S>
Eigen::Matrix<S, 3, 1> panoramaScreenDirection(const S& sx, const S& sy, const S& hx, const S& hy,
                                               const Eigen::Matrix<S, 3, 1>& f, const Eigen::Matrix<S, 3, 1>& r,
                                               const Eigen::Matrix<S, 3, 1>& u) {
    // Azimuth about `up` is positive to the left: the screen's right is negative azimuth.
    return panoramaDirection(S(-sx * hx), S(sy * hy), f, r, u);
}

// The inverse: the homogeneous screen position (x, y, w) of direction d through a pinhole (offsets
// sx = x / w, sy = y / w; in front when w > 0), and the screen offsets of a panorama (sx = -azimuth
// / half extent, sy = elevation / half extent). For every scalar: Camera::project calls them in
// double, the Goedel shader's lcPinholeHomogeneous and lcPanoramaScreen are generated from them.
template <class S>
Eigen::Matrix<S, 3, 1> pinholeHomogeneous(const Eigen::Matrix<S, 3, 1>& d, const Eigen::Matrix<S, 3, 1>& f,
                                          const Eigen::Matrix<S, 3, 1>& r, const Eigen::Matrix<S, 3, 1>& u,
                                          const S& tanHalfX, const S& tanHalfY) {
    return Eigen::Matrix<S, 3, 1>(d.dot(r) / tanHalfX, d.dot(u) / tanHalfY, d.dot(f));
}
template <class S>
Eigen::Matrix<S, 2, 1> panoramaScreen(const Eigen::Matrix<S, 3, 1>& d, const Eigen::Matrix<S, 3, 1>& f,
                                      const Eigen::Matrix<S, 3, 1>& r, const Eigen::Matrix<S, 3, 1>& u, const S& halfX,
                                      const S& halfY) {
    using std::atan2;
    using std::sqrt;
    // Elevation by atan2, not asin: well conditioned at the poles, and GLSL's asin is far less
    // accurate than its atan on llvmpipe (1e-4 rad).
    const S df = d.dot(f), dr = d.dot(r);
    const S el = atan2(d.dot(u), sqrt(df * df + dr * dr));
    const S az = atan2(-dr, df);
    return Eigen::Matrix<S, 2, 1>(-az / halfX, el / halfY);
}

struct Camera {
    enum class Projection { Pinhole, Panorama };
    Projection projection = Projection::Pinhole;
    int width = 512, height = 256;
    double fovXDeg = 90, fovYDeg = 45;  // panorama: azimuth and elevation extents (seed 000: 220 x 25)
    // Chart directions at the observer's event (spatial vectors v^i d/dx^i); the camera's frame is
    // their projection into the observer's rest space, forward first (core/scene/frame_camera.hpp).
    // Camera::direction and project read them as frame components: renderers call them on
    // lc::frameCamera's result.
    Vec3 forward{1, 0, 0};
    Vec3 up{0, 0, 1};
    // Spatial chart position to look at: forward is then the chart direction from the observer to
    // it (resolved by lc::frameCamera, so it follows a moving observer).
    std::optional<Vec3> lookAt;

    bool operator==(const Camera& o) const {
        return projection == o.projection && width == o.width && height == o.height && fovXDeg == o.fovXDeg &&
               fovYDeg == o.fovYDeg && forward == o.forward && up == o.up && lookAt == o.lookAt;
    }
    bool operator!=(const Camera& o) const { return !(*this == o); }

    // Throws std::invalid_argument naming the value and its accepted range (core/input/ranges.hpp).
    void validate() const {
        using namespace input;
        kImageSide.require(width, "camera width");
        kImageSide.require(height, "camera height");
        kImagePixels.require(double(width) * double(height), "camera width x height");
        kFieldOfView.require(fovXDeg, "camera horizontal field of view");
        kFieldOfView.require(fovYDeg, "camera vertical field of view");
        if (projection == Projection::Pinhole && (fovXDeg >= 180 || fovYDeg >= 180))
            throw std::invalid_argument("camera: a pinhole field of view must be below 180 degrees (use panorama)");
        if (projection == Projection::Panorama && fovYDeg > 180)
            throw std::invalid_argument("camera: a panorama spans at most 180 degrees of elevation");
        for (int k = 0; k < 3; ++k) {
            kDirectionComponent.require(forward(k), "camera forward component");
            kDirectionComponent.require(up(k), "camera up component");
            if (lookAt) kCoordinate.require((*lookAt)(k), "camera look_at component");
        }
        if (!(forward.norm() > 1e-12 && up.norm() > 1e-12))
            throw std::invalid_argument("camera: forward and up must not be zero");
        // With look_at, forward is known only at the observer's event (lc::frameCamera checks it).
        if (!lookAt && forward.normalized().cross(up.normalized()).norm() < 1e-9)
            throw std::invalid_argument("camera: forward and up are parallel");
    }

    // Half the fields of view in radians (a panorama's half extents), and their tangents (a
    // pinhole's screen half extents at unit distance): the CPU's and the shaders' one source.
    Vec2 halfFieldRadians() const {
        const double deg = kPi / 180;
        return Vec2(0.5 * fovXDeg * deg, 0.5 * fovYDeg * deg);
    }
    Vec2 halfFieldTangents() const {
        const Vec2 h = halfFieldRadians();
        return Vec2(std::tan(h.x()), std::tan(h.y()));
    }

    // The orthonormal frame of the image: forward, right (forward x up) and up made orthogonal.
    struct Axes {
        Vec3 forward, right, up;
    };
    Axes axes() const {
        Axes a;
        a.forward = forward.normalized();
        a.right = a.forward.cross(up).normalized();
        a.up = a.right.cross(a.forward);
        return a;
    }
    // A pinhole's focal lengths in pixels, (fx, fy): image x = width / 2 + fx (d.right) / (d.forward)
    // and y = height / 2 - fy (d.up) / (d.forward), as project() computes them; they differ where
    // the pixels are not square (both fields of view are honoured).
    Vec2 pinholeFocalPixels() const {
        const Vec2 t = halfFieldTangents();
        return Vec2(0.5 * width / t.x(), 0.5 * height / t.y());
    }

    // Direction through the centre of pixel (i, j); row j = 0 is the top of the image.
    Vec3 direction(double i, double j) const { return directionAt(i + 0.5, j + 0.5); }
    // Direction through the continuous image point (x, y), pixel (i, j) covering [i, i+1) x [j, j+1).
    Vec3 directionAt(double x, double y) const {
        const Axes a = axes();
        const Vec3 &f = a.forward, &r = a.right, &u = a.up;
        const Eigen::Vector2d s = screenCoordinates(x, y, double(width), double(height));
        if (projection == Projection::Pinhole) {
            const Vec2 t = halfFieldTangents();
            return pinholeScreenDirection(s.x(), s.y(), t.x(), t.y(), f, r, u);
        }
        // Equirectangular strip: azimuth about `up` (positive to the left), elevation above.
        const Vec2 h = halfFieldRadians();
        return panoramaScreenDirection(s.x(), s.y(), h.x(), h.y(), f, r, u);
    }

    // Inverse of direction(): continuous image coordinates (x, y) of a viewing direction, with
    // pixel (i, j) covering [i, i+1) x [j, j+1). False if the direction is behind a pinhole.
    bool project(const Vec3& d, double& x, double& y) const {
        const Axes a = axes();
        const Vec3 &f = a.forward, &r = a.right, &u = a.up;
        double sx, sy;
        if (projection == Projection::Pinhole) {
            const Vec2 t = halfFieldTangents();
            const Vec3 h = pinholeHomogeneous(d, f, r, u, t.x(), t.y());
            if (h(2) <= 0) return false;
            sx = h(0) / h(2);
            sy = h(1) / h(2);
        } else {
            const Vec2 h = halfFieldRadians();
            const Vec2 s = panoramaScreen(d, f, r, u, h.x(), h.y());
            sx = s(0);
            sy = s(1);
        }
        x = 0.5 * (sx + 1) * width;
        y = 0.5 * (1 - sy) * height;
        return true;
    }
};

}  // namespace lc
