#pragma once
// A null ray launched by the static observer at an event along a chart direction (as the camera
// reads directions, core/scene/frame_camera.hpp): past-directed, or future-directed with `future`.
// Its momentum is non-finite where no static observer exists (inside a horizon or ergoregion).
// `lightcone trace --event --direction` and Python's lightcone.trace launch their rays with it.
#include "core/scene/frame_camera.hpp"

#include <algorithm>

namespace lc {

inline PhasePoint staticObserverRay(const Spacetime& st, const Vec4& event, const Vec3& chartDirection, bool future) {
    PhasePoint start;
    start.x = event;
    const LocalFrame f = LocalFrame::staticObserver(st, event);
    start.p = f.pastNullMomentum(st, restSpaceComponents(st, f, chartDirection));
    if (future) start.p = -st.metric(event) * (st.inverseMetric(event) * start.p);  // the same ray, reversed
    return start;
}

// Where a ray launched at `event` has escaped (asymptotically flat metrics): far beyond the
// launch point and never closer than 1000 M.
inline double escapeRadiusForRayFrom(const Vec4& event) { return std::max(1e3, 10 * event.tail<3>().norm()); }

}  // namespace lc
