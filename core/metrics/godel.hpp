// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include "core/spacetime/spacetime.hpp"

#include <limits>
#include <stdexcept>

namespace lc {

// Goedel rays never escape; one returns to the axis after at most 2 pi a of affine length, so
// following `windings` windings takes (windings + 1) 2 pi a (either chart).
inline double godelAffineLengthForWindings(double a, int windings) { return (windings + 1) * 2 * kPi * a; }

// Goedel universe, cylindrical chart of Kajari et al. (t, r, phi, z), u = (r/2a)^2:
//   ds^2 = dt^2 + 2 r^2/(sqrt2 a) dt dphi - dr^2/(1+u) - r^2 (1-u) dphi^2 - dz^2.
// Singular on the axis r = 0 (coordinate singularity): use GodelCartesian for numeric rays.
class GodelCylindrical final : public CodedMetric<GodelCylindrical> {
public:
    explicit GodelCylindrical(double a) : a_(a) {
        if (!(a > 0)) throw std::invalid_argument("Goedel: parameter a must be > 0");
    }
    std::string name() const override { return "godel-cylindrical"; }
    std::map<std::string, double> parameters() const override { return {{"a", a_}}; }
    std::array<std::string, 4> coordinateNames() const override { return {"t", "r", "phi", "z"}; }
    double a() const { return a_; }

    Mat4 inverseMetric(const Vec4& x) const override {  // closed form, docs/PHYSICS.md section 1
        const double r = x(1), u = r * r / (4 * a_ * a_);
        Mat4 gi = Mat4::Zero();
        gi(0, 0) = (1 - u) / (1 + u);
        gi(0, 2) = gi(2, 0) = 1 / (kSqrt2 * a_ * (1 + u));
        gi(2, 2) = -1 / (r * r * (1 + u));
        gi(1, 1) = -(1 + u);
        gi(3, 3) = -1;
        return gi;
    }

    template <class S>
    Eigen::Matrix<S, 4, 4> g(const Eigen::Matrix<S, 4, 1>& X) const {
        const S r = X(1);
        const S u = r * r / S(4 * a_ * a_);
        Eigen::Matrix<S, 4, 4> m = Eigen::Matrix<S, 4, 4>::Zero();
        m(0, 0) = S(1.0);
        m(0, 2) = m(2, 0) = r * r / S(kSqrt2 * a_);
        m(1, 1) = S(-1.0) / (S(1.0) + u);
        m(2, 2) = -r * r * (S(1.0) - u);
        m(3, 3) = S(-1.0);
        return m;
    }

private:
    double a_;
};

// The same spacetime in the chart (t, X, Y, z) with X = r cos phi, Y = r sin phi, which is
// smooth on the axis:
//   ds^2 = dt^2 + sqrt2/a dt (X dY - Y dX)
//          - [dX^2 + dY^2 - (X dX + Y dY)^2 / (4a^2 (1+u)) - (X dY - Y dX)^2 / (4a^2)] - dz^2.
class GodelCartesian final : public CodedMetric<GodelCartesian> {
public:
    explicit GodelCartesian(double a) : a_(a) {
        if (!(a > 0)) throw std::invalid_argument("Goedel: parameter a must be > 0");
    }
    std::string name() const override { return "godel"; }
    std::optional<double> godelRadius() const override { return a_; }
    std::map<std::string, double> parameters() const override { return {{"a", a_}}; }
    std::array<std::string, 4> coordinateNames() const override { return {"t", "x", "y", "z"}; }
    double a() const { return a_; }
    double affineLengthForWindings(int windings) const { return godelAffineLengthForWindings(a_, windings); }

    template <class S>
    Eigen::Matrix<S, 4, 4> g(const Eigen::Matrix<S, 4, 1>& P) const {
        const S &X = P(1), &Y = P(2);
        const double k = 1.0 / (4 * a_ * a_);
        const S u = (X * X + Y * Y) * S(k);
        const S c = S(k) / (S(1.0) + u);
        Eigen::Matrix<S, 4, 4> m = Eigen::Matrix<S, 4, 4>::Zero();
        m(0, 0) = S(1.0);
        m(0, 1) = m(1, 0) = -Y / S(kSqrt2 * a_);
        m(0, 2) = m(2, 0) = X / S(kSqrt2 * a_);
        m(1, 1) = -(S(1.0) - c * X * X - S(k) * Y * Y);
        m(2, 2) = -(S(1.0) - c * Y * Y - S(k) * X * X);
        m(1, 2) = m(2, 1) = c * X * Y - S(k) * X * Y;
        m(3, 3) = S(-1.0);
        return m;
    }

private:
    double a_;
};

// The affine length that follows `windings` windings of light in either Goedel chart; infinite
// for other metrics, whose rays end otherwise.
inline double affineLengthForWindings(const Spacetime& st, int windings) {
    if (const auto* g = dynamic_cast<const GodelCartesian*>(&st)) return godelAffineLengthForWindings(g->a(), windings);
    if (const auto* g = dynamic_cast<const GodelCylindrical*>(&st))
        return godelAffineLengthForWindings(g->a(), windings);
    return std::numeric_limits<double>::infinity();
}

}  // namespace lc
