// The fragment-shader Hamiltonian tracer on data/kerr.json at 480x240 against the CPU
// renderNumeric (2 threads), at the CPU's own tolerance and at the shader's. Run under
// xvfb-run from the repository root; on these machines the "GPU" is Mesa llvmpipe.
#include "bench_common.hpp"
#include "core/render.hpp"
#include "readers/io/scene_reader.hpp"
#include "vtkLightconeGeodesicShaderRenderer.h"

#include <cstdio>

int main(int argc, char** argv) {
    const std::string file = argc > 1 ? argv[1] : "data/kerr.json";
    lc::Scene scene = lc::io::readScene(file);
    scene.camera.width = 480;
    scene.camera.height = 240;
    scene.settings.progress = false;
    vtkNew<vtkLightconeGeodesicShaderRenderer> gpu;
    gpu->SetScene(scene);
    gpu->RenderColour();  // shader compilation and texture upload
    const int frames = 3;
    double gpuSeconds = 0;
    for (int f = 0; f < frames; ++f) {
        gpu->RenderColour();
        gpuSeconds += gpu->GetLastRenderSeconds() / frames;
    }
    const std::vector<int> ids = gpu->RenderIds();
    const lc::RenderResult cpu = lc::renderNumeric(scene);
    lc::Scene loose = scene;
    loose.settings.trace.absTol = loose.settings.trace.relTol = gpu->GetTolerance();
    const lc::RenderResult cpuLoose = lc::renderNumeric(loose);
    std::size_t shadow = 0, differ = 0;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        const bool c = cpu.pixels[k].kind == lc::PixelRecord::Horizon;
        shadow += c;
        differ += c != (ids[k] == vtkLightconeGeodesicShaderRenderer::Horizon);
    }
    std::printf("# Black hole in a fragment shader, %s at 480x240\n\nMachine: %s, OpenGL through Mesa llvmpipe.\n\n",
                file.c_str(), lc::bench::machineName().c_str());
    std::printf("| renderer | tolerance | steps/ray | seconds/frame |\n|---|---|---|---|\n");
    std::printf("| fragment shader (float, Dormand-Prince) | %.0e | - | %.3f |\n", gpu->GetTolerance(), gpuSeconds);
    std::printf("| CPU renderNumeric, 2 threads | %.0e | %.0f | %.2f |\n", scene.settings.trace.relTol, cpu.stats.meanSteps,
                cpu.stats.seconds);
    std::printf("| CPU renderNumeric, 2 threads | %.0e | %.0f | %.2f |\n", loose.settings.trace.relTol,
                cpuLoose.stats.meanSteps, cpuLoose.stats.seconds);
    std::printf("\nShadow: %zu pixels on the CPU, classification differs on %zu.\n", shadow, differ);
    return 0;
}
