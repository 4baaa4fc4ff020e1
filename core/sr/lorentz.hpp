// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Lorentz boosts and the Poincare map between the observer frame S and a frame S' moving
// with constant velocity. Signature (+,-,-,-), c = 1, events are (t, x, y, z).
#include "core/numerics/types.hpp"

#include <cmath>

namespace lc::sr {

// gamma = 1 / sqrt(1 - beta^2), for every scalar (double; codegen::Expr in the shaders' boosts):
// the one place the Lorentz factor is written.
template <class S>
S lorentzFactor(const Eigen::Matrix<S, 3, 1>& beta) {
    using std::sqrt;
    return S(1.0) / sqrt(S(1.0) - beta.squaredNorm());
}
// The same, checked: throws std::invalid_argument unless |beta| < 1.
double lorentzGamma(const Vec3& beta);

// Minkowski metric eta = diag(1, -1, -1, -1).
Mat4 minkowskiMetric();

// Boost of seed 003 eq. 2 / docs/PHYSICS.md section 6:
//   Lambda(beta) = [[gamma, gamma beta^T], [gamma beta, 1 + gamma^2/(gamma+1) beta beta^T]].
// Maps coordinates of S' (moving with velocity beta relative to S) to S.
// Throws std::invalid_argument unless |beta| < 1.
Mat4 boost(const Vec3& beta);
// Inverse boost: Lambda(beta)^-1 = Lambda(-beta).
inline Mat4 inverseBoost(const Vec3& beta) { return boost(-beta); }

// Composition Lambda(outer) Lambda(inner): a boost followed by a rotation (Thomas-Wigner)
// unless the velocities are parallel; it maps S'' -> S' -> S.
inline Mat4 composeBoosts(const Vec3& outer, const Vec3& inner) { return boost(outer) * boost(inner); }

// Relativistic velocity addition: velocity in S of a body moving with u in S', where S'
// moves with v relative to S (the spatial direction of Lambda(v) applied to gamma_u (1, u)).
Vec3 addVelocities(const Vec3& v, const Vec3& u);

// Minkowski product a^T eta b.
inline double minkowskiDot(const Vec4& a, const Vec4& b) {
    return a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
}

// Inertial frame S' of a moving object: at t = t' = 0 its origin is at `origin` in S, and it
// moves with constant velocity beta. Poincare map (seed 003 eq. 1):
//   x = Lambda(beta) x' + a,  x' = Lambda(-beta) (x - a),  a = (0, origin).
class MovingFrame {
public:
    explicit MovingFrame(const Vec3& beta = Vec3::Zero(), const Vec3& origin = Vec3::Zero());
    // The frame whose origin passes the event (t, x) of S: at t = 0 it is at x - beta t.
    static MovingFrame throughEvent(const Vec3& beta, const Vec4& event) {
        return MovingFrame(beta, event.tail<3>() - beta * event(0));
    }

    const Vec3& beta() const { return beta_; }
    const Vec3& origin() const { return origin_; }
    double gamma() const { return gamma_; }
    const Mat4& toObserverMatrix() const { return L_; }
    const Mat4& toRestMatrix() const { return Linv_; }

    // Events (affine).
    Vec4 eventToObserver(const Vec4& xRest) const;
    Vec4 eventToRest(const Vec4& xObserver) const;
    // Four-vectors (linear: wave vectors, velocities).
    Vec4 vectorToObserver(const Vec4& kRest) const { return L_ * kRest; }
    Vec4 vectorToRest(const Vec4& k) const { return Linv_ * k; }

private:
    Vec3 beta_, origin_;
    double gamma_;
    Mat4 L_, Linv_;
};

}  // namespace lc::sr
