#pragma once
// Local orthonormal frames (tetrads) and the map from a viewing direction to a null momentum.
#include "core/spacetime/spacetime.hpp"

namespace lc {

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

    // Covariant momentum of the past-directed null ray that the observer sees when looking
    // along unit spatial direction n (frame components): k = -e0 + n^i e_i, lowered with g.
    // The photon arriving has future momentum -k with g(-k, e0) = 1 (unit observed frequency).
    Vec4 pastNullMomentum(const Spacetime& st, const Vec3& n) const;
    // Frame components (n^1, n^2, n^3) of the direction a (past-directed) momentum points to.
    Vec3 directionOf(const Spacetime& st, const Vec4& pCovariant) const;
};

}  // namespace lc
