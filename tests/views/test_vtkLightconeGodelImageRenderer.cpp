// SPDX-License-Identifier: BSD-3-Clause
// The egocentric Goedel image drawn by VTK/OpenGL shaders (vtkLightconeGodelImageRenderer)
// against the CPU closed-form per-pixel renderer, which traces every pixel's null geodesic and
// shares no code with the shader path beyond the scene (reference computed independently).
// Runs under Xvfb (Mesa llvmpipe is enough).
#include "core/render/render.hpp"
#include "readers/io/scene_reader.hpp"
#include "vtkLightconeGodelImageRenderer.h"

#include "dump_image.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numeric>

namespace {

lc::Scene defaultScene(int width, int height) {
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    scene.camera.width = width;
    scene.camera.height = height;
    scene.settings.progress = false;
    return scene;
}

using lc::test::dump;

struct Coverage {
    std::size_t objectPixels = 0;  // object in either image
    std::size_t differing = 0;     // object in one image and not the other, or another object
    double fraction() const { return objectPixels ? static_cast<double>(differing) / objectPixels : 0.0; }
};

Coverage compareCoverage(const std::vector<int>& gpu, const lc::RenderResult& cpu) {
    Coverage c;
    for (std::size_t k = 0; k < gpu.size(); ++k) {
        const lc::PixelRecord& p = cpu.pixels[k];
        const int ref = p.kind == lc::PixelRecord::Object ? p.object : -1;
        if (ref < 0 && gpu[k] < 0) continue;
        ++c.objectPixels;
        c.differing += ref != gpu[k];
    }
    return c;
}

// 4-connected components of the pixels with id >= 0; a full 360 degree panorama wraps in x.
// labels (optional) receives the component of every pixel, -1 for none.
int components(const std::vector<int>& ids, int w, int h, bool wrapX, int minPixels = 4,
               std::vector<int>* labels = nullptr) {
    std::vector<int> label(ids.size(), -1);
    int count = 0;
    std::vector<int> stack;
    for (int start = 0; start < w * h; ++start) {
        if (ids[start] < 0 || label[start] >= 0) continue;
        int size = 0;
        stack.assign(1, start);
        label[start] = count;
        while (!stack.empty()) {
            const int k = stack.back();
            stack.pop_back();
            ++size;
            const int i = k % w, j = k / w;
            const int nb[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
            for (const auto& n : nb) {
                int ni = n[0];
                const int nj = n[1];
                if (nj < 0 || nj >= h) continue;
                if (ni < 0 || ni >= w) {
                    if (!wrapX) continue;
                    ni = (ni + w) % w;
                }
                const int q = nj * w + ni;
                if (ids[q] >= 0 && label[q] < 0 && ids[q] == ids[k]) {
                    label[q] = count;
                    stack.push_back(q);
                }
            }
        }
        if (size >= minPixels) ++count;
    }
    if (labels) *labels = label;
    return count;
}

std::vector<int> cpuIds(const lc::RenderResult& r) {
    std::vector<int> ids(r.pixels.size());
    for (std::size_t k = 0; k < ids.size(); ++k)
        ids[k] = r.pixels[k].kind == lc::PixelRecord::Object ? r.pixels[k].object : -1;
    return ids;
}

// One scene drawn both ways, as every comparison below does it: by the shader path (`gpu`, its
// scene and mesh resolution set by the test) and by the CPU, with the closed form per pixel or,
// for PerVertex, the CPU raster of the same photo-object layers at the GPU's mesh resolution.
enum class Reference { ClosedForm, PerVertex };
enum class Colour { No, Yes };

struct GodelImages {
    std::vector<int> ids;       // shader path: object per pixel, -1 for none
    std::vector<float> colour;  // shader path (Colour::Yes)
    lc::RenderResult cpu;
    std::vector<float> ref;  // lc::shadePixels of cpu (Colour::Yes)
    Coverage coverage() const { return compareCoverage(ids, cpu); }
};

GodelImages renderBoth(vtkLightconeGodelImageRenderer* gpu, const lc::Scene& scene, Colour colour = Colour::No,
                       Reference reference = Reference::ClosedForm) {
    GodelImages im;
    im.ids = gpu->RenderObjectIds();
    if (colour == Colour::Yes) im.colour = gpu->RenderColour();
    im.cpu = reference == Reference::ClosedForm
                 ? lc::renderGodelClosedForm(scene)
                 : lc::renderGodelPerVertex(scene, gpu->GetLatitudes(), gpu->GetLongitudes());
    if (colour == Colour::Yes) im.ref = lc::shadePixels(scene, im.cpu);
    return im;
}

// The coverage check: enough object pixels for the fraction to mean something (fatal: call it
// through ASSERT_NO_FATAL_FAILURE where the test must stop there), at most `tolerance` differing.
void expectCoverage(const Coverage& c, std::size_t minObjectPixels, double tolerance) {
    ASSERT_GT(c.objectPixels, minObjectPixels);
    EXPECT_LT(c.fraction(), tolerance) << c.differing << " of " << c.objectPixels;
}

// The pixels where both images show the first object (id 0), where colours are compared: f(k)
// for each; returns their number.
template <class F>
std::size_t forCommonPixels(const GodelImages& im, F f) {
    std::size_t n = 0;
    for (std::size_t k = 0; k < im.ids.size(); ++k) {
        if (im.ids[k] != 0 || im.cpu.pixels[k].kind != lc::PixelRecord::Object) continue;
        f(k);
        ++n;
    }
    return n;
}
std::size_t commonPixels(const GodelImages& im) {
    return forCommonPixels(im, [](std::size_t) {});
}

// Mean |a - b| per channel over those pixels. ClampB::Yes: b is CPU shading, which is not
// clamped (a lit side exceeds 1), compared with the framebuffer's [0, 1].
enum class ClampB { No, Yes };
double meanDifference(const GodelImages& im, const std::vector<float>& a, const std::vector<float>& b,
                      ClampB clampB = ClampB::No) {
    double sum = 0;
    const std::size_t n = forCommonPixels(im, [&](std::size_t k) {
        for (int c = 0; c < 3; ++c) {
            const double r = clampB == ClampB::Yes ? std::clamp(b[3 * k + c], 0.0f, 1.0f) : b[3 * k + c];
            sum += std::abs(a[3 * k + c] - r) / 3;
        }
    });
    return n ? sum / n : 0.0;
}

// Coverage threshold: the images differ only along silhouettes. The shader path draws a
// tessellated sphere (100 x 200 quads: the chord of a 1.8 degree facet lies inside the true
// outline by R (1 - cos(0.9 deg)) ~ 1e-4 R, far below a pixel) rasterised with OpenGL's
// pixel-centre and top-left rules, while the closed form samples each pixel centre exactly.
// A pixel differs only where the outline passes within about half a pixel of its centre, so
// the differing fraction is ~ (perimeter in pixels) / (area in pixels) x 0.5 . At 360 x 120
// the default ball's two images cover some hundreds of pixels each with outlines of ~ 60-100
// pixels: ~ 1-2 %, and the stitching rim between the branches (seed 001 section 5.2) adds a
// few pixels where the two branch images fuse. 3 % leaves room for that and still fails if a
// layer is missing, shifted by a pixel or mirrored (each would be > 10 %).
constexpr double kCoverageTolerance = 0.03;

TEST(GpuGodelRender, DefaultSceneCoverageMatchesClosedForm) {
    const lc::Scene scene = defaultScene(360, 120);
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    const GodelImages im = renderBoth(gpu, scene);
    const std::vector<int>& ids = im.ids;
    const lc::RenderResult& cpu = im.cpu;
    const Coverage c = im.coverage();
    std::printf(
        "default scene 360x120: %zu object pixels, %zu differ (%.2f %%), %zu triangles, %d layers, vertex step %.3f "
        "s\n",
        c.objectPixels, c.differing, 100 * c.fraction(), gpu->GetNumberOfTriangles(), gpu->GetNumberOfLayers(),
        gpu->GetVertexSeconds());
    ASSERT_NO_FATAL_FAILURE(expectCoverage(c, 200, kCoverageTolerance));
    // Negative controls: the comparison does see a left-right mirrored or a one-row-shifted
    // image (the default scene is symmetric about the horizon, so not an up-down mirror).
    std::vector<int> mirrored(ids.size()), shifted(ids.size(), -1);
    for (int j = 0; j < 120; ++j)
        for (int i = 0; i < 360; ++i) {
            mirrored[j * 360 + i] = ids[j * 360 + 359 - i];
            if (j > 0) shifted[j * 360 + i] = ids[(j - 1) * 360 + i];
        }
    EXPECT_GT(compareCoverage(mirrored, cpu).fraction(), 0.1);
    EXPECT_GT(compareCoverage(shifted, cpu).fraction(), 2 * kCoverageTolerance);
    // The ball is seen twice (front and back, docs/PHYSICS.md section 3): two separate images.
    EXPECT_EQ(components(ids, 360, 120, true), 2);
    EXPECT_EQ(components(cpuIds(cpu), 360, 120, true), 2);
}

TEST(GpuGodelRender, OffAxisObserverTwoWindingsCoverageMatchesClosedForm) {
    lc::Scene scene = defaultScene(360, 120);
    scene.observer = lc::Vec4(0, -0.3, 0.4, 0.1);
    scene.settings.windings = 2;
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    EXPECT_EQ(gpu->GetWindings(), 2);
    const GodelImages im = renderBoth(gpu, scene);
    const Coverage c = im.coverage();
    std::printf("off-axis observer, windings 2: %zu object pixels, %zu differ (%.2f %%), components gpu %d cpu %d\n",
                c.objectPixels, c.differing, 100 * c.fraction(), components(im.ids, 360, 120, true),
                components(cpuIds(im.cpu), 360, 120, true));
    expectCoverage(c, 200, kCoverageTolerance);
}

// Two balls, the farther one partly behind the nearer one in some images, with windings 0..2:
// every layer of both objects goes through one depth buffer (lambda / lambdaMax), so the
// object id of each pixel must be the closed form's nearest hit.
TEST(GpuGodelRender, TwoObjectsOccludeThroughOneDepthBuffer) {
    // Parsed, so that the reader gives each ball its Goedel placement (the closed form uses it).
    lc::Scene fresh = lc::io::parseScene(R"({"metric": {"name": "godel", "a": 1.0},
        "observer": {"position": [0, 0, 0, 0]},
        "camera": {"projection": "panorama", "width": 360, "height": 120, "fov": [360, 120]},
        "objects": [{"type": "sphere", "name": "near", "centre": [0, 0.0, 0.9, 0.0], "radius": 0.25,
                     "texture": {"type": "checker", "cells": [16, 8], "colors": [[0.95, 0.95, 0.9], [0.8, 0.15, 0.1]]}},
                    {"type": "sphere", "name": "far", "centre": [0, 0.0, 1.55, 0.05], "radius": 0.35,
                     "texture": {"type": "solid", "color": [0.2, 0.5, 0.9]}}],
        "render": {"windings": 2}})",
                                         "two balls");
    fresh.settings.progress = false;
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(fresh);
    const GodelImages im = renderBoth(gpu, fresh);
    const std::vector<int>& ids = im.ids;
    const Coverage c = im.coverage();
    std::size_t near = 0, farPixels = 0;
    for (int id : ids) {
        near += id == 0;
        farPixels += id == 1;
    }
    // The scene must really test occlusion: pixels of the near ball that the far ball's own
    // images (rendered alone) also cover.
    lc::Scene alone = fresh;
    alone.spheres.erase(alone.spheres.begin());
    vtkNew<vtkLightconeGodelImageRenderer> farOnly;
    farOnly->SetScene(alone);
    const std::vector<int> farIds = farOnly->RenderObjectIds();
    std::size_t hidden = 0;
    for (std::size_t k = 0; k < ids.size(); ++k) hidden += ids[k] == 0 && farIds[k] == 0;
    std::printf(
        "two balls, windings 2: %zu object pixels, %zu differ (%.2f %%), near %zu, far %zu, far hidden behind near "
        "%zu, %d layers\n",
        c.objectPixels, c.differing, 100 * c.fraction(), near, farPixels, hidden, gpu->GetNumberOfLayers());
    EXPECT_GT(near, 100u);
    EXPECT_GT(farPixels, 100u);
    EXPECT_GT(hidden, 20u);  // the scene does test occlusion
    EXPECT_LT(c.fraction(), kCoverageTolerance);
}

