// SPDX-License-Identifier: BSD-3-Clause
// The CPU reference renderer on the default Goedel scene: the sphere inside the horizon is
// seen twice, in the directions that the z = 0 inverse problem predicts (docs/PHYSICS.md section 3:
// k3 = 0, w l in {h, pi - h}, h = arcsin(r_p / 2a), phi0 = phi_p + Phi(l)).
#include "core/render/render.hpp"
#include "readers/io/scene_reader.hpp"

#include "core/godel/images.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <queue>

using namespace lc;

namespace {

struct Blob {
    std::size_t pixels = 0;
    double sumX = 0, sumY = 0;
};

std::vector<Blob> objectBlobs(const RenderResult& r) {
    std::vector<int> label(r.pixels.size(), -1);
    std::vector<Blob> blobs;
    for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i) {
            const std::size_t n = static_cast<std::size_t>(j) * r.width + i;
            if (label[n] >= 0 || r.pixels[n].kind != PixelRecord::Object) continue;
            blobs.emplace_back();
            std::queue<std::pair<int, int>> q;
            q.push({i, j});
            label[n] = static_cast<int>(blobs.size()) - 1;
            while (!q.empty()) {
                auto [x, y] = q.front();
                q.pop();
                blobs.back().pixels++;
                blobs.back().sumX += x;
                blobs.back().sumY += y;
                for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                    const int xx = (x + dx + r.width) % r.width, yy = y + dy;  // panorama wraps
                    if (yy < 0 || yy >= r.height) continue;
                    const std::size_t m = static_cast<std::size_t>(yy) * r.width + xx;
                    if (label[m] < 0 && r.pixels[m].kind == PixelRecord::Object) {
                        label[m] = label[n];
                        q.push({xx, yy});
                    }
                }
            }
        }
    return blobs;
}

TEST(DefaultScene, SphereInsideHorizonIsSeenTwiceWhereTheInverseProblemSays) {
    Scene s = io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    s.camera.width = 360;  // 1 pixel per degree of azimuth
    s.camera.height = 60;
    const RenderResult r = renderNumeric(s);
    const auto blobs = objectBlobs(r);
    ASSERT_EQ(blobs.size(), 2u);
    EXPECT_LT(r.stats.worstDrift, 1e-7);

    // Oracle: sphere centre at r_p = 1, phi_p = 0, a = 1 -> q = 1/2.
    const double h = std::asin(0.5);
    const double phiFront = std::atan(kSqrt2 * std::tan(h));
    const double phiBack = kPi + std::atan(kSqrt2 * std::tan(kPi - h));
    std::vector<double> expectedColumns;
    for (double phi : {phiFront, phiBack})  // azimuth to the left of forward (+x), 1 px per degree
        expectedColumns.push_back(180.0 - phi * 180 / kPi - 0.5);
    std::vector<double> columns;
    for (const auto& b : blobs) columns.push_back(b.sumX / b.pixels);
    std::sort(columns.begin(), columns.end());
    std::sort(expectedColumns.begin(), expectedColumns.end());
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(columns[k], expectedColumns[k], 1.5) << k;
    // Both images straddle the horizon line (z = 0 plane).
    for (const auto& b : blobs) EXPECT_NEAR(b.sumY / b.pixels, 29.5, 1.0);
}

}  // namespace

namespace {

TEST(DefaultScene, ClosedFormAndNumericRenderersAgree) {
    // Two independent routes to the same image: Odeint on the Goedel metric versus the
    // closed-form geodesics after moving the observer to the origin.
    Scene s = io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    s.observer = Vec4(0.3, 0.2, -0.4, 0.1);  // off the axis: exercises the isometry
    s.camera.width = 240;
    s.camera.height = 80;
    s.settings.trace.absTol = s.settings.trace.relTol = 1e-11;
    const RenderResult numeric = renderNumeric(s);
    const RenderResult closed = renderGodelClosedForm(s);
    std::size_t differ = 0, objects = 0;
    double worstDepth = 0;
    for (std::size_t n = 0; n < numeric.pixels.size(); ++n) {
        const PixelRecord &a = numeric.pixels[n], &b = closed.pixels[n];
        objects += a.kind == PixelRecord::Object;
        if (a.kind != b.kind || a.object != b.object) {
            ++differ;
            std::printf("pixel %zu: numeric kind %d affine %g, closed kind %d affine %g\n", n, a.kind, a.affine, b.kind,
                        b.affine);
            continue;
        }
        if (a.kind == PixelRecord::Object) worstDepth = std::max(worstDepth, double(std::abs(a.affine - b.affine)));
    }
    EXPECT_GT(objects, 100u);
    EXPECT_EQ(differ, 0u);
    EXPECT_LT(worstDepth, 1e-5);  // float storage of the affine depth
}

}  // namespace

