// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A null ray launched by an observer at an event along a chart direction (projected into the
// observer's rest space, as a camera reads `forward`, core/scene/frame_camera.hpp). Either way
// the ray runs along the direction as its affine parameter grows: past-directed, it is the ray the
// observer sees when looking that way, traced back towards its source; with `future`, it is the
// photon the observer sends that way. Its observed frequency is 1 (-p.u = 1 for the future ray).
// `lightcone trace --event --direction [--observer]` and Python's lightcone.trace launch with it.
#include "core/scene/frame_camera.hpp"

#include <algorithm>

namespace lc {

// `velocity` contravariant, future timelike (throws std::invalid_argument otherwise).
inline PhasePoint observerRay(const Spacetime& st, const Vec4& event, const Vec4& velocity, const Vec3& chartDirection,
                              bool future) {
    PhasePoint start;
    start.x = event;
    const LocalFrame f = LocalFrame::withVelocity(st, event, velocity);
    const Vec3 n = restSpaceComponents(st, f, chartDirection).normalized();
    // Past: k = -e0 + n e, lowered. Future: e0 + n e = -(-e0 - n e), the past ray along -n reversed.
    start.p = future ? Vec4(-f.pastNullMomentum(st, -n)) : f.pastNullMomentum(st, n);
    return start;
}

// The static observer's (along d/dt): throws where there is none (inside a horizon or ergoregion).
inline PhasePoint staticObserverRay(const Spacetime& st, const Vec4& event, const Vec3& chartDirection, bool future) {
    return observerRay(st, event, Vec4::Unit(0), chartDirection, future);
}

// Where a ray launched at `event` has escaped (asymptotically flat metrics): far beyond the
// launch point and never closer than 1000 M.
inline double escapeRadiusForRayFrom(const Vec4& event) { return std::max(1e3, 10 * event.tail<3>().norm()); }

}  // namespace lc
