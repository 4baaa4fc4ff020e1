// SPDX-License-Identifier: BSD-3-Clause
// Post-rendering frame rates (seed 000 section 5.2 and its figures: re-texturing and time shift
// ~2450 fps, frequency shift 8.4 fps at 512 x 512 on a GeForce 8800 GTS, 2009): the GPU
// post-renderer (vtkLightconePostRenderer) against the CPU reference lc::shadePixels (what
// `lightcone shade` runs), 1024 x 512 by default, per effect, with the agreement of the two
// images in 8-bit levels. Each GPU frame changes the effect's parameter (uniforms only), as a
// slider does. Run under xvfb-run -a from the repository root: bench_gpu_post_render [W H [scene.json ...]].
#include "bench_common.hpp"
#include "core/render/post_render.hpp"
#include "core/render/render.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/scene_reader.hpp"
#include "vtkLightconePostRenderer.h"

#include <vtkNew.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace {

using lc::bench::seconds;

struct Effect {
    const char* name;
    std::function<lc::PostRender(int frame)> settings;
};

// The four effects of seed 000 section 5.2, each frame f a new value of its parameter (captured
// by value: the list outlives this call).
std::vector<Effect> seedEffects(const std::shared_ptr<lc::CheckerTexture>& checker, float t0, double span) {
    return {
        {"re-texturing (uv offset)",
         [=](int f) {
             lc::PostRender p;
             p.objectTextures = {checker};
             p.uOffset = 0.01 * f;
             return p;
         }},
        {"frequency shift (temperature)",
         [=](int f) {
             lc::PostRender p;
             p.temperature = 3000 + 100 * (f % 60);
             return p;
         }},
        {"time shift (window over 2nd texture)",
         [=](int f) {
             lc::PostRender p;
             p.timeWindow = std::make_pair(t0 + span * 0.02 * (f % 50), t0 + span * (0.3 + 0.02 * (f % 50)));
             p.outsideTexture = checker;
             return p;
         }},
        {"blinking lights",
         [=](int f) {
             lc::PostRender p;
             p.blinkPeriod = 0.25 * span;
             p.blinkPhase = 0.01 * span * f;
             return p;
         }},
    };
}

// One table row: GPU frames (drawn, then drawn and read back) and CPU frames of one effect, and
// how many pixels of the two last frames differ by one 8-bit level or more.
void benchEffect(vtkLightconePostRenderer* gpu, const lc::Scene& scene, const lc::RenderResult& data, const Effect& e) {
    const int gpuFrames = 40;
    double draw = 0, readBack = 0;
    for (int f = 0; f < gpuFrames; ++f) {
        gpu->SetPostRender(e.settings(f));
        draw += gpu->DrawOnly();
    }
    std::vector<unsigned char> g;
    for (int f = 0; f < gpuFrames; ++f) {
        gpu->SetPostRender(e.settings(f));
        readBack += seconds([&] { g = gpu->RenderSrgb(); });
    }
    // The CPU: shadePixels (every pixel, the reference) and the sweep path (lc::PixelShader, what
    // `shade --sweep` runs: the unchanging pixels coloured once), each frame a new setting.
    auto cpuFps = [&](const std::function<std::vector<float>(const lc::PostRender&)>& shade) {
        int frames = 0;
        const double s = seconds([&] {
            for (; frames < 40; ++frames) shade(e.settings(frames));
        });
        return frames / s;
    };
    const std::vector<float> rgb = lc::shadePixels(scene, data, e.settings(gpuFrames - 1));
    const double fullFps = cpuFps([&](const lc::PostRender& p) { return lc::shadePixels(scene, data, p); });
    lc::PixelShader sweep(scene, data);
    const double sweepFps = cpuFps([&](const lc::PostRender& p) {
        sweep.shade(p);
        return std::vector<float>();
    });
    std::size_t one = 0, more = 0;
    for (std::size_t p = 0; p < data.pixels.size(); ++p) {
        int d = 0;
        for (int c = 0; c < 3; ++c)
            d = std::max(d,
                         std::abs(int(g[3 * p + c]) - int(std::lround(255.0f * lc::io::srgbEncode(rgb[3 * p + c])))));
        one += d == 1;
        more += d > 1;
    }
    const double gpuFps = gpuFrames / draw;
    std::printf("| %s | %.0f | %.0f | %.0f | %.0f | %.2g x | %zu | %zu |\n", e.name, gpuFps, gpuFrames / readBack,
                fullFps, sweepFps, gpuFps / sweepFps, one, more);
}

