// Colour from per-pixel data: texture lookups, black-body colours and day/night only, no
// tracing ("render once, explore after": lightcone shade calls this again with new settings).
#include "core/render/render.hpp"

#include "core/colour/blackbody.hpp"
#include "core/colour/srgb.hpp"

#include <algorithm>

namespace lc {

std::vector<float> shadePixels(const Scene& scene, const RenderResult& r) {
    std::vector<float> rgb(3 * r.pixels.size());
    for (std::size_t n = 0; n < r.pixels.size(); ++n) {
        const PixelRecord& px = r.pixels[n];
        Vec3 c = scene.background;
        switch (px.kind) {
            case PixelRecord::Object: {
                // Objects are numbered spheres first, then meshes.
                const std::size_t k = static_cast<std::size_t>(px.object);
                const bool sphere = k < scene.spheres.size();
                const TexturePtr& tex =
                    sphere ? scene.spheres[k].texture : scene.meshes[k - scene.spheres.size()].texture;
                const double T =
                    sphere ? scene.spheres[k].temperature : scene.meshes[k - scene.spheres.size()].temperature;
                c = tex ? tex->sample(px.u, px.v) : Vec3(0.8, 0.8, 0.8);
                if (T > 0) {  // a black-body emitter, seen at the shifted temperature D T
                    const Vec3 srgb = colour::blackbodySrgb(std::clamp(px.frequencyRatio * T, 500.0, 1e5),
                                                            colour::ToneMap::ColourOnly);
                    for (int q = 0; q < 3; ++q) c(q) = colour::srgbDecode(srgb(q));
                }
                if (!scene.lights.empty()) {
                    const Vec3 light(px.light[0], px.light[1], px.light[2]);
                    const TexturePtr night = sphere ? scene.spheres[k].nightTexture : nullptr;
                    const Vec3 nightColour = night ? night->sample(px.u, px.v) : Vec3::Zero();
                    c = dayNightColour(c, night ? &nightColour : nullptr, light);
                }
                break;
            }
            case PixelRecord::Sky: c = scene.sky ? scene.sky->sample(px.u, px.v) : scene.background; break;
            case PixelRecord::Horizon: c = Vec3::Zero(); break;
            case PixelRecord::Failed: c = Vec3(1, 0, 1); break;  // visible on purpose
            default: break;
        }
        for (int k = 0; k < 3; ++k) rgb[3 * n + k] = static_cast<float>(c(k));
    }
    return rgb;
}

}  // namespace lc
