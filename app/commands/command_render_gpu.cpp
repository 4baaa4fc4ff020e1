// SPDX-License-Identifier: BSD-3-Clause
// `lightcone render --gpu`: the image through VTK's OpenGL pipeline with custom shaders,
// offscreen, plus the frame rate of a short animation: Goedel photo-objects
// (views/godel/vtkLightconeGodelImageRenderer, the camera turns: only uniforms change), special
// relativity by local ray tracing (vtkLightconeSrImageRenderer, the observer's time
// advances: footprints rebuilt every frame), black holes by a fragment-shader Hamiltonian
// tracer (vtkLightconeNumericImageRenderer, the camera looks around).
#include "app/commands/commands.hpp"
#include "core/colour/srgb.hpp"
#include "core/metrics/godel.hpp"
#include "core/render/special_relativity.hpp"
#include "core/scene/frame_camera.hpp"
#include "readers/io/image_io.hpp"
#include "vtkLightconeNumericImageRenderer.h"
#include "vtkLightconeGodelImageRenderer.h"
#include "vtkLightconeSrImageRenderer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>

namespace lc::cli {
namespace {

void writeRgb(const std::string& output, const Camera& cam, std::vector<float> rgb) {
    io::ImageChannels img;
    img.width = cam.width;
    img.height = cam.height;
    img.names = {"R", "G", "B"};
    img.data = std::move(rgb);
    io::writeImage(output, img);
}

// Renders `frames` frames, calling setFrame(k) before each, and prints the rate.
void timeAnimation(int frames, const char* what, const std::function<void(int)>& setFrame,
                   const std::function<void()>& render) {
    if (frames <= 0) return;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < frames; ++k) {
        setFrame(k);
        render();
    }
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s: %d frames in %.3f s = %.2f frames per second\n", what, frames, secs, frames / secs);
}

int renderSrImage(const Scene& scene, const std::string& output, int frames, bool polygons) {
    vtkNew<vtkLightconeSrImageRenderer> gpu;
    gpu->SetScene(scene);
    if (polygons) gpu->SetModeToPolygonDistortion();
    std::vector<float> rgb = gpu->RenderColour();  // display sRGB, as the CPU SrRenderer
    for (float& c : rgb) c = static_cast<float>(colour::srgbDecode(c));
    writeRgb(output, scene.camera, std::move(rgb));
    std::printf("rendered %s: %dx%d, special relativity, %s in VTK OpenGL shaders (%zu triangles", scene.source.c_str(),
                scene.camera.width, scene.camera.height, polygons ? "polygon distortion" : "local ray tracing",
                gpu->GetNumberOfTriangles());
    if (!polygons) std::printf(", %zu footprint quads", gpu->GetNumberOfQuads());
    std::printf(")\n");
    timeAnimation(
        frames, "animation (observer time advancing)",
        [&](int k) { gpu->SetObserverTime(scene.observer(0) + 0.2 * k); }, [&] { gpu->Render(); });
    return 0;
}

int renderBlackHole(const Scene& scene, const std::string& output, int frames) {
    if (!scene.spheres.empty() || !scene.meshes.empty())
        throw std::invalid_argument("the geodesic shader draws sky and horizon only; render objects without --gpu");
    vtkNew<vtkLightconeNumericImageRenderer> gpu;
    gpu->SetScene(scene);
    writeRgb(output, scene.camera, gpu->RenderColour());
    std::printf(
        "rendered %s: %dx%d, %s, Hamiltonian rays in a fragment shader (metric and derivatives generated as GLSL from "
        "its code)\n",
        scene.source.c_str(), scene.camera.width, scene.camera.height, scene.spacetime->name().c_str());
    const Vec3& up = scene.camera.up;
    timeAnimation(
        frames, "camera sweep",
        [&](int k) { gpu->SetCameraOrientation(turnedForward(scene, 0.2 * std::sin(2 * kPi * k / frames)), up); },
        [&] { gpu->Render(); });
    return 0;
}

int renderGodel(const Scene& scene, const std::string& output, int frames) {
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    gpu->SetLatitudes(scene.settings.meshLatitudes);
    gpu->SetLongitudes(scene.settings.meshLongitudes);
    gpu->Build();
    const auto t0 = std::chrono::steady_clock::now();
    writeRgb(output, scene.camera, gpu->RenderColour());
    const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("rendered %s: %dx%d, godel, photo-objects through VTK OpenGL shaders (%d layers, %zu triangles)\n",
                scene.source.c_str(), scene.camera.width, scene.camera.height, gpu->GetNumberOfLayers(),
                gpu->GetNumberOfTriangles());
    std::printf("vertex images %.3f s, first frame %.3f s\n", gpu->GetVertexSeconds(), first);
    const Vec3& up = scene.camera.up;
    timeAnimation(
        frames, "camera orbit",
        [&](int k) { gpu->SetCameraOrientation(turnedForward(scene, 2 * kPi * k / frames), up); },
        [&] { gpu->Render(); });
    return 0;
}

}  // namespace

