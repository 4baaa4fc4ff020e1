// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A sky of stars, each a black body of its own temperature (issue 50): what a falling observer
// sees shifted star by star, g T with brightness g^4. The stars are spread on an equirectangular
// map (lc::skyUv's u, v) of brightness b and b T, each a small Gaussian, so that the map's bilinear
// blend gives the brightness and the brightness-weighted temperature in every direction. The CPU
// shading samples it (LightMap::at), the GPU uploads the same texels as a float texture.
#include "core/scene/texture.hpp"

#include <cstdint>
#include <vector>

namespace lc {

struct Star {
    Vec3 direction;          // unit, chart components (x, y, z)
    double temperature = 0;  // K, as a static observer at infinity measures it
    double brightness = 0;   // linear, the Gaussian's peak: 1 is white at rest
};

// The random field of `stars` stars: directions uniform on the sphere, temperatures uniform in
// log T over [minTemperature, maxTemperature], magnitudes from 0 to faintestMagnitude distributed
// as stars of one kind spread evenly through space (N(< m) ~ 10^(0.6 m)), brightness 10^(-0.4 m).
struct StarFieldRecipe {
    int stars = 2000;
    std::uint32_t seed = 1;
    double minTemperature = 3000, maxTemperature = 30000;
    double faintestMagnitude = 6;
};
std::vector<Star> randomStars(const StarFieldRecipe& recipe);

class StarSky final : public Texture {
public:
    // sizeDegrees: the Gaussian's standard deviation. The map has two texels to a size (bilinear
    // then follows the Gaussian within 3 % of its peak): 360 / size x 2 round the equator.
    StarSky(std::vector<Star> stars, double sizeDegrees);
    // The rest colour: the Planck colour of T (hue only) times b, what a static observer at
    // infinity sees; every path that knows no frequency shift draws this.
    Vec3 sample(double u, double v) const override;
    const LightMap* lightMap() const override { return &map_; }
    const std::vector<Star>& stars() const { return stars_; }
    double sizeDegrees() const { return sizeDegrees_; }

private:
    std::vector<Star> stars_;
    double sizeDegrees_;
    LightMap map_;
};

}  // namespace lc
