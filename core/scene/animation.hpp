// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A path through scenes, one scene per frame (`lightcone animate`, a scene's "animation" block):
// the observer's proper time along its world line, the camera turned (pan), the observer carried
// round the chart's z axis (orbit), a numeric field of the scene file swept; several at once
// when they have the same number of frames.
#include "core/scene/observer_world_line.hpp"

#include <optional>
#include <string>

namespace lc {

// FROM to TO over FRAMES frames, both ends included (one frame: FROM).
struct FrameInterval {
    double from = 0, to = 0;
    int frames = 1;
    double at(int frame) const { return frames == 1 ? from : from + (to - from) * frame / (frames - 1); }
};

struct FieldSweep {
    std::string field;  // a scene-file field path, "metric.a", "objects[0].centre[1]"
    FrameInterval values;
};

struct AnimationPath {
    std::optional<FrameInterval> properTime;    // the observer's proper time from its scene event
    std::optional<ObserverMotion> motion;       // how it moves; default from its velocity
    std::optional<FrameInterval> panDegrees;    // the camera turned about its up direction (+: left)
    std::optional<FrameInterval> orbitDegrees;  // the observer carried about the chart's z axis
    std::optional<FieldSweep> sweep;
    bool still = false;  // no path: one frame, the scene as it is (a render over MPI ranks)

    bool empty() const { return !properTime && !panDegrees && !orbitDegrees && !sweep && !still; }
    // The common number of frames; throws std::invalid_argument when no path is given or their
    // counts differ.
    int frames() const;
    // Only the camera turns: every frame sees the same past light cone (photo-objects built once).
    bool cameraOnly() const { return (still || panDegrees) && !properTime && !orbitDegrees && !sweep; }
};

}  // namespace lc
