// SPDX-License-Identifier: BSD-3-Clause
// The GPU post-renderer (vtkLightconePostRenderer) against the CPU reference lc::shadePixels,
// the colours `lightcone shade` writes: the same per-pixel data (rendered here on the CPU),
// the same settings, compared byte for byte after the image writer's sRGB encoding. Tolerance:
// one 8-bit level (the shader computes in float, the CPU in double; both interpolate the same
// black-body table), and at
// most 0.5 % of the pixels by more (a float uv or emission time rounded across a texel or window
// edge).
#include "core/render/post_render.hpp"
#include "core/render/render.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/scene_reader.hpp"
#include "vtkLightconePostRenderMapper.h"
#include "vtkLightconePostRenderer.h"

#include <gtest/gtest.h>

#include <vtkNew.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>

namespace {

struct Rendered {
    lc::Scene scene;
    lc::RenderResult data;
};

Rendered renderOnCpu(const std::string& name, int width, int height) {
    Rendered r;
    r.scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/" + name);
    r.scene.camera.width = width;
    r.scene.camera.height = height;
    r.data = lc::render(r.scene);
    return r;
}

// The bytes lightcone shade writes: lc::shadePixels, then the image writer's encoding.
std::vector<unsigned char> cpuBytes(const Rendered& r, const lc::PostRender& post) {
    const std::vector<float> rgb = lc::shadePixels(r.scene, r.data, post);
    std::vector<unsigned char> out(rgb.size());
    for (std::size_t k = 0; k < rgb.size(); ++k)
        out[k] = static_cast<unsigned char>(std::lround(255.0f * lc::io::srgbEncode(rgb[k])));
    return out;
}

struct Agreement {
    std::size_t pixels = 0, offByOne = 0, worse = 0;
    int worst = 0;
};

Agreement compare(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
    Agreement g;
    g.pixels = a.size() / 3;
    for (std::size_t p = 0; p < g.pixels; ++p) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a[3 * p + c]) - int(b[3 * p + c])));
        g.offByOne += d == 1;
        g.worse += d > 1;
        g.worst = std::max(g.worst, d);
    }
    return g;
}

// Pixels whose colour the settings changed (so that agreement is not that of two unchanged images).
std::size_t changedPixels(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
    std::size_t n = 0;
    for (std::size_t p = 0; p < a.size() / 3; ++p)
        n += a[3 * p] != b[3 * p] || a[3 * p + 1] != b[3 * p + 1] || a[3 * p + 2] != b[3 * p + 2];
    return n;
}

class PostRenderCase : public ::testing::TestWithParam<const char*> {
protected:
    void SetUp() override {
        if (!std::getenv("DISPLAY")) GTEST_SKIP() << "needs an X display (ctest runs under xvfb-run)";
    }
    // GPU and CPU for `post`; the settings must change at least `minChanged` pixels from plain shading.
    void expectAgreement(const Rendered& r, const lc::PostRender& post, const char* what, std::size_t minChanged) {
        gpu->SetPostRender(post);
        const std::vector<unsigned char> g = gpu->RenderSrgb(), c = cpuBytes(r, post);
        ASSERT_EQ(g.size(), c.size());
        const Agreement a = compare(g, c);
        const std::size_t changed = changedPixels(c, cpuBytes(r, lc::PostRender{}));
        std::printf("%s / %s: %zu px, %zu changed by the settings, %zu off by one level, %zu worse (worst %d)\n",
                    GetParam(), what, a.pixels, changed, a.offByOne, a.worse, a.worst);
        EXPECT_GE(changed, minChanged) << what;
        EXPECT_LE(a.worse, a.pixels / 200) << what;
        // The CPU's sweep path is shadePixels, bit for bit: one lc::PixelShader through every setting
        // of the test in turn (unchanging pixels coloured once, samples kept between settings).
        if (!sweep) sweep = std::make_unique<lc::PixelShader>(r.scene, r.data);
        EXPECT_EQ(sweep->shade(post), lc::shadePixels(r.scene, r.data, post)) << what;
    }
    vtkNew<vtkLightconePostRenderer> gpu;
    std::unique_ptr<lc::PixelShader> sweep;
};

