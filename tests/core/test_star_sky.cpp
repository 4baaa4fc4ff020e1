// SPDX-License-Identifier: BSD-3-Clause
// A sky of black-body stars (core/scene/star_sky, issue 50): the map holds each star's brightness
// and temperature where the star is, wherever it is (the poles, the seam of u); the random field
// follows its distributions; and an observer falling into Schwarzschild sees every star at its
// own shifted temperature g T and brightness g^4 b, with g the closed-form Doppler-shifted static
// shift and the colour Planck's law integrated directly (colour::blackbodySrgb), not the table.
#include "core/colour/blackbody.hpp"
#include "core/colour/srgb.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/render/render.hpp"
#include "core/scene/frame_camera.hpp"
#include "core/scene/sky.hpp"
#include "core/scene/star_sky.hpp"
#include "core/spacetime/named_observer.hpp"
#include "tests/common/test_camera.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace lc;

namespace {

Vec3 skyDirection(double u, double v) {
    const double phi = 2 * kPi * (u - 0.5), theta = kPi * v;
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

double angleBetween(const Vec3& a, const Vec3& b) { return 2 * std::asin(std::min(1.0, 0.5 * (a - b).norm())); }

// A star's light at angle alpha from it: the Gaussian of the documented size (docs/SCENES.md).
double gaussian(double peak, double alpha, double sizeDegrees) {
    const double sigma = sizeDegrees * kPi / 180;
    return peak * std::exp(-0.5 * alpha * alpha / (sigma * sigma));
}

}  // namespace

// Hard cases: a star on each pole (every u is the same direction), one on the seam where u wraps,
// one just off the equator; each alone, so the map's brightness-weighted temperature is its own.
TEST(StarSky, EachStarsLightPeaksAtItsDirectionWithItsOwnTemperature) {
    const double size = 0.5;
    const std::vector<Star> stars = {{Vec3(0, 0, 1), 3500, 1.0},
                                     {Vec3(0, 0, -1), 25000, 0.5},
                                     {Vec3(-1, 1e-9, 0).normalized(), 6000, 0.8},
                                     {Vec3(-1, -1e-9, 0.2).normalized(), 9000, 0.3},
                                     {Vec3(0.3, 0.9, 0.1).normalized(), 12000, 0.05}};
    const StarSky sky(stars, size);
    ASSERT_NE(sky.lightMap(), nullptr);
    for (const Star& s : stars) {
        const Vec2 uv = skyUv(s.direction);
        const LightMap::Light l = sky.lightMap()->at(uv(0), uv(1));
        EXPECT_NEAR(l.temperature, s.temperature, 1e-5 * s.temperature) << s.direction.transpose();
        // The Gaussian sampled at texel centres two to a star size and blended bilinearly: within
        // (1/8) (texel / size)^2 of the peak along each axis, 7 % in all.
        EXPECT_NEAR(l.brightness, s.brightness, 0.07 * s.brightness) << s.direction.transpose();
        // Half a size away: the Gaussian's value; the colour is the Planck hue times the brightness.
        const Vec3 aside = (s.direction + 0.5 * size * kPi / 180 * s.direction.unitOrthogonal()).normalized();
        const Vec2 uvAside = skyUv(aside);
        const LightMap::Light la = sky.lightMap()->at(uvAside(0), uvAside(1));
        const double expected = gaussian(s.brightness, angleBetween(aside, s.direction), size);
        EXPECT_NEAR(la.brightness, expected, 0.07 * s.brightness) << s.direction.transpose();
        const Vec3 rest = sky.sample(uv(0), uv(1)),
                   planck = colour::blackbodySrgb(s.temperature, colour::ToneMap::ColourOnly);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(rest(c), colour::srgbDecode(planck(c)) * l.brightness, 2e-3) << s.direction.transpose();
    }
    // Far from every star: no light, and no temperature.
    const Vec2 empty = skyUv(Vec3(1, -1, 0.5).normalized());
    EXPECT_EQ(sky.lightMap()->at(empty(0), empty(1)).brightness, 0);
    EXPECT_EQ(sky.sample(empty(0), empty(1)), Vec3::Zero());
}

// 40000 stars: uniform on the sphere (mean direction near 0, a third of the stars within 0.33 of
// each axis' |cos|), temperatures uniform in log T (median sqrt(Tmin Tmax)), magnitudes with
// N(< m) ~ 10^(0.6 m): the stars brighter than m_max - 1 are 10^-0.6 = 25 % of all.
TEST(StarSky, RandomStarsFollowTheirDistributions) {
    StarFieldRecipe recipe;
    recipe.stars = 40000;
    recipe.seed = 7;
    recipe.minTemperature = 2000;
    recipe.maxTemperature = 32000;
    recipe.faintestMagnitude = 6;
    const std::vector<Star> stars = randomStars(recipe);
    ASSERT_EQ(stars.size(), 40000u);
    Vec3 mean = Vec3::Zero();
    std::vector<double> temperatures;
    int brighter = 0, polar = 0;
    for (const Star& s : stars) {
        EXPECT_NEAR(s.direction.norm(), 1, 1e-12);
        EXPECT_GE(s.temperature, 2000);
        EXPECT_LE(s.temperature, 32000);
        EXPECT_GE(s.brightness, std::pow(10.0, -0.4 * 6) * (1 - 1e-12));
        EXPECT_LE(s.brightness, 1);
        mean += s.direction;
        temperatures.push_back(s.temperature);
        if (s.brightness > std::pow(10.0, -0.4 * 5)) ++brighter;
        if (std::abs(s.direction(2)) > 2.0 / 3) ++polar;
    }
    EXPECT_LT((mean / 40000).norm(), 0.02);
    EXPECT_NEAR(polar / 40000.0, 1.0 / 3, 0.01);  // uniform in z = cos(theta)
    std::nth_element(temperatures.begin(), temperatures.begin() + 20000, temperatures.end());
    EXPECT_NEAR(temperatures[20000], 8000, 250);  // sqrt(2000 x 32000)
    EXPECT_NEAR(brighter / 40000.0, (std::pow(10.0, -0.6) - std::pow(10.0, -3.6)) / (1 - std::pow(10.0, -3.6)), 0.01);
    // The same seed, the same stars; another seed, others.
    EXPECT_EQ(randomStars(recipe).back().direction, stars.back().direction);
    recipe.seed = 8;
    EXPECT_NE(randomStars(recipe).back().direction, stars.back().direction);
}

// Falling from rest at infinity into Schwarzschild at r = 4 M, a whole-sky panorama: the sky's
// frequency ratio along frame direction d is the static 1/sqrt(1 - 2M/r) Doppler-shifted by the
// infall speed beta = sqrt(2M/r) (docs/PHYSICS.md, SkyShift tests). Each pixel that sees one star
// (no other within 5 sizes) near its core is drawn in the Planck colour of g T_star, with
// brightness g^4 times the star's Gaussian at the ray's escape direction (within the map's 7 %).
TEST(StarSky, FallingObserverSeesEachStarAtItsOwnShiftedTemperatureAndBrightness) {
    const double r = 4, size = 3, beta = std::sqrt(2 / r), gamma = 1 / std::sqrt(1 - beta * beta);
    StarFieldRecipe recipe;
    recipe.stars = 80;
    recipe.seed = 3;
    recipe.faintestMagnitude = 2;
    Scene s;
    s.source = "stars falling into Schwarzschild";
    s.spacetime = std::make_shared<KerrNewman>(1.0, 0.0, 0.0);
    s.observer = Vec4(0, r, 0, 0);
    s.observerVelocity = namedObserverVelocity(*s.spacetime, s.observer, NamedObserver::FreeFall);
    s.camera = test::testCamera(Camera::Projection::Panorama, 120, 60, 360, 170, Vec3(-1, 0, 0), Vec3(0, 0, 1));
    s.settings.progress = false;
    const auto stars = std::make_shared<StarSky>(randomStars(recipe), size);
    s.sky = stars;
    const Camera cam = frameCamera(s);
    const RenderResult out = render(s);
    const std::vector<float> rgb = shadePixels(s, out);
    int seen = 0, blue = 0, red = 0;
    for (int j = 0; j < out.height; ++j)
        for (int i = 0; i < out.width; ++i) {
            const std::size_t n = std::size_t(j) * out.width + i;
            const PixelRecord& px = out.pixels[n];
            if (px.kind != PixelRecord::Sky) continue;
            const Vec3 escape = skyDirection(px.u, px.v);
            const Star* nearest = nullptr;
            double alpha = 1e9, second = 1e9;
            for (const Star& star : stars->stars()) {
                const double a = angleBetween(escape, star.direction);
                if (a < alpha) {
                    second = alpha;
                    alpha = a, nearest = &star;
                } else
                    second = std::min(second, a);
            }
            const double sigma = size * kPi / 180;
            if (alpha > sigma || second < 5 * sigma) continue;
            ++seen;
            const Vec3 d = cam.direction(i, j).normalized();
            const double g = 1 / std::sqrt(1 - 2 / r) / (gamma * (1 - beta * d.dot(cam.forward.normalized())));
            const Vec3 hue = colour::blackbodySrgb(g * nearest->temperature, colour::ToneMap::ColourOnly);
            const double brightness = g * g * g * g * gaussian(nearest->brightness, alpha, size);
            for (int c = 0; c < 3; ++c) {
                const double expected = colour::srgbDecode(hue(c)) * brightness;
                EXPECT_NEAR(rgb[3 * n + c], expected, 0.07 * brightness + 2e-3) << i << "," << j << " c" << c;
            }
            if (g > 1.5) ++blue;
            if (g < 0.8) ++red;
        }
    EXPECT_GT(seen, 40);
    EXPECT_GT(blue, 3);  // stars ahead, shifted blue
    EXPECT_GT(red, 3);   // and behind, red
}
