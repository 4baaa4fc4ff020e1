// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The egocentric view's interactions as scene edits (so they are undoable, saved in sessions and
// checked by the scene reader like any other edit): look around, zoom, switch the projection,
// reset the view to the scene file's camera.
#include "readers/io/scene_edits.hpp"

#include <vector>

namespace lc::gui {

// A number the workbench computed (a zoomed field of view, a turned forward vector, a time from
// the slider) to 12 significant digits: 108.9, not 108.90000000000001, in the properties dock and
// the session, far below any pixel's angle or the slider's step.
double readableNumber(double value);

// A drag of (dx, dy) image pixels: the view follows the hand (dragging right turns the view
// left, as azimuth grows to the left), turning in the observer's rest space (lc::turnedForward);
// the forward vector never tilts onto the up axis. A camera with look_at turns away from it (the
// edits drop look_at and set forward).
std::vector<lc::io::SceneEdit> lookAroundEdits(const lc::Scene& scene, double dx, double dy);
// Wheel steps: +1 narrows the field of view by 10 %, -1 widens it, within the projection's limits.
lc::io::SceneEdit zoomEdit(const lc::Camera& camera, int steps);
// Projection and a field of view it accepts, together (either alone may be refused).
std::vector<lc::io::SceneEdit> projectionEdits(const lc::Camera& camera, bool panorama);
// The file's forward, up, field of view and projection again (empty when nothing differs).
std::vector<lc::io::SceneEdit> resetViewEdits(const lc::io::EditableScene& scene);

}  // namespace lc::gui