ShaderPath shaderPathFor(const Scene& scene) {
    if (isSrScene(scene) && (!scene.spheres.empty() || !scene.meshes.empty())) return ShaderPath::SpecialRelativity;
    // A black-body or star sky needs p_t conserved (stationary metrics) for the shader's g.
    const bool blackbodySky = scene.skyTemperature || (scene.sky && scene.sky->lightMap());
    const bool skyDrawable = !blackbodySky || scene.spacetime->declaredStationary();
    if (scene.spacetime->asymptoticallyFlat())
        return scene.spheres.empty() && scene.meshes.empty() && skyDrawable ? ShaderPath::BlackHole : ShaderPath::None;
    if (scene.spacetime->godelRadius() && scene.observerVelocity.tail<3>().norm() == 0) return ShaderPath::Godel;
    return ShaderPath::None;
}

std::vector<float> renderShaderImage(const Scene& scene, std::shared_ptr<const std::vector<PhotoSceneObject>> photos) {
    switch (shaderPathFor(scene)) {
        case ShaderPath::SpecialRelativity: {
            vtkNew<vtkLightconeSrImageRenderer> gpu;
            gpu->SetScene(scene);
            std::vector<float> rgb = gpu->RenderColour();  // display sRGB, as the CPU SrRenderer
            for (float& c : rgb) c = static_cast<float>(colour::srgbDecode(c));
            return rgb;
        }
        case ShaderPath::BlackHole: {
            vtkNew<vtkLightconeNumericImageRenderer> gpu;
            gpu->SetScene(scene);
            return gpu->RenderColour();
        }
        case ShaderPath::Godel: {
            vtkNew<vtkLightconeGodelImageRenderer> gpu;
            gpu->SetScene(scene);
            gpu->SetLatitudes(scene.settings.meshLatitudes);
            gpu->SetLongitudes(scene.settings.meshLongitudes);
            gpu->SetPhotoScene(std::move(photos));  // null: built here
            return gpu->RenderColour();
        }
        case ShaderPath::None: break;
    }
    throw std::invalid_argument(
        "no shader renderer draws this scene (black holes: sky and horizon only; Goedel: static observer)");
}

int renderWithShaders(const Scene& scene, const std::string& output, int orbitFrames, bool polygons) {
    if (!std::getenv("DISPLAY"))
        throw std::runtime_error("the shader renderers draw through GLX and need an X display (hint: xvfb-run -a)");
    // As shaderPathFor, but each renderer refuses what it cannot draw in its own words.
    if (shaderPathFor(scene) == ShaderPath::SpecialRelativity)
        renderSrImage(scene, output, orbitFrames, polygons);
    else if (scene.spacetime->asymptoticallyFlat())
        renderBlackHole(scene, output, orbitFrames);
    else if (scene.spacetime->godelRadius())
        renderGodel(scene, output, orbitFrames);
    else  // the geodesic shader's float loses rays blueshifted into a big bang or a horizon there
        throw std::invalid_argument("--gpu draws asymptotically flat metrics and Goedel's; metric '" +
                                    scene.spacetime->name() + "' is neither (render it without --gpu)");
    std::printf("wrote %s\n", output.c_str());
    return 0;
}

}  // namespace lc::cli