// One scene's table: traced once on the CPU, then every effect.
void benchScene(const char* name, int width, int height) {
    lc::Scene scene = lc::io::readScene(std::string("data/") + name);
    scene.camera.width = width;
    scene.camera.height = height;
    lc::RenderResult data;
    const double traceSeconds = seconds([&] { data = lc::render(scene); });
    std::size_t objectPixels = 0;
    float t0 = 1e30f, t1 = -1e30f;
    for (const auto& p : data.pixels)
        if (lc::PixelShader::settingsChange(p)) {  // objects and disks: the time windows and blinking span them
            objectPixels += p.kind == lc::PixelRecord::Object;
            t0 = std::min(t0, p.emissionTime);
            t1 = std::max(t1, p.emissionTime);
        }
    vtkNew<vtkLightconePostRenderer> gpu;
    gpu->SetInput(scene, data);
    const double firstSeconds = seconds([&] { gpu->RenderSrgb(); });  // window, shaders, textures
    std::printf(
        "## %s: traced once on the CPU in %.2f s; %zu object pixels (%.1f %%); first GPU frame "
        "(window, shader compile, upload) %.2f s\n\n",
        name, traceSeconds, objectPixels, 100.0 * objectPixels / data.pixels.size(), firstSeconds);
    std::printf(
        "| effect | GPU fps (draw) | GPU fps (draw + read-back) | CPU fps (shadePixels, every pixel) | CPU fps "
        "(PixelShader, shade --sweep) | GPU/CPU sweep | pixels off by 1 level | by more |\n"
        "|---|---|---|---|---|---|---|---|\n");
    const auto checker = std::make_shared<lc::CheckerTexture>(16, 8, lc::Vec3(1, 0.8, 0.1), lc::Vec3(0.05, 0.1, 0.5));
    for (const Effect& e : seedEffects(checker, t0, std::max(1e-3, double(t1 - t0)))) benchEffect(gpu, scene, data, e);
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    if (!std::getenv("DISPLAY")) {
        std::fprintf(stderr, "needs an X display: run under xvfb-run -a\n");
        return 2;
    }
    const int width = argc > 2 ? std::atoi(argv[1]) : 1024, height = argc > 2 ? std::atoi(argv[2]) : 512;
    std::printf("# Post-rendering, %d x %d, %s, %u threads for the CPU reference\n\n", width, height,
                lc::bench::machineName().c_str(), std::thread::hardware_concurrency());
    // Every bundled scene but the formula twins of kerr.json and kerr_disk.json (the same images),
    // or those named after W H.
    std::vector<std::string> scenes{"default.json",
                                    "ellis_wormhole.json",
                                    "godel_free_fall_earth.json",
                                    "godel_lit_earth.json",
                                    "godel_lit_sphere.json",
                                    "godel_many_images.json",
                                    "godel_time_traveller.json",
                                    "kerr.json",
                                    "kerr_disk.json",
                                    "sr_cube.json"};
    if (argc > 3) scenes.assign(argv + 3, argv + argc);
    for (const std::string& name : scenes) {
        try {
            benchScene(name.c_str(), width, height);
        } catch (const std::exception& e) {
            std::printf("## %s: not measured: %s\n\n", name.c_str(), e.what());
        }
    }
    std::printf("GPU here: VTK's GLX path under Xvfb, i.e. Mesa llvmpipe on the CPU (no GPU in this machine).\n");
    return 0;
}
