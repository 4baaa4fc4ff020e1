// `lightcone render --gpu`: the egocentric Goedel image through VTK's OpenGL pipeline with
// custom shaders (views/vtkLightconeGodelImageRenderer), offscreen, plus the frame rate of a
// short camera orbit (only the projection changes: the photo-object layers are reused).
#include "app/commands.hpp"
#include "readers/io/image_io.hpp"
#include "core/render_sr.hpp"
#include "vtkLightconeGeodesicShaderRenderer.h"
#include "vtkLightconeGodelImageRenderer.h"
#include "vtkLightconeSpecialRelativityRenderer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace lc::cli {

namespace {

// Special relativity: local ray tracing (or polygon distortion) in shaders; the orbit moves
// the observer's time forward, so the objects move and every frame rebuilds the footprints.
int renderSpecialRelativityWithShaders(const Scene& scene, const std::string& output, int frames, bool polygons) {
    vtkNew<vtkLightconeSpecialRelativityRenderer> gpu;
    gpu->SetScene(scene);
    if (polygons) gpu->SetModeToPolygonDistortion();
    io::ImageChannels img;
    img.width = scene.camera.width;
    img.height = scene.camera.height;
    img.names = {"R", "G", "B"};
    img.data = gpu->RenderColour();
    io::writeImage(output, img);
    std::printf("rendered %s: %dx%d, special relativity, %s in VTK OpenGL shaders (%zu footprint quads)\n",
                scene.source.c_str(), img.width, img.height, polygons ? "polygon distortion" : "local ray tracing",
                static_cast<std::size_t>(gpu->GetNumberOfQuads()));
    if (frames > 0) {
        const auto t0 = std::chrono::steady_clock::now();
        for (int k = 0; k < frames; ++k) {
            gpu->SetObserverTime(scene.observer(0) + 0.2 * k);
            gpu->Render();
        }
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("animation (observer time advancing): %d frames in %.3f s = %.1f frames per second\n", frames, secs,
                    frames / secs);
    }
    std::printf("wrote %s\n", output.c_str());
    return 0;
}

// Black holes and flat spacetime: Hamilton's equations integrated per pixel in a fragment
// shader (single precision); sky and horizon only.
int renderGeodesicsWithShaders(const Scene& scene, const std::string& output, int frames) {
    if (!scene.spheres.empty() || !scene.meshes.empty())
        throw std::invalid_argument("the geodesic shader draws sky and horizon only; render objects without --gpu");
    vtkNew<vtkLightconeGeodesicShaderRenderer> gpu;
    gpu->SetScene(scene);
    io::ImageChannels img;
    img.width = scene.camera.width;
    img.height = scene.camera.height;
    img.names = {"R", "G", "B"};
    img.data = gpu->RenderColour();
    io::writeImage(output, img);
    std::printf("rendered %s: %dx%d, %s, Hamiltonian rays in a fragment shader (dual-number derivatives)\n",
                scene.source.c_str(), img.width, img.height, scene.spacetime->name().c_str());
    if (frames > 0) {
        const Vec3 f = scene.camera.forward.normalized(), u = scene.camera.up.normalized();
        const Vec3 side = f.cross(u).normalized(), up = side.cross(f);
        const auto t0 = std::chrono::steady_clock::now();
        for (int k = 0; k < frames; ++k) {
            const double ang = 0.2 * std::sin(2 * kPi * k / frames);  // look around the hole
            gpu->SetCameraOrientation(std::cos(ang) * f + std::sin(ang) * side, up);
            gpu->Render();
        }
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("camera sweep: %d frames in %.3f s = %.2f frames per second\n", frames, secs, frames / secs);
    }
    std::printf("wrote %s\n", output.c_str());
    return 0;
}

}  // namespace

int renderWithShaders(const Scene& scene, const std::string& output, int orbitFrames, bool polygons) {
    if (!std::getenv("DISPLAY"))
        throw std::runtime_error("the shader renderer draws through GLX and needs an X display (hint: xvfb-run -a)");
    if (isSpecialRelativityScene(scene) && (!scene.spheres.empty() || !scene.meshes.empty()))
        return renderSpecialRelativityWithShaders(scene, output, orbitFrames, polygons);
    if (scene.spacetime->asymptoticallyFlat()) return renderGeodesicsWithShaders(scene, output, orbitFrames);
    vtkNew<vtkLightconeGodelImageRenderer> gpu;
    gpu->SetScene(scene);
    gpu->SetLatitudes(scene.settings.meshLatitudes);
    gpu->SetLongitudes(scene.settings.meshLongitudes);
    gpu->Build();
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<float> rgb = gpu->RenderColour();
    const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    io::ImageChannels img;
    img.width = scene.camera.width;
    img.height = scene.camera.height;
    img.names = {"R", "G", "B"};
    img.data = std::move(rgb);
    io::writeImage(output, img);
    std::printf("rendered %s: %dx%d, godel, photo-objects through VTK OpenGL shaders (%d layers, %zu triangles)\n",
                scene.source.c_str(), img.width, img.height, gpu->GetNumberOfLayers(), gpu->GetNumberOfTriangles());
    std::printf("vertex images %.3f s, first frame %.3f s\n", gpu->GetVertexSeconds(), first);
    if (orbitFrames > 0) {
        // Turn the camera once around its up axis.
        const Vec3 f = scene.camera.forward.normalized(), u = scene.camera.up.normalized();
        const Vec3 side = f.cross(u).normalized(), up = side.cross(f);
        const auto o0 = std::chrono::steady_clock::now();
        for (int k = 0; k < orbitFrames; ++k) {
            const double ang = 2 * kPi * k / orbitFrames;
            gpu->SetCameraOrientation(std::cos(ang) * f + std::sin(ang) * side, up);
            gpu->Render();
        }
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - o0).count();
        std::printf("camera orbit: %d frames in %.3f s = %.1f frames per second\n", orbitFrames, secs, orbitFrames / secs);
    }
    std::printf("wrote %s\n", output.c_str());
    return 0;
}

}  // namespace lc::cli
