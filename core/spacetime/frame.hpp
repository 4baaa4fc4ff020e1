// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Local orthonormal frames (tetrads) and the map from a viewing direction to a null momentum.
#include "core/spacetime/spacetime.hpp"

#include <array>
#include <optional>

namespace lc {

// k = -e0 + n^i e_i lowered with g (rows of g at the frame's event): the covariant momentum of
// the past-directed null ray seen along unit frame direction n. For every scalar:
// LocalFrame::pastNullMomentum calls it in double, the GPU tracer's lcPastNullMomentum is
// generated from it.
template <class S>
Eigen::Matrix<S, 4, 1> pastNullMomentumAlong(const Eigen::Matrix<S, 3, 1>& n,
                                             const std::array<Eigen::Matrix<S, 4, 1>, 4>& e,
                                             const Eigen::Matrix<S, 4, 4>& g) {
    const Eigen::Matrix<S, 4, 1> k = -e[0] + n(0) * e[1] + n(1) * e[2] + n(2) * e[3];
    return g * k;
}

// e[0] = observer 4-velocity (g(e0,e0) = +1), e[1..3] spatial (g(ei,ei) = -1), all
// contravariant coordinate components. Built by Gram-Schmidt from u and the coordinate
// directions d/dx^1, d/dx^2, d/dx^3, so at a point where the metric is diag(1,-1,-1,-1) and u
// is d/dt the frame is the coordinate frame.
struct LocalFrame {
    Vec4 x = Vec4::Zero();
    std::array<Vec4, 4> e;

    // Static observer (u along d/dt); throws if d/dt is not timelike there.
    static LocalFrame staticObserver(const Spacetime& st, const Vec4& x);
    // Observer with the given 4-velocity (normalised here; must be future timelike).
    static LocalFrame withVelocity(const Spacetime& st, const Vec4& x, const Vec4& u);
    // The same Gram-Schmidt with g given, asking only that u be timelike (nullopt otherwise, or
    // where no spatial vector can be built): beyond the Goedel horizon a future-directed world
    // line may run backwards in the chart's t (the time traveller), so u^t > 0 is not asked.
    static std::optional<LocalFrame> fromMetric(const Mat4& g, const Vec4& x, const Vec4& u);

    // Covariant momentum of the past-directed null ray that the observer sees when looking
    // along unit spatial direction n (frame components): k = -e0 + n^i e_i, lowered with g.
    // The photon arriving has future momentum -k with g(-k, e0) = 1 (unit observed frequency).
    Vec4 pastNullMomentum(const Spacetime& st, const Vec3& n) const;
    // Frame components (n^1, n^2, n^3) of the direction a (past-directed) momentum points to.
    Vec3 directionOf(const Spacetime& st, const Vec4& pCovariant) const;
    // The chart vector w^i e_i of the spatial direction with frame components w.
    Vec4 spatialVector(const Vec3& w) const { return w(0) * e[1] + w(1) * e[2] + w(2) * e[3]; }
};

}  // namespace lc
