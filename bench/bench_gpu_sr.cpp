// SPDX-License-Identifier: BSD-3-Clause
// Frames per second of special-relativistic rendering (seed 003 Table 1) at 1280 x 720:
// local ray tracing against polygon distortion, through VTK/OpenGL shaders
// (vtkLightconeSrImageRenderer) and on the CPU (lc::sr::SrRenderer, same image).
// Run under xvfb-run; without a GPU the OpenGL numbers are Mesa's software rasteriser.
//
//   "GPU draw": geometry built once, only the draw (+ glFinish) per frame: a static camera.
//   "GPU frame": the observer time changes every frame, so the per-triangle footprints
//                (local ray tracing) or apparent vertices (polygon distortion) are rebuilt on
//                the CPU and uploaded: the cost of an animation.
//   "CPU": lc::sr::SrRenderer::render of the same image (OpenMP on all cores).
#include "bench_common.hpp"
#include "core/sr/mesh.hpp"
#include "core/sr/renderer.hpp"
#include "vtkLightconeSrImageRenderer.h"

#include <cmath>
#include <vtkNew.h>
#include <vtkRenderWindow.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Case {
    std::string name;
    lc::sr::SrScene scene;
};

// Seed 003's cube: edge 4, moving at 0.95 c along x, seen straight ahead at t = 0.
lc::sr::SrScene movingScene(lc::sr::TriMesh mesh) {
    lc::sr::SrScene s;
    s.objects.push_back({std::move(mesh), lc::sr::MovingFrame(lc::Vec3(0.95, 0, 0), lc::Vec3(9.5, 0, -10)), {}});
    s.lightPosition = lc::Vec3(0, 10, 10);
    return s;
}

// Repeats f until at least minSeconds and minFrames have passed; frames per second.
template <class F>
double fps(F&& f, double minSeconds, int minFrames) {
    int frames = 0;
    double total = 0;
    while (total < minSeconds || frames < minFrames) {
        total += lc::bench::seconds(f);
        ++frames;
    }
    return frames / total;
}

}  // namespace

int main(int argc, char** argv) {
    // OpenMP threads that spin at barriers starve llvmpipe's rasteriser threads (and the
    // other way round) on a small machine: both renderers become ~10x slower. libgomp reads
    // the policy when it loads, so set it and start again.
    if (!std::getenv("OMP_WAIT_POLICY")) {
        setenv("OMP_WAIT_POLICY", "passive", 1);
        execv("/proc/self/exe", argv);
    }
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const int W = quick ? 320 : 1280, H = quick ? 180 : 720;
    const double minSeconds = quick ? 0.2 : 1.5;
    lc::sr::ObserverCamera cam;
    cam.width = W;
    cam.height = H;
    cam.fovYDeg = 75.0;
    cam.fovXDeg = 2 * std::atan(std::tan(0.5 * cam.fovYDeg * lc::kPi / 180) * W / H) * 180 / lc::kPi;  // square pixels
    cam.forward = lc::Vec3(0, 0, -1);
    cam.up = lc::Vec3(0, 1, 0);

    std::vector<Case> cases;
    cases.push_back({"cube, 50 triangles per face", movingScene(lc::sr::makeCube(4.0, 5))});
    cases.push_back({"cube, 200 triangles per face", movingScene(lc::sr::makeCube(4.0, 10))});
    cases.push_back({"UV sphere 128 x 120, r = 2", movingScene(lc::sr::makeUvSphere(2.0, 128, 120))});

    std::printf("# Special relativity: local ray tracing vs polygon distortion, %d x %d\n\n", W, H);
    std::printf(
        "Machine: %s. OpenGL: Mesa llvmpipe software rasteriser under Xvfb (no GPU), so the\n"
        "\"GPU\" columns measure VTK's OpenGL path on the CPU cores.\n\n",
        lc::bench::machineName().c_str());
    std::printf("OMP_WAIT_POLICY=%s.\n\n", std::getenv("OMP_WAIT_POLICY"));
    std::printf(
        "| scene | triangles | method | quads (full screen) | GPU draw fps | GPU frame fps (incl. CPU rebuild) | "
        "CPU rebuild ms | CPU SrRenderer fps | draw / CPU |\n");
    std::printf("|---|---:|---|---:|---:|---:|---:|---:|---:|\n");
    const lc::sr::SrRenderer cpu;
    for (const Case& c : cases) {
        std::size_t triangles = 0;
        for (const auto& o : c.scene.objects) triangles += o.mesh.triangles.size();
        for (int mode :
             {vtkLightconeSrImageRenderer::LocalRayTracing, vtkLightconeSrImageRenderer::PolygonDistortion}) {
            vtkNew<vtkLightconeSrImageRenderer> gpu;
            gpu->SetScene(c.scene, cam);
            gpu->SetMode(mode);
            gpu->Render();  // build, compile the shaders, upload
            vtkRenderWindow* win = gpu->GetRenderWindow();
            const double draw = fps(
                [&] {
                    gpu->Render();
                    win->WaitForCompletion();
                },
                minSeconds, 5);
            double t = 0, build = 0;
            int builds = 0;
            const double frame = fps(
                [&] {
                    t += 1e-3;
                    gpu->SetObserverTime(t);
                    gpu->Render();
                    win->WaitForCompletion();
                    build += gpu->GetBuildSeconds();
                    ++builds;
                },
                minSeconds, 5);
            lc::sr::SrRenderOptions opt;
            opt.mode = mode == vtkLightconeSrImageRenderer::LocalRayTracing ? lc::sr::SrRenderMode::LocalRayTracing
                                                                            : lc::sr::SrRenderMode::PolygonDistortion;
            const double cpuFps = fps([&] { (void)cpu.render(c.scene, cam, opt); }, minSeconds, 2);
            const bool lrt = mode == vtkLightconeSrImageRenderer::LocalRayTracing;
            std::printf("| %s | %zu | %s | %s | %.1f | %.1f | %.1f | %.2f | %.1fx |\n", c.name.c_str(), triangles,
                        lrt ? "local ray tracing" : "polygon distortion",
                        lrt ? (std::to_string(gpu->GetNumberOfQuads()) + " (" +
                               std::to_string(gpu->GetNumberOfFullScreenQuads()) + ")")
                                  .c_str()
                            : "-",
                        draw, frame, 1e3 * build / builds, cpuFps, draw / cpuFps);
            std::fflush(stdout);
        }
    }
    return 0;
}
