// SPDX-License-Identifier: BSD-3-Clause
// The CPU reference renderer for SR scenes (core/sr/renderer).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/sr/doppler.hpp"
#include "core/sr/photo_object.hpp"
#include "core/sr/renderer.hpp"
#include "tests/common/sr_camera.hpp"

using namespace lc;
using namespace lc::sr;

namespace {

std::shared_ptr<const colour::BlackbodyTable> sharedTable() {
    static auto t = std::make_shared<const colour::BlackbodyTable>(1000.0, 60000.0, 1024);
    return t;
}

// Seed 003 Fig. 4 geometry: unit cube centred at the origin of S', observer at (2, 5, 0.2),
// c t_obs = 5.12 for beta = (0, 0.95, 0); light at (90, 0, 9.8) as in Fig. 7.
SrScene cubeScene(int n, const Vec3& beta, double tObs = 5.12) {
    SrScene s;
    SrObject o;
    o.mesh = makeCube(1.0, n);
    o.frame = MovingFrame(beta, Vec3::Zero());
    s.objects.push_back(o);
    s.lightPosition = Vec3(90.0, 0.0, 9.8);
    s.observerTime = tObs;
    return s;
}

// Looks at the apparent centre of the scene's first object.
ObserverCamera cubeCamera(const SrScene& s, int w, int h, double fovDeg = 35.0) {
    ObserverCamera c;
    c.position = Vec3(2.0, 5.0, 0.2);
    const Vec4 obs(s.observerTime, c.position.x(), c.position.y(), c.position.z());
    c.forward = apparentPosition(s.objects[0].frame, Vec3::Zero(), obs) - c.position;
    c.up = Vec3(0.0, 0.0, 1.0);
    c.fovYDeg = fovDeg;
    c.fovXDeg = lc::test::squarePixelFovX(w, h, fovDeg);
    c.width = w;
    c.height = h;
    return c;
}

int countHits(const SrImage& img) {
    return static_cast<int>(std::count_if(img.object.begin(), img.object.end(), [](int o) { return o >= 0; }));
}

}  // namespace

TEST(SrRenderer, LocalRayTracingEqualsBruteForce) {
    const SrRenderer r(sharedTable());
    const SrScene scene = cubeScene(3, Vec3(0.0, 0.95, 0.0));
    const ObserverCamera cam = cubeCamera(scene, 96, 72);
    SrRenderOptions o;
    o.mode = SrRenderMode::BruteForce;
    const SrImage brute = r.render(scene, cam, o);
    o.mode = SrRenderMode::LocalRayTracing;
    const SrImage local = r.render(scene, cam, o);
    EXPECT_GT(countHits(brute), 200);
    EXPECT_EQ(brute.object, local.object);
    EXPECT_EQ(brute.triangle, local.triangle);
    EXPECT_EQ(brute.depth, local.depth);
    EXPECT_EQ(brute.rgb, local.rgb);
}

TEST(SrRenderer, OneAndTwoThreadsGiveTheSameImage) {
    const SrRenderer r(sharedTable());
    const SrScene scene = cubeScene(4, Vec3(0.0, 0.9, 0.2));
    const ObserverCamera cam = cubeCamera(scene, 80, 60);
    SrRenderOptions o;
    o.threads = 1;
    const SrImage a = r.render(scene, cam, o);
    o.threads = 2;
    const SrImage b = r.render(scene, cam, o);
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(a.triangle, b.triangle);
}

