// SPDX-License-Identifier: BSD-3-Clause
// The fragment-shader Hamiltonian tracer for every metric, its GLSL generated from the metric's
// code: frame time, trial steps per ray (and where they go: sky, horizon, failed) and the
// agreement with the CPU renderNumeric (double precision, odeint, 2 threads) on the same scene:
// pixels whose class (sky / horizon / background) differs, and the mean colour difference.
// Usage: bench_gpu_geodesic [WIDTH HEIGHT [kerr]]  (default 1024 512; "kerr": only the Kerr
// speed-against-agreement table). Run under xvfb-run from the
// repository root; on these machines the "GPU" is Mesa llvmpipe on the same cores.
#include "bench_common.hpp"
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"
#include "core/render/render.hpp"
#include "readers/io/scene_reader.hpp"
#include "vtkLightconeNumericImageRenderer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>

namespace {

struct Case {
    std::string label;
    lc::Scene scene;
};

lc::Scene coded(lc::SpacetimePtr st, const lc::Vec4& observer, const lc::Vec3& forward, double fovX, double fovY) {
    lc::Scene s;
    s.spacetime = std::move(st);
    s.observer = observer;
    s.camera.forward = forward;
    s.camera.up = lc::Vec3(0, 0, 1);
    s.camera.fovXDeg = fovX;
    s.camera.fovYDeg = fovY;
    s.sky = std::make_shared<lc::CheckerTexture>(36, 18, lc::Vec3(0.9, 0.9, 0.85), lc::Vec3(0.1, 0.15, 0.3));
    return s;
}

// Two timed colour frames after a first that compiles and uploads, then the id and step passes.
struct GpuRun {
    double seconds = 0;
    std::vector<float> rgb;
    std::vector<int> ids, steps;
};
GpuRun runGpu(vtkLightconeNumericImageRenderer* gpu) {
    GpuRun run;
    gpu->RenderColour();
    for (int f = 0; f < 2; ++f) {
        run.rgb = gpu->RenderColour();
        run.seconds += gpu->GetLastRenderSeconds() / 2;
    }
    run.ids = gpu->RenderIds();
    run.steps = gpu->RenderStepCounts();
    return run;
}

// The GPU image against the CPU's, pixel by pixel.
struct Agreement {
    double meanSteps = 0, meanColour = 0, offFraction = 0;  // off: largest channel off by > 0.05
    int maxSteps = 0;
    std::size_t classDiffers = 0, shadowDiffers = 0;
    std::map<std::pair<int, int>, std::size_t> differences;  // (CPU class, GPU class) -> pixels
};

const char* className(int c) {
    using R = vtkLightconeNumericImageRenderer;
    return c == R::Sky ? "sky" : c == R::Horizon ? "horizon" : c == R::Background ? "background" : "failed";
}
Agreement compare(const GpuRun& gpu, const lc::RenderResult& cpu, const std::vector<float>& cpuRgb) {
    using R = vtkLightconeNumericImageRenderer;
    Agreement a;
    std::size_t off = 0;
    const std::size_t n = gpu.ids.size();
    for (std::size_t k = 0; k < n; ++k) {
        a.meanSteps += gpu.steps[k];
        a.maxSteps = std::max(a.maxSteps, gpu.steps[k]);
        const int kind = cpu.pixels[k].kind;
        const int cpuClass = kind == lc::PixelRecord::Sky          ? R::Sky
                             : kind == lc::PixelRecord::Horizon    ? R::Horizon
                             : kind == lc::PixelRecord::Background ? R::Background
                                                                   : R::Failed;
        a.classDiffers += cpuClass != gpu.ids[k];
        if (cpuClass != gpu.ids[k]) ++a.differences[{cpuClass, gpu.ids[k]}];
        a.shadowDiffers += (cpuClass == R::Horizon) != (gpu.ids[k] == R::Horizon);
        double d = 0;
        for (int q = 0; q < 3; ++q) d = std::max(d, double(std::abs(gpu.rgb[3 * k + q] - cpuRgb[3 * k + q])));
        a.meanColour += d;
        off += d > 0.05;
    }
    a.meanSteps /= n;
    a.meanColour /= n;
    a.offFraction = double(off) / n;
    return a;
}

// The metrics of the first table, each with an observer and a view that shows its features.
std::vector<Case> metricCases() {
    std::vector<Case> cases;
    cases.push_back(
        {"minkowski", coded(std::make_shared<lc::Minkowski>(), lc::Vec4(0, 0, 0, 0), lc::Vec3(1, 0, 0), 90, 45)});
    cases.push_back({"schwarzschild, r = 30 M", coded(std::make_shared<lc::Schwarzschild>(1.0), lc::Vec4(0, 30, 0, 0),
                                                      lc::Vec3(-1, 0, 0), 40, 20)});
    cases.push_back({"kerr a = 0.9 (data/kerr.json)", lc::io::readScene("data/kerr.json")});
    cases.push_back(
        {"kerr-newman a = 0.6, Q = 0.5", coded(std::make_shared<lc::KerrNewman>(1.0, 0.6, 0.5), lc::Vec4(0, 18, 12, 10),
                                               lc::Vec3(-18, -10.5, -10), 60, 30)});
    cases.push_back(
        {"alcubierre v = 1.5, R = 1, sigma = 8", coded(std::make_shared<lc::Alcubierre>(1.5, 1.0, 8.0),
                                                       lc::Vec4(0, 4, 0, 0), lc::Vec3(-1, 0.2, 0.1), 120, 60)});
    lc::Scene godel =
        coded(std::make_shared<lc::GodelCartesian>(1.0), lc::Vec4(0, 0, 0, 0), lc::Vec3(1, 0, 0), 120, 60);
    godel.settings.trace.maxAffine = 12;
    cases.push_back({"godel a = 1 (numeric chart, affine limit 12)", godel});

    return cases;
}

// Speed against agreement for Kerr: the stepper's tolerance and the far-field step cap.
void benchKerrVariants(const lc::Scene& kerr, int width, int height) {
    const lc::RenderResult cpu = lc::renderNumeric(kerr);
    const std::vector<float> cpuRgb = lc::shadePixels(kerr, cpu);
    std::printf("\n## Kerr (data/kerr.json), %dx%d: speed against agreement with the CPU image\n\n", width, height);
    std::printf(
        "| tolerance | step cap (x r) near | far (outgoing) | s/frame | steps/ray | shadow px differ | mean colour "
        "diff | px off by > 0.05 |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    struct Variant {
        double tolerance, near, far;
    };
    for (const Variant v :
         {Variant{1e-5, 0.1, 0.0}, Variant{1e-5, 0.1, 1.0}, Variant{1e-4, 0.1, 1.0}, Variant{1e-5, 0.2, 1.0},
          Variant{1e-5, 0.3, 1.0}, Variant{1e-4, 0.3, 1.0}, Variant{1e-5, 0.5, 1.0}}) {
        vtkNew<vtkLightconeNumericImageRenderer> gpu;
        gpu->SetScene(kerr);  // the CPU reference keeps the scene's cap (0.1 r)
        gpu->SetStepPerRadius(v.near);
        gpu->SetTolerance(v.tolerance);
        gpu->SetFarFieldStepPerRadius(v.far);
        const GpuRun run = runGpu(gpu);
        const Agreement a = compare(run, cpu, cpuRgb);
        std::printf("| %.0e | %.1f | %s | %.3f | %.0f | %zu | %.4f | %.2f%% |\n", v.tolerance, v.near,
                    v.far > 0 ? "1.0" : "as near", run.seconds, a.meanSteps, a.shadowDiffers, a.meanColour,
                    100.0 * a.offFraction);
        std::fflush(stdout);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const int width = argc > 2 ? std::atoi(argv[1]) : 1024, height = argc > 2 ? std::atoi(argv[2]) : 512;
    std::vector<Case> cases = metricCases();
    std::printf(
        "# Fragment-shader tracer per metric, %dx%d\n\nMachine: %s; OpenGL: Mesa llvmpipe under Xvfb (no GPU), 2 "
        "cores.\n\n",
        width, height, lc::bench::machineName().c_str());
    std::printf(
        "| metric | GPU s/frame | GPU steps/ray (mean, max) | CPU s/frame (tol 1e-8) | CPU steps/ray | class differs | "
        "mean colour diff |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    const bool kerrOnly = argc > 3 && std::string(argv[3]) == "kerr";
    std::string differences;  // which classes the differing pixels have on each side
    for (Case& c : cases) {
        c.scene.camera.width = width;
        c.scene.camera.height = height;
        c.scene.settings.progress = false;
        c.scene.settings.threads = 2;
        if (kerrOnly) continue;
        vtkNew<vtkLightconeNumericImageRenderer> gpu;
        gpu->SetScene(c.scene);
        const GpuRun run = runGpu(gpu);
        const lc::RenderResult cpu = lc::renderNumeric(c.scene);
        const Agreement a = compare(run, cpu, lc::shadePixels(c.scene, cpu));
        std::printf("| %s | %.3f | %.0f, %d | %.2f | %.0f | %zu of %zu | %.4f |\n", c.label.c_str(), run.seconds,
                    a.meanSteps, a.maxSteps, cpu.stats.seconds, cpu.stats.meanSteps, a.classDiffers, run.ids.size(),
                    a.meanColour);
        for (const auto& [classes, pixels] : a.differences)
            differences += "- " + c.label + ": " + std::to_string(pixels) + " px " + className(classes.first) +
                           " on the CPU, " + className(classes.second) + " on the GPU\n";
        std::fflush(stdout);
    }
    if (!kerrOnly)
        std::printf(
            "\nGPU steps are trial steps (accepted and rejected), read back in units of 8. Differing classes:\n%s",
            differences.empty() ? "- none\n" : differences.c_str());

    benchKerrVariants(cases[2].scene, width, height);
    return 0;
}
