// SPDX-License-Identifier: BSD-3-Clause
// Frames per second of the shader renderer (views/godel/vtkLightconeGodelImageRenderer) at
// 1024x512 for a 20k-vertex sphere seen 2, 6 and 20 times, with and without lighting,
// against the CPU per-vertex raster and the CPU closed-form per-pixel renderer of the same
// image. Run under xvfb-run: on these machines the "GPU" is Mesa llvmpipe on 2 CPU cores.
#include "bench_common.hpp"
#include "bench_scenes.hpp"
#include "core/godel/images.hpp"
#include "core/scene/godel_placement.hpp"
#include "core/metrics/godel.hpp"
#include "core/render/render.hpp"
#include "vtkLightconeGodelImageRenderer.h"

#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderWindow.h>

#include <chrono>
#include <cstdio>

using namespace lc;

namespace {

Scene makeScene(int windings, bool lit) {
    Scene s = bench::godelBallPanorama(Vec4(0, 0.8, 0, 0.6), 0.2, windings);
    if (lit) {
        PointLight light;
        light.position = Vec4(0, -0.5, 0.5, 0.3);
        s.lights.push_back(light);
    }
    return s;
}

}  // namespace

int main() {
    std::printf("# Goedel shader renderer: frames per second, 1024x512 panorama\n\n");
    std::printf(
        "Machine: %s; OpenGL through Mesa llvmpipe (no GPU), 2 cores. Sphere of 100 x 200 = 19802 vertices.\n\n",
        bench::machineName().c_str());
    std::printf(
        "| windings | images | lighting | vertex step | shader frame (orbit mean) | fps | CPU per-vertex frame | CPU "
        "closed form per pixel |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    for (int windings : {0, 2, 9})
        for (bool lit : {false, true}) {
            const Scene s = makeScene(windings, lit);
            godel::ImageOptions io;
            io.maxWinding = windings;
            const std::size_t images = godel::ImageSolver(1.0).solve(s.spheres[0].centre.tail<3>(), io).images.size();
            vtkNew<vtkLightconeGodelImageRenderer> gpu;
            gpu->SetScene(s);
            gpu->Build();
            gpu->Render();  // first frame: shader compilation
            const int frames = 20;
            const double secs = bench::seconds([&] {
                for (int k = 0; k < frames; ++k) {
                    const double ang = 2 * kPi * k / frames;
                    gpu->SetCameraOrientation(Vec3(std::cos(ang), std::sin(ang), 0), Vec3(0, 0, 1));
                    gpu->Render();
                }
            });
            const RenderResult vertex = renderGodelPerVertex(s);
            const double closed = lit ? -1 : renderGodelClosedForm(s).stats.seconds;
            char closedText[32] = "(lit: per-pixel shading)";
            if (closed >= 0) std::snprintf(closedText, sizeof closedText, "%.2f s", closed);
            std::printf("| %d | %zu | %s | %.2f s | %.1f ms | %.1f | %.0f ms | %s |\n", windings, images,
                        lit ? "yes" : "no", gpu->GetVertexSeconds(), 1e3 * secs / frames, frames / secs,
                        1e3 * vertex.stats.seconds, closedText);
        }
    return 0;
}