TEST(SrRenderer, PolygonDistortionConvergesToLocalRayTracing) {
    // Seed 003 Fig. 10: the polygon method approaches the exact image as the mesh is refined.
    const SrRenderer r(sharedTable());
    const ObserverCamera cam = cubeCamera(cubeScene(1, Vec3(0.0, 0.95, 0.0)), 160, 120);
    SrRenderOptions o;
    auto maskMismatch = [&](int n) {
        const SrScene scene = cubeScene(n, Vec3(0.0, 0.95, 0.0));
        o.mode = SrRenderMode::LocalRayTracing;
        const SrImage exact = r.render(scene, cam, o);
        o.mode = SrRenderMode::PolygonDistortion;
        const SrImage poly = r.render(scene, cam, o);
        int diff = 0;
        double depthErr = 0.0;
        for (size_t i = 0; i < exact.object.size(); ++i) {
            if ((exact.object[i] >= 0) != (poly.object[i] >= 0))
                ++diff;
            else if (exact.object[i] >= 0)
                depthErr = std::max(depthErr, std::abs(double(poly.depth[i]) / exact.depth[i] - 1.0));
        }
        std::printf("  cube %2d x %2d per face: %5d hit pixels, %4d differ in coverage, max depth error %.2e\n", n, n,
                    countHits(exact), diff, depthErr);
        return std::make_pair(diff / double(countHits(exact)), depthErr);
    };
    const auto coarse = maskMismatch(1), medium = maskMismatch(5), fine = maskMismatch(40);
    EXPECT_GT(coarse.first, 0.02);  // 2 triangles per face: visibly wrong
    EXPECT_LT(fine.first, medium.first);
    EXPECT_LT(fine.first, 0.005);
    EXPECT_LT(fine.second, 1e-2);
    EXPECT_LT(fine.second, coarse.second);
}

TEST(SrRenderer, DopplerShiftsColourAndPixelFactorsAreExact) {
    const SrRenderer r(sharedTable());
    SrRenderOptions o;
    o.shading = false;
    auto blueOverRed = [&](const Vec3& beta, double* meanD) {
        const SrScene scene = cubeScene(2, beta, 0.0);
        const ObserverCamera cam = cubeCamera(scene, 64, 48);
        const SrImage img = r.render(scene, cam, o);
        double br = 0.0, dsum = 0.0;
        int n = 0;
        for (int i = 0; i < img.width * img.height; ++i) {
            if (img.object[i] < 0) continue;
            br += img.rgb[3 * i + 2] / std::max(1e-6f, img.rgb[3 * i]);
            dsum += img.doppler[i];
            // The pixel's factor is the textbook D for light arriving against the view direction.
            const Vec3 d = cam.direction(i % img.width, i / img.width);
            EXPECT_NEAR(img.doppler[i], dopplerFactor(beta, -d), 1e-5 * img.doppler[i]);
            ++n;
        }
        EXPECT_GT(n, 50);
        *meanD = dsum / n;
        return br / n;
    };
    double dRest, dApp, dRec;
    const double rest = blueOverRed(Vec3(0, 1e-9, 0), &dRest);
    const double approaching = blueOverRed(Vec3(0, 0.5, 0), &dApp);
    const double receding = blueOverRed(Vec3(0, -0.5, 0), &dRec);
    EXPECT_NEAR(dRest, 1.0, 1e-6);
    EXPECT_GT(dApp, 1.5);
    EXPECT_LT(dRec, 0.7);
    EXPECT_GT(approaching, rest + 0.05);
    EXPECT_LT(receding, rest - 0.05);
}

TEST(SrRenderer, ReferenceToneMapShowsTheSearchlight) {
    // With the fixed-luminance map a 2000 K emitter approaching is brighter than receding.
    const SrRenderer r(sharedTable());
    SrRenderOptions o;
    o.shading = false;
    o.toneMap = colour::ToneMap::ReferenceLog;
    auto meanBrightness = [&](double beta) {
        SrScene scene = cubeScene(2, Vec3(0, beta, 0), 0.0);
        const ObserverCamera cam = cubeCamera(scene, 64, 48);
        scene.objects[0].material.temperatureK = 2000.0;
        const SrImage img = r.render(scene, cam, o);
        double sum = 0.0;
        int n = 0;
        for (int i = 0; i < img.width * img.height; ++i)
            if (img.object[i] >= 0) sum += img.rgb[3 * i] + img.rgb[3 * i + 1] + img.rgb[3 * i + 2], ++n;
        return sum / n;
    };
    EXPECT_GT(meanBrightness(0.3), 1.3 * meanBrightness(1e-9));
    EXPECT_LT(meanBrightness(-0.3), 0.7 * meanBrightness(1e-9));
}