TEST(GpuGodelRender, PinholeCoverageMatchesClosedForm) {
    lc::Scene scene = defaultScene(240, 160);
    scene.camera.projection = lc::Camera::Projection::Pinhole;
    scene.camera.fovXDeg = 100;
    scene.camera.fovYDeg = 76;
    scene.camera.forward = lc::Vec3(0.2, 1, 0);  // towards the ball
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    const Coverage c = renderBoth(gpu, scene).coverage();
    std::printf("pinhole 240x160: %zu object pixels, %zu differ (%.2f %%)\n", c.objectPixels, c.differing,
                100 * c.fraction());
    expectCoverage(c, 200, kCoverageTolerance);
}

// The seed-000 strip panorama (220 x 25 degrees, here 220 x 60 to hold the images) turned so
// that an edge cuts an image: triangles leaving a partial panorama are clipped, not wrapped.
TEST(GpuGodelRender, PartialPanoramaCoverageMatchesClosedForm) {
    lc::Scene scene = defaultScene(330, 90);
    scene.camera.fovXDeg = 220;
    scene.camera.fovYDeg = 60;
    for (double deg : {90.0, 200.0, -20.0}) {
        scene.camera.forward = lc::Vec3(std::cos(deg * lc::kPi / 180), std::sin(deg * lc::kPi / 180), 0);
        vtkNew<vtkLightconeGodelImageRenderer> gpu;
        gpu->SetScene(scene);
        const Coverage c = renderBoth(gpu, scene).coverage();
        std::printf("panorama 220x60 deg, forward %.0f deg: %zu object pixels, %zu differ (%.2f %%)\n", deg,
                    c.objectPixels, c.differing, 100 * c.fraction());
        SCOPED_TRACE(deg);
        expectCoverage(c, 50, kCoverageTolerance);
    }
}

