// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Basic vector types of the physics core. Plain Eigen, no VTK or Qt.
#include <Eigen/Dense>
#include <cmath>

namespace lc {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Matrix<double, 4, 1>;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix<double, 4, 4>;

constexpr double kPi = 3.14159265358979323846;
constexpr double kSqrt2 = 1.41421356237309504880;

// Phase-space state of a geodesic: position x^mu and covariant momentum p_mu.
struct PhasePoint {
    Vec4 x = Vec4::Zero();
    Vec4 p = Vec4::Zero();
};

}  // namespace lc