namespace {

TEST(DefaultScene, PerVertexRasterMatchesPerPixelClosedForm) {
    // The inverse problem per vertex (seed 001's method) against tracing every pixel: the two
    // agree except along silhouettes, where the tessellated outline differs by under a pixel.
    Scene s = io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    s.observer = Vec4(0.3, 0.2, -0.4, 0.1);
    s.camera.width = 360;
    s.camera.height = 120;
    s.settings.windings = 2;
    s.settings.trace.maxAffine = 3 * 2 * kPi;
    const RenderResult perPixel = renderGodelClosedForm(s);
    const RenderResult perVertex = renderGodelPerVertex(s, 60, 120);
    std::size_t objects = 0, differ = 0, compared = 0;
    double uvError = 0, depthError = 0, timeError = 0;
    for (std::size_t n = 0; n < perPixel.pixels.size(); ++n) {
        const PixelRecord &a = perPixel.pixels[n], &b = perVertex.pixels[n];
        objects += a.kind == PixelRecord::Object;
        if (a.kind != b.kind) {
            ++differ;
            continue;
        }
        if (a.kind != PixelRecord::Object) continue;
        ++compared;
        const double du = std::abs(a.u - b.u);
        uvError += std::min(du, 1 - du) + std::abs(a.v - b.v);
        depthError += std::abs(a.affine - b.affine) / a.affine;
        timeError = std::max(timeError, double(std::abs(a.emissionTime - b.emissionTime)));
    }
    ASSERT_GT(objects, 200u);
    std::printf(
        "per-vertex vs per-pixel: %zu object pixels, %zu differ in coverage, mean |duv| %.2e, mean depth rel. %.2e\n",
        objects, differ, uvError / compared, depthError / compared);
    EXPECT_LT(double(differ) / objects, 0.02);  // silhouette pixels only
    EXPECT_LT(uvError / compared, 2e-3);        // same surface point
    EXPECT_LT(depthError / compared, 2e-3);     // same depth (affine length)
    EXPECT_LT(timeError, 0.02);                 // same emission time, world chart (linear across a triangle)
}

}  // namespace

