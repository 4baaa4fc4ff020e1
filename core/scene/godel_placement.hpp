// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A static object in the Goedel universe lives in the local chart of its centre: the
// isometry that moves its centre event to the origin maps events to that chart, where the
// metric is Minkowski at the origin. By homogeneity an object then has the same shape
// wherever it is put.
#include "core/godel/isometry.hpp"
#include "core/scene/scene.hpp"

namespace lc {

class GodelPlacement final : public Placement {
public:
    GodelPlacement(double a, const Vec4& centre) : toCentre_(godel::Isometry::movingToOrigin(a, centre)) {}
    Vec3 toLocal(const Vec4& x) const override { return toCentre_.apply(x).tail<3>(); }

private:
    godel::Isometry toCentre_;
};

}  // namespace lc
