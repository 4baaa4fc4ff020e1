// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// How far a numeric render's image can be trusted, in the unit a user reads it: pixels. A sample
// of the image's rays (a grid of perSide x perSide pixels) is traced again with a tolerance 100
// times tighter; for each ray that escaped both times, the angle between the two escape
// directions is the first run's error in where it looks up the sky, in pixels of the camera. A few
// dozen rays: well under 1 % of a render's cost (docs/PHYSICS.md section 9a).
#include "core/scene/scene.hpp"

#include <array>
#include <limits>
#include <vector>

namespace lc {

struct RenderErrorEstimate {
    std::vector<std::array<int, 2>> pixels;  // the sampled rays that escaped both times
    std::vector<double> errorPixels;         // their escape directions' difference, in pixels
    double tighterTolerance = 0;
    double medianPixels() const;
    double maxPixels() const;  // NaN when no sampled ray escaped
};

// Numeric renders of asymptotically flat metrics (others: an empty estimate).
RenderErrorEstimate estimateRenderError(const Scene& scene, int perSide = 8);

// A numeric render of an asymptotically flat metric whose escape angle is above pi: each ray stops
// as escaped once its fate is known, with its bending still ahead, so there is no settled
// direction to estimate (estimateRenderError returns none; the render's report says why).
bool escapeDirectionsUnsettled(const Scene& scene);

}  // namespace lc
