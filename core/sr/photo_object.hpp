// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Photo-objects (seed 003 sect. 3.2, eq. 5-8): where an observer at rest in S sees a point
// that is at rest in a moving frame S'.
#include <vector>

#include "core/sr/lorentz.hpp"

namespace lc::sr {

// Event (in S') at which the point at rest at xRest in S' emits the light that reaches the
// observer event `observer` (in S): x'_obs = Lambda(-beta)(x_obs - a) (eq. 5), then the
// backward light cone t'_P = t'_obs - |x'_P - x'_obs| (eq. 7).
Vec4 emissionEventRest(const MovingFrame& frame, const Vec3& xRest, const Vec4& observer);

// The same event in S (eq. 8); its spatial part is the apparent position.
Vec4 emissionEvent(const MovingFrame& frame, const Vec3& xRest, const Vec4& observer);

inline Vec3 apparentPosition(const MovingFrame& frame, const Vec3& xRest, const Vec4& observer) {
    return emissionEvent(frame, xRest, observer).tail<3>();
}

// Apparent positions of all mesh vertices (the polygon-distortion vertex transform).
std::vector<Vec3> apparentPositions(const MovingFrame& frame, const std::vector<Vec3>& restVertices,
                                    const Vec4& observer);

}  // namespace lc::sr
