// SPDX-License-Identifier: BSD-3-Clause
#include "core/sr/lorentz.hpp"

#include <cmath>
#include <stdexcept>

namespace lc::sr {

double lorentzGamma(const Vec3& beta) {
    if (!(beta.squaredNorm() < 1.0)) throw std::invalid_argument("lorentzGamma: |beta| must be < 1");
    return lorentzFactor<double>(beta);
}

Mat4 minkowskiMetric() { return Vec4(1.0, -1.0, -1.0, -1.0).asDiagonal(); }

Mat4 boost(const Vec3& beta) {
    const double g = lorentzGamma(beta);
    Mat4 L;
    L(0, 0) = g;
    L.block<1, 3>(0, 1) = g * beta.transpose();
    L.block<3, 1>(1, 0) = g * beta;
    L.block<3, 3>(1, 1) = Eigen::Matrix3d::Identity() + (g * g / (g + 1.0)) * beta * beta.transpose();
    return L;
}

Vec3 addVelocities(const Vec3& v, const Vec3& u) {
    const Vec4 U = boost(v) * (lorentzGamma(u) * Vec4(1.0, u.x(), u.y(), u.z()));
    return U.tail<3>() / U[0];
}

MovingFrame::MovingFrame(const Vec3& beta, const Vec3& origin)
    : beta_(beta), origin_(origin), gamma_(lorentzGamma(beta)), L_(boost(beta)), Linv_(boost(-beta)) {}

Vec4 MovingFrame::eventToObserver(const Vec4& xRest) const {
    Vec4 x = L_ * xRest;
    x.tail<3>() += origin_;
    return x;
}

Vec4 MovingFrame::eventToRest(const Vec4& x) const {
    Vec4 d = x;
    d.tail<3>() -= origin_;
    return Linv_ * d;
}

}  // namespace lc::sr
