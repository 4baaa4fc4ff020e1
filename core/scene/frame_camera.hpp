// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene gives the camera's `forward` and `up` as chart directions: spatial vectors v^i d/dx^i at
// the observer's event. The renderers look through the observer's local frame (LocalFrame). The
// camera's frame is the observer's view of those vectors: each is projected into the rest space
// of the observer's 4-velocity u, forward is normalised first, then up is made orthogonal to it,
// all with the metric (docs/SCENES.md, docs/PHYSICS.md section "Camera frame"). So the image
// centre is the physical direction of the chart vector `forward` for any metric, position and
// observer velocity.
#include "core/scene/scene.hpp"
#include "core/spacetime/frame.hpp"

namespace lc {

// Frame components (n^1, n^2, n^3) of the rest-space projection of the chart vector (0, v):
// n^i = -g(v, e_i), since g(e_i, e_i) = -1 and g(e_0, e_i) = 0. Not normalised.
Vec3 restSpaceComponents(const Spacetime& st, const LocalFrame& frame, const Vec3& chartVector);

// The inverse: the spatial chart vector (0, v) whose rest-space projection has frame components
// n (converts cameras given in frame components, e.g. version-1 sessions).
Vec3 chartVectorOf(const Spacetime& st, const LocalFrame& frame, const Vec3& frameComponents);

// The camera with forward and up as frame components (what Camera::direction and project use).
// Throws std::invalid_argument when forward and up are parallel in the observer's rest space.
Camera frameCamera(const Camera& chartCamera, const Spacetime& st, const LocalFrame& frame);
// The same for the scene's observer (its 4-velocity, static when at rest).
LocalFrame observerFrame(const Scene& scene);
Camera frameCamera(const Scene& scene);

// The scene camera's forward turned by `yaw` radians about its up (positive to the left), then
// by `pitch` about its right (positive up, skipped where it would tilt onto the up axis), as the
// observer sees the turn (in its rest space), as a chart direction again (pans, look-around).
Vec3 turnedForward(const Scene& scene, double yaw, double pitch = 0);

// The chart direction from the observer towards the spatial position `target` (look_at): the
// difference of chart coordinates. Throws when the target is the observer's own position.
Vec3 lookAtDirection(const Vec4& observer, const Vec3& target);

}  // namespace lc