TEST(SrRenderer, ReflectedLampLightIsDoubleDopplerShifted) {
    // Lamp at the eye: light goes out along d and comes back along -d, so the received
    // temperature is T_lamp (1 - beta.d) / (1 + beta.d) (radar Doppler; seed 003 eq. 17).
    const SrRenderer r(sharedTable());
    const Vec3 beta(0.1, 0.6, 0.0);
    SrScene scene = cubeScene(2, beta, 0.0);
    const ObserverCamera cam = cubeCamera(scene, 48, 36, 15.0);
    scene.lightPosition = cam.position;
    scene.lightTemperatureK = 4000.0;
    SrRenderOptions o;
    o.shading = false;
    o.colourSource = SrColourSource::ReflectedLight;
    const SrImage img = r.render(scene, cam, o);
    int n = 0;
    for (int i = 0; i < img.width * img.height; ++i) {
        if (img.object[i] < 0) continue;
        const Vec3 d = cam.direction(i % img.width, i / img.width);
        const Vec3 expected =
            r.table().lookup(4000.0 * (1.0 - beta.dot(d)) / (1.0 + beta.dot(d)), colour::ToneMap::ColourOnly);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(img.rgb[3 * i + k], expected[k], 1e-5);
        ++n;
    }
    EXPECT_GT(n, 50);
}

// The SR renderers' camera is the scene's (lc::Camera placed at the observer): its projection
// inverts its view direction at pixel centres and off-image points, with non-square pixels, and
// refuses what is behind a pinhole; validate() names what it refuses.
TEST(SrCamera, ProjectionInvertsTheViewDirectionAndValidateNamesBadValues) {
    ObserverCamera cam;
    cam.width = 64;
    cam.height = 48;
    cam.fovXDeg = 95;
    cam.fovYDeg = 70;
    cam.forward = Vec3(0.3, -0.2, -1.0);
    cam.up = Vec3(0.1, 1.0, 0.0);
    cam.position = Vec3(1.0, 2.0, 3.0);
    EXPECT_NO_THROW(cam.validate());
    const Camera::Axes a = cam.axes();
    const Vec2 t = cam.halfFieldTangents();
    for (const auto& [px, py] : {std::pair{0.5, 0.5}, {63.5, 47.5}, {32.0, 24.0}, {-40.0, 100.0}, {10.25, 3.75}}) {
        const Vec3 d = cam.directionAt(px, py);
        double x = 0, y = 0;
        ASSERT_TRUE(cam.projectPoint(cam.position + 5.0 * d, x, y));
        EXPECT_NEAR(x, px, 1e-10);
        EXPECT_NEAR(y, py, 1e-10);
        const Vec3 h = pinholeHomogeneous<double>(2.0 * d, a.forward, a.right, a.up, t.x(), t.y());
        EXPECT_NEAR(h.z(), 2.0 * d.dot(a.forward), 1e-14);
        EXPECT_FALSE(cam.project(-d, x, y));  // behind the eye
    }
    auto refused = [](ObserverCamera c, const std::string& what) {
        try {
            c.validate();
        } catch (const std::invalid_argument& e) {
            return std::string(e.what()).find(what) != std::string::npos;
        }
        return false;
    };
    ObserverCamera bad = cam;
    bad.width = 0;
    EXPECT_TRUE(refused(bad, "camera width"));
    bad = cam;
    bad.fovYDeg = 180;
    EXPECT_TRUE(refused(bad, "below 180 degrees"));
    bad = cam;
    bad.position.x() = std::nan("");
    EXPECT_TRUE(refused(bad, "position component"));
    bad = cam;
    bad.up = 2.0 * bad.forward;
    EXPECT_TRUE(refused(bad, "parallel"));
    bad = cam;
    bad.lookAt = Vec3(0, 0, 0);
    EXPECT_TRUE(refused(bad, "look_at"));
    bad = cam;
    bad.forward = Vec3::Zero();
    EXPECT_TRUE(refused(bad, "must not be zero"));
}
