// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Where the observer is after a proper time tau along its world line, and its 4-velocity there:
// what `lightcone animate --proper-time` puts at each frame. Objects move on their own world
// lines, so each frame's image is the past light cone of the observer's event at that frame.
#include "core/spacetime/integrator.hpp"

#include <string>
#include <vector>

namespace lc {

enum class ObserverMotion {
    Static,   // on the orbit of d/dt through the start event (at rest in the chart; hovering)
    FreeFall  // on the timelike geodesic with the start velocity
};
// "static", "free_fall"; throws listing them.
ObserverMotion parseObserverMotion(const std::string& name);
std::string observerMotionName(ObserverMotion motion);
// Static for an observer at rest in the chart (zero spatial velocity), FreeFall otherwise.
ObserverMotion defaultObserverMotion(const Vec4& velocity);

struct ObserverEvent {
    Vec4 position;
    Vec4 velocity;  // contravariant, g(u, u) = +1
};

// The observer's events at the proper times `taus` (any order and sign; 0 is the start event).
// Static: dt/dtau = 1/sqrt(g_tt) integrated along the orbit (constant where d/dt is a Killing
// field), which needs d/dt timelike there. FreeFall: the geodesic of H = g^{mu nu} p p / 2 = 1/2
// integrated with `options` (stepper and tolerances), so its affine parameter is the proper time.
// Throws std::invalid_argument naming the proper time at which the world line cannot go on (a
// horizon, a singularity, d/dt no longer timelike).
std::vector<ObserverEvent> observerWorldLine(const Spacetime& spacetime, const Vec4& start, const Vec4& velocity,
                                             ObserverMotion motion, const std::vector<double>& taus,
                                             const TraceOptions& options);

}  // namespace lc
