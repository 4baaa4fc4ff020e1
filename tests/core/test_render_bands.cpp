// SPDX-License-Identifier: BSD-3-Clause
// Bands of rows (RenderSettings::rowBegin/rowEnd), the tasks of a distributed render: a band
// traces exactly the rows of the whole image, bit for bit, and leaves the others blank; the
// statistics count its rays only. Oracle: the same renderer on the whole image.
#include "core/scene/godel_placement.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/render/render.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

using namespace lc;

namespace {

Scene kerrScene() {
    Scene s;
    s.spacetime = std::make_shared<KerrNewman>(1.0, 0.9, 0.0);
    s.observer = Vec4(0, 30, 0, 0);
    s.camera.width = 24;
    s.camera.height = 12;
    s.camera.fovXDeg = 40;
    s.camera.fovYDeg = 20;
    s.camera.forward = Vec3(-1, 0, 0);
    s.settings.trace.absTol = s.settings.trace.relTol = 1e-8;
    s.sky = std::make_shared<CheckerTexture>(36, 18, Vec3(1, 1, 1), Vec3(0, 0, 0));
    return s;
}

Scene godelScene() {
    Scene s;
    s.spacetime = std::make_shared<GodelCartesian>(1.0);
    SphereObject ball;
    ball.centre = Vec4(0, 1, 0, 0);
    ball.radius = 0.25;
    ball.placement = std::make_shared<GodelPlacement>(1.0, ball.centre);
    s.spheres.push_back(ball);
    s.camera.projection = Camera::Projection::Panorama;
    s.camera.width = 36;
    s.camera.height = 12;
    s.camera.fovXDeg = 360;
    s.camera.fovYDeg = 120;
    s.settings.windings = 1;
    s.settings.trace.maxAffine = 4 * kPi;
    return s;
}

bool samePixel(const PixelRecord& a, const PixelRecord& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectBandEqualsWhole(Scene scene, int begin, int end) {
    const RenderResult whole = render(scene);
    scene.settings.rowBegin = begin;
    scene.settings.rowEnd = end;
    const RenderResult band = render(scene);
    const PixelRecord blank;
    for (int j = 0; j < whole.height; ++j)
        for (int i = 0; i < whole.width; ++i) {
            const std::size_t n = static_cast<std::size_t>(j) * whole.width + i;
            const bool inside = j >= begin && j < (end < 0 ? whole.height : end);
            EXPECT_TRUE(samePixel(band.pixels[n], inside ? whole.pixels[n] : blank)) << "row " << j << " column " << i;
        }
    EXPECT_EQ(band.stats.rays, static_cast<std::size_t>(((end < 0 ? whole.height : end) - begin) * whole.width));
}

TEST(RenderBands, NumericKerrBandEqualsItsRowsOfTheWholeImage) {
    expectBandEqualsWhole(kerrScene(), 3, 7);
    expectBandEqualsWhole(kerrScene(), 11, -1);  // to the last row
}

TEST(RenderBands, ClosedFormGodelBandEqualsItsRowsOfTheWholeImage) {
    const Scene s = godelScene();
    ASSERT_EQ(resolveMethod(s), RenderSettings::Method::ClosedForm);
    expectBandEqualsWhole(s, 0, 5);
}

TEST(RenderBands, EmptyOrOutsideBandsAreRefused) {
    Scene s = kerrScene();
    for (auto [begin, end] : {std::pair{5, 5}, {-1, 3}, {0, 13}, {8, 4}}) {
        s.settings.rowBegin = begin;
        s.settings.rowEnd = end;
        EXPECT_THROW(render(s), std::invalid_argument) << begin << " to " << end;
    }
}

}  // namespace
