// SPDX-License-Identifier: BSD-3-Clause
#include "core/sr/observer_camera.hpp"

#include "core/input/ranges.hpp"

#include <stdexcept>

namespace lc::sr {

void ObserverCamera::validate() const {
    Camera::validate();
    for (int k = 0; k < 3; ++k) input::kCoordinate.require(position(k), "camera position component");
    if (lookAt)
        throw std::invalid_argument(
            "special-relativity camera: look_at must be resolved into forward (lc::frameCamera)");
}

}  // namespace lc::sr