TEST_P(PostRenderCase, GpuEqualsShadeForEachEffect) {
    const Rendered r = renderOnCpu(GetParam(), 240, 120);
    gpu->SetInput(r.scene, r.data);
    std::size_t objectPixels = 0;
    for (const auto& p : r.data.pixels) objectPixels += p.kind == lc::PixelRecord::Object;
    ASSERT_GT(objectPixels, 100u);

    expectAgreement(r, lc::PostRender{}, "as rendered", 0);

    lc::PostRender retexture;  // (a) another texture, turned and repeated
    retexture.objectTextures = {
        std::make_shared<lc::CheckerTexture>(12, 6, lc::Vec3(1, 0.8, 0.1), lc::Vec3(0.05, 0.1, 0.5))};
    retexture.uOffset = 0.3;
    retexture.uScale = 2;
    retexture.vScale = 0.75;
    retexture.vOffset = 0.1;
    expectAgreement(r, retexture, "re-textured", objectPixels / 3);

    lc::PostRender hot;  // (b) a black body at 4500 K seen through each pixel's frequency ratio
    hot.temperature = 4500;
    expectAgreement(r, hot, "temperature 4500 K", objectPixels / 2);

    // (c) the emission times' middle half over a second texture, and blinking lights.
    std::vector<float> times;
    for (const auto& p : r.data.pixels)
        if (p.kind == lc::PixelRecord::Object) times.push_back(p.emissionTime);
    std::sort(times.begin(), times.end());
    lc::PostRender window;
    window.timeWindow = std::make_pair(double(times[times.size() / 4]), double(times[3 * times.size() / 4]));
    window.outsideTexture = std::make_shared<lc::CheckerTexture>(8, 4, lc::Vec3(1, 0, 0), lc::Vec3(0, 1, 0));
    expectAgreement(r, window, "time window over a second texture", objectPixels / 4);
    window.outsideTexture = nullptr;
    expectAgreement(r, window, "time window alone", objectPixels / 4);
    lc::PostRender blink;
    blink.blinkPeriod = std::max(0.1, 0.5 * (times.back() - times.front()));
    blink.blinkPhase = times.front();
    blink.blinkDuty = 0.5;
    expectAgreement(r, blink, "blinking", objectPixels / 10);
    expectAgreement(r, retexture, "re-textured again", objectPixels / 3);
    expectAgreement(r, lc::PostRender{}, "as rendered again", 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, PostRenderCase, ::testing::Values("godel_many_images.json", "godel_lit_earth.json"));

TEST(PostRenderer, TheSkyOfAKerrImageIsColouredAgain) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "needs an X display";
    const Rendered r = renderOnCpu("kerr.json", 96, 48);
    vtkNew<vtkLightconePostRenderer> gpu;
    gpu->SetInput(r.scene, r.data);
    const Agreement a = compare(gpu->RenderSrgb(), cpuBytes(r, {}));
    EXPECT_EQ(a.worse, 0u);
}

// A sky of black-body stars (data/kerr_infall_stars.json, falling into Kerr): each star's pixels
// coloured again at the pixel's g T_star with brightness g^4 b from the atlas's (b, b T) texels,
// the bytes `shade` writes to within one level; blue stars and red ones are both there.
TEST(PostRenderer, AStarSkyIsColouredAgainStarByStar) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "needs an X display";
    const Rendered r = renderOnCpu("kerr_infall_stars.json", 240, 120);
    vtkNew<vtkLightconePostRenderer> gpu;
    gpu->SetInput(r.scene, r.data);
    const std::vector<unsigned char> cpu = cpuBytes(r, {});
    const Agreement a = compare(gpu->RenderSrgb(), cpu);
    EXPECT_EQ(a.worse, 0u) << "worst " << a.worst;
    int blue = 0, red = 0;
    for (std::size_t p = 0; p < cpu.size() / 3; ++p) {
        const int R = cpu[3 * p], B = cpu[3 * p + 2];
        if (std::max(R, B) < 60) continue;
        blue += B > R + 20;
        red += R > B + 20;
    }
    EXPECT_GT(blue, 20);
    EXPECT_GT(red, 5);
}

// An accretion disk's pixels (data/kerr_disk.json) coloured again: as rendered (black body at g T
// with g^4 brightness), at another peak temperature, by intensity alone, by its (r, phi) texture,
// and inside a time window.
TEST(PostRenderer, AnAccretionDiskIsColouredAgainLikeShade) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "needs an X display";
    Rendered r = renderOnCpu("kerr_disk.json", 160, 90);
    std::size_t diskPixels = 0;
    std::vector<float> times;
    for (const auto& p : r.data.pixels)
        if (p.kind == lc::PixelRecord::Disk) {
            ++diskPixels;
            times.push_back(p.emissionTime);
        }
    ASSERT_GT(diskPixels, 3000u);
    std::sort(times.begin(), times.end());
    lc::PostRender cooler;
    cooler.temperature = 4000;
    lc::PostRender window;
    window.timeWindow = std::make_pair(double(times[times.size() / 3]), double(times.back()));
    for (auto emission :
         {lc::DiskObject::Emission::Blackbody, lc::DiskObject::Emission::Flux, lc::DiskObject::Emission::Texture}) {
        r.scene.disks[0].emission = emission;
        vtkNew<vtkLightconePostRenderer> gpu;
        gpu->SetInput(r.scene, r.data);
        for (const lc::PostRender& post : {lc::PostRender{}, cooler, window}) {
            gpu->SetPostRender(post);
            const Agreement a = compare(gpu->RenderSrgb(), cpuBytes(r, post));
            std::printf("kerr_disk emission %d: %zu px, %zu off by one level, %zu worse (worst %d)\n",
                        static_cast<int>(emission), a.pixels, a.offByOne, a.worse, a.worst);
            EXPECT_LE(a.worse, a.pixels / 200);
        }
    }
    r.scene.disks[0].emission = lc::DiskObject::Emission::Blackbody;
    EXPECT_NE(cpuBytes(r, cooler), cpuBytes(r, {}));  // the temperature reaches the disk
}

TEST(PostRenderer, RefusesDataThatDoNotBelongToTheScene) {
    Rendered r = renderOnCpu("godel_many_images.json", 40, 20);
    vtkNew<vtkLightconePostRenderer> gpu;
    r.data.pixels[5].kind = lc::PixelRecord::Object;
    r.data.pixels[5].object = 3;  // the scene has one object
    EXPECT_THROW(gpu->SetInput(r.scene, r.data), std::invalid_argument);
    r.data.pixels.pop_back();
    r.data.pixels[5].object = 0;
    EXPECT_THROW(gpu->SetInput(r.scene, r.data), std::invalid_argument);
    EXPECT_THROW(gpu->RenderSrgb(), std::logic_error);
    std::ostringstream os;
    gpu->PrintSelf(os, vtkIndent());
    EXPECT_NE(os.str().find("Mapper"), std::string::npos);
}

}  // namespace