namespace {

TEST(MovingObjects, FreeFallAtZeroSpeedMatchesTheSphereAtRest) {
    // Two independent routes: the inverse problem of a static point (PhotoObjectBuilder) and
    // the emission-event solve on each vertex's world line (imagesOfWorldLine) for a body in
    // free fall with k0 = 1 (at rest): same image, frequency ratio 1.
    Scene rest = io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    rest.camera.width = 360;
    rest.camera.height = 120;
    rest.settings.windings = 1;
    Scene falling = rest;
    falling.spheres[0].motion.kind = Motion::Kind::FreeFall;
    falling.spheres[0].motion.k0 = 1;
    const RenderResult a = renderGodelPerVertex(rest, 24, 48);
    const RenderResult b = renderGodelPerVertex(falling, 24, 48);
    std::size_t objects = 0, differ = 0;
    double worstShift = 0;
    for (std::size_t n = 0; n < a.pixels.size(); ++n) {
        objects += a.pixels[n].kind == PixelRecord::Object;
        differ += a.pixels[n].kind != b.pixels[n].kind;
        if (b.pixels[n].kind == PixelRecord::Object)
            worstShift = std::max(worstShift, double(std::abs(b.pixels[n].frequencyRatio - 1)));
    }
    ASSERT_GT(objects, 100u);
    EXPECT_LT(double(differ) / objects, 0.02);  // stitching differs along the rim only
    EXPECT_LT(worstShift, 1e-6);
}

TEST(MovingObjects, GivenWorldLineAtRestMatchesTheSphereAtRest) {
    // A world line that stays at the centre: the same image as the static inverse problem, at
    // frequency ratio 1, and the same emission times.
    Scene rest = io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    rest.camera.width = 360;
    rest.camera.height = 120;
    rest.settings.windings = 1;
    Scene carried = rest;
    Motion& m = carried.spheres[0].motion;
    m.kind = Motion::Kind::WorldLine;
    const Vec4 c = carried.spheres[0].centre;
    m.points = {Vec4(-20, c(1), c(2), c(3)), Vec4(0, c(1), c(2), c(3)), Vec4(5, c(1), c(2), c(3))};
    const RenderResult a = renderGodelPerVertex(rest, 24, 48);
    const RenderResult b = renderGodelPerVertex(carried, 24, 48);
    std::size_t objects = 0, differ = 0;
    double worstShift = 0, worstTime = 0;
    for (std::size_t n = 0; n < a.pixels.size(); ++n) {
        objects += a.pixels[n].kind == PixelRecord::Object;
        differ += a.pixels[n].kind != b.pixels[n].kind;
        if (a.pixels[n].kind == PixelRecord::Object && b.pixels[n].kind == PixelRecord::Object) {
            worstShift = std::max(worstShift, double(std::abs(b.pixels[n].frequencyRatio - 1)));
            worstTime = std::max(worstTime, double(std::abs(a.pixels[n].emissionTime - b.pixels[n].emissionTime)));
        }
    }
    ASSERT_GT(objects, 100u);
    EXPECT_LT(double(differ) / objects, 0.02);
    EXPECT_LT(worstShift, 1e-5);
    EXPECT_LT(worstTime, 1e-3);
}

TEST(MovingObjects, PerPixelTracersRefuseWhatTheyCannotDraw) {
    Scene s = io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    s.spheres[0].motion.kind = Motion::Kind::FreeFall;
    s.spheres[0].motion.k0 = 1.2;
    EXPECT_THROW(renderGodelClosedForm(s), std::invalid_argument);
    EXPECT_THROW(renderNumeric(s), std::invalid_argument);
    EXPECT_EQ(resolveMethod(s), RenderSettings::Method::PerVertex);
}

}  // namespace

namespace {

// A panorama narrower than 360 degrees wraps every 360 degrees, not every image width: a triangle
// straddling the direction straight behind (outside the view) must not be drawn as a strip across
// the image (it was, until the GPU twin of data/godel_time_traveller.json disagreed).
TEST(DefaultScene, PerVertexPanoramaBelowFullTurnMatchesPerPixelClosedForm) {
    Scene s = io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    s.camera.projection = Camera::Projection::Panorama;
    s.camera.fovXDeg = 240;
    s.camera.fovYDeg = 60;
    s.camera.width = 320;
    s.camera.height = 80;
    // Straight behind the camera: the direction of the sphere's nearest image, reversed.
    const auto images = godel::ObserverView(1.0, s.observer).images(s.spheres[0].centre.tail<3>(), 0);
    ASSERT_FALSE(images.images.empty());
    s.camera.forward = -images.images.front().direction;
    s.camera.up = Vec3(0, 0, 1);
    s.settings.progress = false;
    const RenderResult perPixel = renderGodelClosedForm(s);
    const RenderResult perVertex = renderGodelPerVertex(s, 60, 120);
    std::size_t objects = 0, differ = 0;
    for (std::size_t n = 0; n < perPixel.pixels.size(); ++n) {
        objects += perPixel.pixels[n].kind == PixelRecord::Object;
        differ += perPixel.pixels[n].kind != perVertex.pixels[n].kind;
    }
    EXPECT_GT(objects, 50u);
    EXPECT_LT(differ, objects / 10 + 5) << objects << " object pixels";
}

}  // namespace