// Texture: inside the pixels that both renderers call object, the checker colour of the shader
// path against lc::shadePixels of the closed form. Most pixels match exactly; a pixel whose
// centre lies within the error of the interpolated uv (a facet is 1/200 of u, 1/100 of v wide,
// interpolated linearly in the image instead of following the exact ray) of a checker edge
// takes the other colour. With 16 x 8 cells and ~ 10-20 pixels per cell edge in the image
// such pixels are < ~10 %; the two colours differ by ~ 0.5 per channel on average, so the
// mean absolute difference stays below 0.05 (plus 1/255 quantisation of the 8-bit texture),
// while a flipped v, a shifted u or a wrong texture gives ~ 0.25.
TEST(GpuGodelRender, TextureColoursMatchClosedForm) {
    const lc::Scene scene = defaultScene(360, 120);
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    const GodelImages im = renderBoth(gpu, scene, Colour::Yes);
    const std::vector<int>& ids = im.ids;
    const std::vector<float>& colour = im.colour;
    dump("gpu_default", colour, 360, 120);
    dump("cpu_default", im.ref, 360, 120);
    std::size_t mismatched = 0;
    const std::size_t n = forCommonPixels(im, [&](std::size_t k) {
        double d = 0;
        for (int c = 0; c < 3; ++c) d += std::abs(colour[3 * k + c] - im.ref[3 * k + c]);
        mismatched += d > 0.1;
    });
    const double mean = n ? meanDifference(im, colour, im.ref) : 1.0;
    std::printf("texture: %zu common object pixels, mean |difference| %.4f, %zu pixels with another colour\n", n, mean,
                mismatched);
    ASSERT_GT(n, 200u);
    EXPECT_LT(mean, 0.05);
    // Background: outside every object the shader path shows the scene's background colour.
    std::size_t bg = 0, bgWrong = 0;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        if (ids[k] >= 0) continue;
        ++bg;
        for (int c = 0; c < 3; ++c) bgWrong += std::abs(colour[3 * k + c] - scene.background(c)) > 2.0 / 255;
    }
    EXPECT_GT(bg, 0u);
    EXPECT_EQ(bgWrong, 0u);
}

