// SPDX-License-Identifier: BSD-3-Clause
#include "core/scene/star_sky.hpp"

#include "core/colour/blackbody.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace lc {

std::vector<Star> randomStars(const StarFieldRecipe& recipe) {
    // std::mt19937 is the same sequence everywhere; the distributions are written out because
    // std::uniform_real_distribution's are not.
    std::mt19937 engine(recipe.seed);
    auto uniform = [&] { return (engine() + 0.5) / 4294967296.0; };  // (0, 1)
    const double logMin = std::log(recipe.minTemperature), logMax = std::log(recipe.maxTemperature);
    // N(< m) ~ 10^(0.6 m) on [0, m_max]: m = m_max + log10(q + (1 - q) U) / 0.6, q = 10^(-0.6 m_max).
    const double q = std::pow(10.0, -0.6 * recipe.faintestMagnitude);
    std::vector<Star> stars(static_cast<std::size_t>(recipe.stars));
    for (Star& s : stars) {
        const double z = 2 * uniform() - 1, phi = 2 * kPi * uniform(), rho = std::sqrt(std::max(0.0, 1 - z * z));
        s.direction = Vec3(rho * std::cos(phi), rho * std::sin(phi), z);
        s.temperature = std::exp(logMin + (logMax - logMin) * uniform());
        const double m = recipe.faintestMagnitude + std::log10(q + (1 - q) * uniform()) / 0.6;
        s.brightness = std::pow(10.0, -0.4 * std::max(0.0, m));
    }
    return stars;
}

namespace {

// The direction through the centre of texel (i, j) of a w x h equirectangular map (lc::skyUv).
Vec3 texelDirection(int i, int j, int w, int h) {
    const double phi = 2 * kPi * ((i + 0.5) / w - 0.5), theta = kPi * (j + 0.5) / h;
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

// Each star a Gaussian of standard deviation sigma (radians) in the angle from its direction, cut
// at 4 sigma, added to the texels it covers.
void splatStars(LightMap& map, const std::vector<Star>& stars, double sigma) {
    const int w = map.width, h = map.height;
    const double reach = 4 * sigma, dTheta = kPi / h;
    for (const Star& s : stars) {
        const double theta = std::acos(std::clamp(s.direction(2), -1.0, 1.0));
        const double phi = std::atan2(s.direction(1), s.direction(0));
        const int j0 = std::max(0, static_cast<int>(std::floor((theta - reach) / dTheta - 0.5)));
        const int j1 = std::min(h - 1, static_cast<int>(std::ceil((theta + reach) / dTheta - 0.5)));
        // The narrowest circle of latitude the star reaches sets how far round it spreads.
        const double sinEdge = std::min(std::sin(std::max(theta - reach, 0.0)), std::sin(std::min(theta + reach, kPi)));
        const bool wholeRow = theta - reach <= 0 || theta + reach >= kPi || reach >= sinEdge;
        const double dPhi = wholeRow ? kPi : std::asin(std::sin(reach) / sinEdge);
        const double centre = (phi / (2 * kPi) + 0.5) * w - 0.5, spread = dPhi / (2 * kPi) * w + 1;
        const int i0 = wholeRow ? 0 : static_cast<int>(std::floor(centre - spread));
        const int i1 = wholeRow ? w - 1 : static_cast<int>(std::ceil(centre + spread));
        for (int j = j0; j <= j1; ++j)
            for (int k = i0; k <= i1; ++k) {
                const int i = ((k % w) + w) % w;
                const double chord = (texelDirection(i, j, w, h) - s.direction).norm();
                const double angle = 2 * std::asin(std::min(1.0, 0.5 * chord));
                if (angle > reach) continue;
                const double b = s.brightness * std::exp(-0.5 * angle * angle / (sigma * sigma));
                float* t = &map.texels[2 * (static_cast<std::size_t>(j) * w + i)];
                t[0] += static_cast<float>(b);
                t[1] += static_cast<float>(b * s.temperature);
            }
    }
}

}  // namespace

StarSky::StarSky(std::vector<Star> stars, double sizeDegrees) : stars_(std::move(stars)), sizeDegrees_(sizeDegrees) {
    if (!(sizeDegrees >= 0.1 && sizeDegrees <= 90))
        throw std::invalid_argument("StarSky: a star size in [0.1, 90] degrees (the map's texels are half of it)");
    map_.width = 2 * static_cast<int>(std::ceil(360 / sizeDegrees));
    map_.height = map_.width / 2;
    map_.texels.assign(2 * static_cast<std::size_t>(map_.width) * map_.height, 0.0f);
    splatStars(map_, stars_, sizeDegrees * kPi / 180);
}

Vec3 StarSky::sample(double u, double v) const {
    const LightMap::Light light = map_.at(u, v);
    if (!(light.brightness > 0)) return Vec3::Zero();
    return colour::standardBlackbodyTable()->lookupLinear(light.temperature, colour::ToneMap::ColourOnly) *
           light.brightness;
}

}  // namespace lc
