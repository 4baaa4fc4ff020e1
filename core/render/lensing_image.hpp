// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The lensing channels of a render with ray bundles (RenderSettings::magnification) drawn as a
// picture, `shade --show`: where the images are magnified, stretched or turned, and the critical
// curves where the magnification diverges.
#include "core/render/render.hpp"

#include <string>
#include <vector>

namespace lc {

enum class LensingQuantity { Magnification, Shear, Rotation };
// "magnification", "shear" or "rotation"; throws std::invalid_argument naming them.
LensingQuantity parseLensingQuantity(const std::string& name);

// Linear RGB, row 0 on top. Magnification: log10 |mu| from -1 to 2 (0.1x to 100x) from black to
// white for images of kept parity, to light blue for mirrored ones (mu < 0). Shear |gamma| from 0
// to 1, black to white. Rotation from -10 to +10 degrees, blue through white to red. Pixels without
// a map (no source: horizon, failed, background) are black. Throws when r has no lensing channels.
std::vector<float> lensingImage(const RenderResult& r, LensingQuantity quantity);

}  // namespace lc