// Camera orbit: only the projection uniforms change, the geometry stays on the GPU. A full
// turn of the forward vector about `up` must bring back the same image; the frame rate is
// reported (llvmpipe on 2 cores is the slow end).
TEST(GpuGodelRender, CameraOrbitReusesGeometry) {
    const lc::Scene scene = defaultScene(360, 120);
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    const std::vector<int> first = gpu->RenderObjectIds();
    const int frames = 36;
    gpu->Render();
    const auto t0 = std::chrono::steady_clock::now();
    for (int f = 1; f <= frames; ++f) {
        const double angle = 2 * lc::kPi * f / frames;
        gpu->SetCameraOrientation(lc::Vec3(std::cos(angle), std::sin(angle), 0), lc::Vec3(0, 0, 1));
        gpu->Render();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // The same orbit with the colour image read back every frame.
    const auto t1 = std::chrono::steady_clock::now();
    for (int f = 1; f <= frames; ++f) {
        const double angle = 2 * lc::kPi * f / frames;
        gpu->SetCameraOrientation(lc::Vec3(std::cos(angle), std::sin(angle), 0), lc::Vec3(0, 0, 1));
        EXPECT_EQ(gpu->RenderColour().size(), 3u * 360 * 120);
    }
    const double withReadback = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    std::printf(
        "orbit: %d frames at 360x120, %zu triangles (x2 seam copies): %.1f fps, %.1f fps with read-back "
        "(vertex step once: %.3f s)\n",
        frames, gpu->GetNumberOfTriangles(), frames / seconds, frames / withReadback, gpu->GetVertexSeconds());
    const std::vector<int> last = gpu->RenderObjectIds();
    std::size_t diff = 0, obj = 0;
    for (std::size_t k = 0; k < first.size(); ++k) {
        obj += first[k] >= 0 || last[k] >= 0;
        diff += first[k] != last[k];
    }
    ASSERT_GT(obj, 0u);
    EXPECT_LT(static_cast<double>(diff) / obj, 0.01);  // rounding of the rotated frame only

    // Half a turn: the ball's images move by half the panorama width.
    gpu->SetCameraOrientation(lc::Vec3(-1, 0, 0), lc::Vec3(0, 0, 1));
    const std::vector<int> half = gpu->RenderObjectIds();
    std::size_t moved = 0;
    for (int j = 0; j < 120; ++j)
        for (int i = 0; i < 360; ++i) moved += first[j * 360 + i] != half[j * 360 + (i + 180) % 360];
    EXPECT_LT(static_cast<double>(moved) / obj, 0.02);
}

// An image texture (synthetic, smooth, periodic in u) is filtered linearly on the GPU as
// lc::ImageTexture::sample filters it on the CPU. The colour varies by ~ 1 over the ball, so a
// uv error of a facet's size (0.005 in u, 0.01 in v) changes it by < 0.01, plus 1/255
// quantisation: mean |difference| < 0.02; v upside down gives ~ 0.09.
TEST(GpuGodelRender, ImageTextureMatchesClosedForm) {
    lc::Scene scene = defaultScene(360, 120);
    const int w = 64, h = 32;
    std::vector<float> rgb(3 * w * h), flipped(3 * w * h);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const double u = (i + 0.5) / w, v = (j + 0.5) / h;
            const float c[3] = {static_cast<float>(0.5 + 0.4 * std::sin(2 * lc::kPi * u)),
                                static_cast<float>(0.1 + 0.8 * v),
                                static_cast<float>(0.5 + 0.4 * std::cos(2 * lc::kPi * u) * (1 - v))};
            for (int k = 0; k < 3; ++k) {
                rgb[3 * (j * w + i) + k] = c[k];
                flipped[3 * ((h - 1 - j) * w + i) + k] = c[k];
            }
        }
    scene.spheres[0].texture = std::make_shared<lc::ImageTexture>(w, h, rgb);
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    const GodelImages im = renderBoth(gpu, scene, Colour::Yes);
    scene.spheres[0].texture = std::make_shared<lc::ImageTexture>(w, h, flipped);
    const std::vector<float> wrong = lc::shadePixels(scene, im.cpu);
    ASSERT_GT(commonPixels(im), 200u);
    const double mean = meanDifference(im, im.colour, im.ref), meanWrong = meanDifference(im, im.colour, wrong);
    std::printf("image texture: mean |difference| %.4f (v flipped: %.3f)\n", mean, meanWrong);
    EXPECT_LT(mean, 0.02);
    EXPECT_GT(meanWrong, 0.05);
}

