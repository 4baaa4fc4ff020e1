// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The special-relativity renderers' camera: the project's one camera model (lc::Camera,
// core/scene/camera.hpp: projection, both fields of view, pixel <-> direction) placed at the
// observer's position in S. The observer rests in S, whose chart frame is orthonormal, so forward
// and up are S directions as they stand.
#include "core/scene/camera.hpp"

namespace lc::sr {

struct ObserverCamera : Camera {
    Vec3 position = Vec3::Zero();

    // Camera::validate, a finite position, and no look_at left to resolve (lc::frameCamera turns
    // a scene's look_at into forward). Throws std::invalid_argument naming the value.
    void validate() const;
    bool operator==(const ObserverCamera& o) const { return Camera::operator==(o) && position == o.position; }
    bool operator!=(const ObserverCamera& o) const { return !(*this == o); }
    // Pixel coordinates of a point of S; false if a pinhole has it behind the camera.
    bool projectPoint(const Vec3& point, double& x, double& y) const { return project(point - position, x, y); }
};

}  // namespace lc::sr
