// SPDX-License-Identifier: BSD-3-Clause
#include "core/render/lensing_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace lc {

LensingQuantity parseLensingQuantity(const std::string& name) {
    if (name == "magnification") return LensingQuantity::Magnification;
    if (name == "shear") return LensingQuantity::Shear;
    if (name == "rotation") return LensingQuantity::Rotation;
    throw std::invalid_argument("unknown lensing quantity '" + name + "' (magnification, shear or rotation)");
}

namespace {

std::array<float, 3> lensingColour(const PixelRecord& p, LensingQuantity q) {
    if (p.magnification == 0) return {0, 0, 0};
    switch (q) {
        case LensingQuantity::Magnification: {
            const float t = std::clamp((std::log10(std::abs(p.magnification)) + 1) / 3, 0.0f, 1.0f);
            return p.magnification > 0 ? std::array<float, 3>{t, t, t} : std::array<float, 3>{0.35f * t, 0.6f * t, t};
        }
        case LensingQuantity::Shear: {
            const float t = std::clamp(p.shear, 0.0f, 1.0f);
            return {t, t, t};
        }
        case LensingQuantity::Rotation: {
            const float t = std::clamp(p.rotation / static_cast<float>(10 * kPi / 180), -1.0f, 1.0f);
            return t >= 0 ? std::array<float, 3>{1, 1 - t, 1 - t} : std::array<float, 3>{1 + t, 1 + t, 1};
        }
    }
    return {0, 0, 0};
}

}  // namespace

std::vector<float> lensingImage(const RenderResult& r, LensingQuantity quantity) {
    if (!r.lensing)
        throw std::invalid_argument(
            "the pixel data has no lensing channels (hint: render it with --magnification or the scene's "
            "render.magnification)");
    std::vector<float> rgb(3 * r.pixels.size());
    for (std::size_t n = 0; n < r.pixels.size(); ++n) {
        const auto c = lensingColour(r.pixels[n], quantity);
        std::copy(c.begin(), c.end(), rgb.begin() + static_cast<std::ptrdiff_t>(3 * n));
    }
    return rgb;
}

}  // namespace lc
