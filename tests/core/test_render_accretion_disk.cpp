// SPDX-License-Identifier: BSD-3-Clause
// The numeric tracer's accretion disk (core/render/numeric.cpp) against closed forms: a ring seen
// from the axis has g = sqrt(1 - 3/r + 2a/r^1.5) / ((1 + a/r^1.5) sqrt(g_tt(observer))) whatever
// the ray's path (Bardeen, Press & Teukolsky 1972 u^t; p_phi = 0 for rays reaching the axis), a
// face-on Schwarzschild disk is circularly symmetric, and an inclined one shows its secondary image.
#include "core/accretion/thin_disk.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/render/post_render.hpp"
#include "core/render/render.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace lc;

namespace {

Scene faceOnDisk(double a, double distance, int side) {
    Scene s;
    s.source = "face-on disk";
    s.spacetime = std::make_shared<KerrNewman>(1.0, a, 0.0);
    s.observer = Vec4(0, 0, 0, distance);
    s.camera.width = s.camera.height = side;
    // The disk's edge (20 M) fills about 80 % of the field.
    const double half = std::atan(20 / distance) * 180 / kPi / 0.8;
    s.camera.fovXDeg = s.camera.fovYDeg = 2 * half;
    s.camera.forward = Vec3(0, 0, -1);
    s.camera.up = Vec3(1, 0, 0);
    DiskObject d;
    d.name = "disk";
    d.model = std::make_shared<ThinDiskModel>(s.spacetime, 0, 20, true);
    s.disks.push_back(d);
    s.settings.trace.relTol = s.settings.trace.absTol = 1e-11;
    s.settings.progress = false;
    return s;
}

const PixelRecord& at(const RenderResult& r, int i, int j) {
    return r.pixels[static_cast<std::size_t>(j) * r.width + i];
}

TEST(RenderAccretionDisk, FaceOnRedshiftOfEveryPixelIsTheClosedFormOfItsRing) {
    const double a = 0.9, D = 500;
    const Scene scene = faceOnDisk(a, D, 41);
    const RenderResult r = render(scene);
    const double gttObserver = 1 - 2 * D / (D * D + a * a);
    int disk = 0;
    for (const PixelRecord& px : r.pixels) {
        if (px.kind != PixelRecord::Disk) continue;
        ++disk;
        const double radius = px.diskRadius, r32 = std::pow(radius, 1.5);
        const double expected = std::sqrt(1 - 3 / radius + 2 * a / r32) / (1 + a / r32) / std::sqrt(gttObserver);
        ASSERT_NEAR(px.frequencyRatio, expected, 2e-6) << "r = " << radius;  // float storage
        EXPECT_EQ(px.order, 0);
        EXPECT_GE(radius, scene.disks[0].model->isco() - 1e-5);
        // Observed bolometric intensity g^4 F / F_max.
        const double flux = scene.disks[0].model->flux(radius) / scene.disks[0].model->maxFlux();
        EXPECT_NEAR(px.intensity, std::pow(expected, 4) * flux, 1e-5);
    }
    EXPECT_GT(disk, 41 * 41 / 3);  // the disk fills most of the field, the shadow the middle
    EXPECT_EQ(at(r, 20, 20).kind, PixelRecord::Horizon);
}

TEST(RenderAccretionDisk, FaceOnSchwarzschildDiskIsCircularlySymmetric) {
    const RenderResult r = render(faceOnDisk(0, 300, 31));
    int compared = 0;
    for (int j = 0; j < 31; ++j)
        for (int i = 0; i < 31; ++i) {
            // A quarter turn about the image centre maps (i, j) to (30 - j, i).
            const PixelRecord &p = at(r, i, j), &q = at(r, 30 - j, i);
            ASSERT_EQ(p.kind, q.kind) << i << ", " << j;
            if (p.kind != PixelRecord::Disk) continue;
            EXPECT_NEAR(p.diskRadius, q.diskRadius, 1e-5 * p.diskRadius);
            EXPECT_NEAR(p.frequencyRatio, q.frequencyRatio, 1e-6);
            ++compared;
        }
    EXPECT_GT(compared, 300);
}

TEST(RenderAccretionDisk, InclinedDiskShowsDirectAndSecondaryImagesAndBeaming) {
    // a = 0.9 seen from 50 M at 75 degrees from the spin axis (data/kerr_disk.json, smaller).
    Scene s = faceOnDisk(0.9, 50, 2);
    const double inc = 75 * kPi / 180;
    s.observer = Vec4(0, 50 * std::sin(inc), 0, 50 * std::cos(inc));
    s.camera.width = 160;
    s.camera.height = 90;
    s.camera.fovXDeg = 48;
    s.camera.fovYDeg = 27;
    s.camera.forward = -s.observer.tail<3>();
    s.camera.up = Vec3(0, 0, 1);
    s.settings.trace.relTol = s.settings.trace.absTol = 1e-9;
    const RenderResult r = render(s);
    int direct = 0, secondary = 0;
    double left = 0, right = 0;
    for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i) {
            const PixelRecord& px = at(r, i, j);
            if (px.kind != PixelRecord::Disk) continue;
            (px.order == 0 ? direct : secondary) += 1;
            (i < r.width / 2 ? left : right) += px.intensity;
        }
    EXPECT_GT(direct, 3000);
    EXPECT_GT(secondary, 5);  // the thin ring just outside the shadow (11 pixels at this size)
    // The disk turns counter-clockwise seen from +z; from +x with +z up its approaching side, at -y,
    // is on the left: beamed brighter there.
    EXPECT_GT(left, 2 * right);
}