// A black-body ball (temperature instead of texture): the Planck colour everywhere on it.
TEST(GpuGodelRender, BlackbodyBallHasPlanckColour) {
    lc::Scene scene = defaultScene(360, 120);
    scene.spheres[0].temperature = 3000;
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    const GodelImages im = renderBoth(gpu, scene, Colour::Yes);
    double worst = 0;
    const std::size_t n = forCommonPixels(im, [&](std::size_t k) {
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, static_cast<double>(std::abs(im.colour[3 * k + c] - im.ref[3 * k + c])));
    });
    ASSERT_GT(n, 200u);
    // 8-bit texture and framebuffer, tabulated Planck colours (BlackbodyTable interpolates
    // linearly between 1024 samples): a few 1/255 steps at most.
    EXPECT_LT(worst, 4.0 / 255);
}

// Panorama seam: turn the camera about `up` so that each image straddles the +-180 degree edge;
// at every angle the shader path (centroid-unwrapped azimuths plus the shifted copy) must
// match the closed form, which has no seam at all.
TEST(GpuGodelRender, PanoramaSeamMatchesClosedForm) {
    lc::Scene scene = defaultScene(240, 80);
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    // A coarse twin (22-30 degree facets on the ball, many pixels in a 720 x 240 image): a triangle
    // cut by the edge leaves more than a sub-pixel sliver on the far side, which only the
    // shifted copy draws. Its reference is itself turned by half a turn (image in the middle,
    // no seam), rolled by half the width: the panorama is periodic, so the two must agree.
    vtkNew<vtkLightconeGodelImageRenderer> coarse;
    coarse->SetScene(defaultScene(720, 240));
    coarse->SetLatitudes(8);
    coarse->SetLongitudes(12);
    // Azimuth of each image's centre seen with forward = +x (azimuth positive to the left).
    std::vector<int> labels;
    const std::vector<int> ids0 = gpu->RenderObjectIds();
    const int n = components(ids0, 240, 80, true, 4, &labels);
    ASSERT_EQ(n, 2);
    std::vector<double> centres;
    for (int l = 0; l < n; ++l) {
        double c = 0, s = 0;
        for (std::size_t k = 0; k < labels.size(); ++k)
            if (labels[k] == l) {
                const double az = -(2.0 * (k % 240 + 0.5) / 240 - 1) * lc::kPi;
                c += std::cos(az);
                s += std::sin(az);
            }
        centres.push_back(std::atan2(s, c));
    }
    int seamCrossings = 0;
    double worst = 0, worstCoarse = 0;
    for (double centre : centres)
        for (double offsetDeg : {0.0, -2.0, 3.0}) {
            // Turn the camera so that this image's centre lies on the +-180 degree edge.
            const double angle = centre - lc::kPi + offsetDeg * lc::kPi / 180;
            const lc::Vec3 forward(std::cos(angle), std::sin(angle), 0);
            scene.camera.forward = forward;
            gpu->SetCameraOrientation(forward, scene.camera.up);
            const GodelImages im = renderBoth(gpu, scene);
            const std::vector<int>& ids = im.ids;
            bool left = false, right = false;
            for (int j = 0; j < 80; ++j) {
                left = left || ids[j * 240] >= 0;
                right = right || ids[j * 240 + 239] >= 0;
            }
            seamCrossings += left && right;
            const Coverage c = im.coverage();
            worst = std::max(worst, c.fraction());
            EXPECT_LT(c.fraction(), kCoverageTolerance) << "forward azimuth " << angle * 180 / lc::kPi << " deg";

            coarse->SetCameraOrientation(forward, scene.camera.up);
            const std::vector<int> atSeam = coarse->RenderObjectIds();
            coarse->SetCameraOrientation(-forward, scene.camera.up);
            const std::vector<int> inMiddle = coarse->RenderObjectIds();
            std::size_t obj = 0, diff = 0;
            for (int j = 0; j < 240; ++j)
                for (int i = 0; i < 720; ++i) {
                    const int p = atSeam[j * 720 + i], q = inMiddle[j * 720 + (i + 360) % 720];
                    obj += p >= 0 || q >= 0;
                    diff += p != q;
                }
            ASSERT_GT(obj, 0u);
            worstCoarse = std::max(worstCoarse, static_cast<double>(diff) / obj);
            // Float rounding of the turned frame only: measured 0 pixels here; 0.3 % of the
            // ~3300 object pixels allows ~10. Without the copy 30-40 pixels go missing.
            EXPECT_LT(static_cast<double>(diff) / obj, 0.003)
                << obj << " coarse, forward azimuth " << angle * 180 / lc::kPi;
        }
    std::printf(
        "seam: %d of %zu orientations put an image across the seam, worst difference %.2f %% (closed form), "
        "%.2f %% (coarse mesh, against itself turned by 180 degrees)\n",
        seamCrossings, 3 * centres.size(), 100 * worst, 100 * worstCoarse);
    EXPECT_GE(seamCrossings, 4);
}

