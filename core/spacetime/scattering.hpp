// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Scattering of light by an asymptotically flat spacetime: rays sent in from far away with an
// exact impact parameter, and the total deflection measured from the turning of the spatial
// momentum (constant where spacetime is flat, so the far tails add only O(M b / D^2)).
#include "core/spacetime/integrator.hpp"

namespace lc {

// Future-directed null ray starting at x = -distance in the plane z = 0, moving along +x,
// whose impact parameter L/E = (x p_y - y p_x)/p_t equals b exactly (p_x = -1, p_y = p_z = 0,
// p_t from the null condition, y = b p_t solved by fixed-point iteration).
PhasePoint impactParameterRay(const Spacetime& st, double b, double distance);

struct DeflectionResult {
    TraceResult trace;
    double deflection = 0;    // net turning of the direction about the initial orbital normal (can exceed pi)
    double angleBetween = 0;  // angle between initial and final directions
    double impact = 0;        // L/E of the start state
};

DeflectionResult measureDeflection(const Spacetime& st, const PhasePoint& start, const TraceOptions& opt);

}  // namespace lc