TEST(RenderAccretionDisk, ShadingIsTheBlackBodyOfTheLocalTemperatureAtGTimesTheIntensity) {
    Scene s = faceOnDisk(0.5, 400, 21);
    s.disks[0].temperature = 8000;
    const RenderResult r = render(s);
    const std::vector<float> rgb = shadePixels(s, r);
    const PixelRecord& px = at(r, 15, 10);
    ASSERT_EQ(px.kind, PixelRecord::Disk);
    // T(r) = T_peak (F / F_max)^(1/4), independent of the stored intensity's g^4.
    const ThinDiskModel& m = *s.disks[0].model;
    const double local = 8000 * std::pow(m.flux(px.diskRadius) / m.maxFlux(), 0.25);
    EXPECT_NEAR(diskLocalTemperature<double>(8000, px.intensity, px.frequencyRatio), local, 1e-3 * local);
    // Flux emission: grey at the intensity.
    s.disks[0].emission = DiskObject::Emission::Flux;
    const std::vector<float> grey = shadePixels(s, r);
    const std::size_t n = 10 * 21 + 15;
    EXPECT_FLOAT_EQ(grey[3 * n], px.intensity);
    EXPECT_NE(rgb[3 * n], rgb[3 * n + 2]);  // a black body is not grey
}

// The sweep path (PixelShader) keeps its frame and the disk's light between settings: through a
// sequence of them, back and forth, each frame equals shadePixels' for the same settings bit for bit.
TEST(RenderAccretionDisk, SweepPathEqualsShadeThroughASequenceOfSettings) {
    Scene s = faceOnDisk(0.5, 400, 21);
    s.disks[0].temperature = 8000;
    const RenderResult r = render(s);
    float t0 = 1e30f, t1 = -1e30f;
    for (const PixelRecord& px : r.pixels)
        if (px.kind == PixelRecord::Disk) t0 = std::min(t0, px.emissionTime), t1 = std::max(t1, px.emissionTime);
    PostRender hot, window, blink, retexture;
    hot.temperature = 12000;
    window.timeWindow = std::make_pair(double(t0), 0.5 * (t0 + t1));
    window.outsideTexture = std::make_shared<CheckerTexture>(4, 2, Vec3(1, 0, 0), Vec3(0, 1, 0));
    blink.blinkPeriod = 0.3 * (t1 - t0);
    blink.blinkPhase = t0;
    blink.temperature = 12000;
    retexture.uOffset = 0.25;
    PixelShader sweep(s, r);
    int changed = 0;
    for (const PostRender* post : {&hot, &window, &blink, &retexture, &hot, &blink, &window}) {
        const std::vector<float>& frame = sweep.shade(*post);
        EXPECT_EQ(frame, shadePixels(s, r, *post));
        changed += frame != shadePixels(s, r);
    }
    EXPECT_EQ(changed, 6);  // every setting but the objects' texture shift changes the disk
}

}  // namespace