// Lighting (data/godel_lit_sphere.json, seed 000 Fig. 4): per-vertex light from
// lc::GodelLighting (godel::ShadowTester through the isometries) interpolated over the
// triangles, against the closed form's per-pixel light. The light varies smoothly over the
// ball except at the terminator, where linear interpolation over a 1.8 x 1.8 degree facet
// of a Lambert cosine clipped at zero differs by at most ~ the facet's cosine change (~0.03)
// and the shadowed/lit transition is smeared over one facet; mean |difference| < 0.03 holds
// with margin, while dropping the light (ambient only) or lighting the wrong side gives > 0.2.
TEST(GpuGodelRender, LightingMatchesClosedForm) {
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/godel_lit_sphere.json");
    scene.camera.width = 240;
    scene.camera.height = 180;
    scene.settings.progress = false;
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    gpu->SetLatitudes(50);
    gpu->SetLongitudes(100);
    const GodelImages im = renderBoth(gpu, scene, Colour::Yes);
    dump("gpu_lit", im.colour, 240, 180);
    dump("cpu_lit", im.ref, 240, 180);
    double sumUnlit = 0, brightGpu = 0, brightCpu = 0;
    const std::size_t n = forCommonPixels(im, [&](std::size_t k) {
        for (int c = 0; c < 3; ++c) {
            // The framebuffer holds [0, 1]; shadePixels does not clamp (the lit side exceeds 1).
            const double r = std::clamp(im.ref[3 * k + c], 0.0f, 1.0f);
            sumUnlit += std::abs(0.08 * 0.9 - r) / 3;
            brightGpu += im.colour[3 * k + c];
            brightCpu += r;
        }
    });
    ASSERT_GT(n, 200u);
    const double mean = meanDifference(im, im.colour, im.ref, ClampB::Yes);
    std::printf(
        "lighting: %zu pixels, mean |difference| %.4f (ambient only would be %.3f), mean brightness gpu %.3f cpu %.3f, "
        "vertex step %.2f s\n",
        n, mean, sumUnlit / n, brightGpu / (3 * n), brightCpu / (3 * n), gpu->GetVertexSeconds());
    EXPECT_LT(mean, 0.03);
    EXPECT_GT(sumUnlit / n, 0.1);  // the scene is really lit: the check can fail
}

}  // namespace

namespace {

// A freely falling body (emission events solved per vertex on its world line) and a mesh
// object: the shader image against the CPU per-vertex raster of the same photo-object layers,
// whose own correctness is tested against the per-pixel closed form and the static solver.
TEST(GpuGodelRender, FreeFallAndMeshMatchCpuPerVertex) {
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/godel_free_fall_earth.json");
    scene.camera.width = 440;
    scene.camera.height = 50;
    lc::MeshObject box;
    box.name = "box";
    box.centre = lc::Vec4(0, -0.6, -0.6, 0.2);
    const double h = 0.1;
    for (int k = 0; k < 8; ++k) box.positions.emplace_back(k & 1 ? h : -h, k & 2 ? h : -h, k & 4 ? h : -h);
    box.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                     {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    box.texture = std::make_shared<lc::SolidTexture>(lc::Vec3(0.2, 0.8, 0.2));
    scene.meshes.push_back(box);
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    gpu->SetLatitudes(24);
    gpu->SetLongitudes(48);
    const GodelImages im = renderBoth(gpu, scene, Colour::No, Reference::PerVertex);
    std::size_t boxPixels = 0;
    for (int id : im.ids) boxPixels += id == 1;
    // Same triangles on both sides: only rasterisation rules on shared edges differ.
    ASSERT_NO_FATAL_FAILURE(expectCoverage(im.coverage(), 200, 0.03));
    EXPECT_GT(boxPixels, 10u);  // the mesh object is drawn
}

}  // namespace

namespace {

// Day/night multitexture: the shader image of the lit earth against lc::shadePixels (which
// applies lc::dayNightColour); and the night texture really contributes (without it the
// image is measurably different on the CPU side too).
TEST(GpuGodelRender, DayNightMultitextureMatchesCpu) {
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/godel_lit_earth.json");
    scene.camera.width = 240;
    scene.camera.height = 180;
    // A uniform night colour: the city-light map is black over the oceans that face us here.
    scene.spheres[0].nightTexture = std::make_shared<lc::SolidTexture>(lc::Vec3(0.3, 0.25, 0.05));
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    gpu->SetLatitudes(50);
    gpu->SetLongitudes(100);
    const GodelImages im = renderBoth(gpu, scene, Colour::Yes);
    lc::Scene dayOnly = scene;
    dayOnly.spheres[0].nightTexture = nullptr;
    const std::vector<float> refDay = lc::shadePixels(dayOnly, im.cpu);
    const std::size_t n = commonPixels(im);
    ASSERT_GT(n, 200u);
    const double diff = meanDifference(im, im.colour, im.ref, ClampB::Yes),
                 nightEffect = meanDifference(im, im.ref, refDay);
    std::printf("day/night: %zu pixels, mean |gpu - cpu| %.4f, mean night contribution %.4f\n", n, diff, nightEffect);
    EXPECT_LT(diff, 0.03);  // texture filtering and per-vertex light interpolation
    EXPECT_GT(nightEffect, 1e-3);
}

}  // namespace

namespace {

// The many-images scene (windings 0..5, twelve images crowding towards the horizon line):
// coverage against the CPU closed form. The thinnest old images are a few pixels tall, so
// the silhouette share is larger here than in the default scene.
TEST(GpuGodelRender, ManyImagesSceneCoverageMatchesClosedForm) {
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/godel_many_images.json");
    scene.camera.width = 540;
    scene.camera.height = 210;
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    gpu->SetLatitudes(60);
    gpu->SetLongitudes(120);
    const GodelImages im = renderBoth(gpu, scene);
    const Coverage c = im.coverage();
    std::printf("many images 540x210: %zu object pixels, %zu differ (%.2f %%), %d layers\n", c.objectPixels,
                c.differing, 100 * c.fraction(), gpu->GetNumberOfLayers());
    ASSERT_NO_FATAL_FAILURE(expectCoverage(c, 500, 0.05));
    EXPECT_GE(components(cpuIds(im.cpu), 540, 210, true), 6);  // several separate images
}

}  // namespace

namespace {

// A freely falling black-body body: the Doppler factor varies over its images, the shader
// looks up Planck(D T) per fragment in the lookup texture; the CPU raster interpolates D per
// pixel and evaluates the same table. Colours agree; and D really varies (not a flat colour).
TEST(GpuGodelRender, MovingBlackBodyDopplerColoursMatchCpu) {
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/godel_free_fall_earth.json");
    scene.camera.width = 440;
    scene.camera.height = 50;
    scene.spheres[0].temperature = 6000;
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    gpu->SetLatitudes(24);
    gpu->SetLongitudes(48);
    const GodelImages im = renderBoth(gpu, scene, Colour::Yes, Reference::PerVertex);
    double dMin = 1e9, dMax = 0;
    const std::size_t n = forCommonPixels(im, [&](std::size_t k) {
        dMin = std::min(dMin, double(im.cpu.pixels[k].frequencyRatio));
        dMax = std::max(dMax, double(im.cpu.pixels[k].frequencyRatio));
    });
    ASSERT_GT(n, 200u);
    const double diff = meanDifference(im, im.colour, im.ref, ClampB::Yes);
    std::printf("moving black body: %zu pixels, D in [%.3f, %.3f], mean |gpu - cpu| %.4f\n", n, dMin, dMax, diff);
    EXPECT_GT(dMax - dMin, 0.1);  // a real Doppler gradient
    EXPECT_LT(diff, 0.02);        // 8-bit read-back, texture vs analytic table interpolation
}

}  // namespace
