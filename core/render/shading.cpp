// Colour from per-pixel data: texture lookups, black-body colours and day/night only, no
// tracing ("render once, explore after": lightcone shade calls this again with new settings).
#include "core/colour/blackbody.hpp"
#include "core/colour/srgb.hpp"
#include "core/render/post_render.hpp"
#include "core/render/render.hpp"

namespace lc {

namespace {

// The object's own colour at the pixel before lighting: texture or black body, time window, blink.
Vec3 objectColour(const Scene& scene, const PixelRecord& px, const PostRender& post, bool& hidden) {
    const std::size_t k = static_cast<std::size_t>(px.object);
    const TexturePtr chosen = shownTexture(scene, post, k);
    const double T = post.temperature.value_or(objectTemperature(scene, k));
    const Eigen::Vector2d uv = retexturedUv<double>(px.u, px.v, post.uOffset, post.vOffset, post.uScale, post.vScale);
    const bool inside = !post.timeWindow ||
                        insideTimeWindow<double>(px.emissionTime, post.timeWindow->first, post.timeWindow->second) > 0;
    hidden = !inside && !post.outsideTexture;
    Vec3 c;
    if (!inside)
        c = post.outsideTexture ? post.outsideTexture->sample(uv(0), uv(1)) : scene.background;
    else if (T > 0) {  // a black-body emitter, seen at the shifted temperature D T
        const Vec3 srgb =
            colour::blackbodySrgb(shiftedTemperature<double>(px.frequencyRatio, T), colour::ToneMap::ColourOnly);
        for (int q = 0; q < 3; ++q) c(q) = colour::srgbDecode(srgb(q));
    } else
        c = chosen ? chosen->sample(uv(0), uv(1)) : Vec3(0.8, 0.8, 0.8);
    if (post.blinkPeriod > 0)
        c *= blinkLevel<double>(px.emissionTime, post.blinkPeriod, post.blinkDuty, post.blinkPhase, post.blinkOffLevel);
    if (!scene.lights.empty() && !hidden) {
        const Vec3 light(px.light[0], px.light[1], px.light[2]);
        const TexturePtr night = objectNightTexture(scene, k);
        const Vec3 nightColour = night ? night->sample(uv(0), uv(1)) : Vec3::Zero();
        c = dayNightColour(c, night ? &nightColour : nullptr, light);
    }
    return c;
}

// A disk pixel: Page-Thorne black body at g T, bolometric brightness, or its texture.
Vec3 diskColour(const Scene& scene, const PixelRecord& px, const PostRender& post) {
    if (px.object < 0 || static_cast<std::size_t>(px.object) >= scene.disks.size()) return scene.background;
    const DiskObject& d = scene.disks[static_cast<std::size_t>(px.object)];
    if (post.timeWindow &&
        insideTimeWindow<double>(px.emissionTime, post.timeWindow->first, post.timeWindow->second) == 0)
        return post.outsideTexture ? post.outsideTexture->sample(px.u, px.v) : scene.background;
    Vec3 c;
    switch (d.emission) {
        case DiskObject::Emission::Texture: c = d.texture ? d.texture->sample(px.u, px.v) : Vec3(0.8, 0.8, 0.8); break;
        case DiskObject::Emission::Flux: c = Vec3::Constant(px.intensity); break;
        case DiskObject::Emission::Blackbody: {
            const double T =
                diskLocalTemperature<double>(post.temperature.value_or(d.temperature), px.intensity, px.frequencyRatio);
            const Vec3 srgb =
                colour::blackbodySrgb(shiftedTemperature<double>(px.frequencyRatio, T), colour::ToneMap::ColourOnly);
            for (int q = 0; q < 3; ++q) c(q) = colour::srgbDecode(srgb(q)) * px.intensity;
            break;
        }
    }
    if (post.blinkPeriod > 0)
        c *= blinkLevel<double>(px.emissionTime, post.blinkPeriod, post.blinkDuty, post.blinkPhase, post.blinkOffLevel);
    return c;
}

}  // namespace

std::size_t objectCount(const Scene& scene) { return scene.spheres.size() + scene.meshes.size(); }

TexturePtr shownTexture(const Scene& scene, const PostRender& post, std::size_t k) {
    if (k < post.objectTextures.size() && post.objectTextures[k]) return post.objectTextures[k];
    return k < scene.spheres.size() ? scene.spheres[k].texture : scene.meshes[k - scene.spheres.size()].texture;
}

TexturePtr objectNightTexture(const Scene& scene, std::size_t k) {
    return k < scene.spheres.size() ? scene.spheres[k].nightTexture : nullptr;
}

double objectTemperature(const Scene& scene, std::size_t k) {
    return k < scene.spheres.size() ? scene.spheres[k].temperature : scene.meshes[k - scene.spheres.size()].temperature;
}

std::vector<float> shadePixels(const Scene& scene, const RenderResult& r, const PostRender& post) {
    std::vector<float> rgb(3 * r.pixels.size());
    for (std::size_t n = 0; n < r.pixels.size(); ++n) {
        const PixelRecord& px = r.pixels[n];
        Vec3 c = scene.background;
        bool hidden = false;
        switch (px.kind) {
            case PixelRecord::Object: c = objectColour(scene, px, post, hidden); break;
            case PixelRecord::Sky: c = scene.sky ? scene.sky->sample(px.u, px.v) : scene.background; break;
            case PixelRecord::Horizon: c = Vec3::Zero(); break;
            case PixelRecord::Failed: c = Vec3(1, 0, 1); break;  // visible on purpose
            case PixelRecord::Disk: c = diskColour(scene, px, post); break;
            default: break;
        }
        for (int k = 0; k < 3; ++k) rgb[3 * n + k] = static_cast<float>(c(k));
    }
    return rgb;
}

std::vector<float> shadePixels(const Scene& scene, const RenderResult& r) {
    return shadePixels(scene, r, PostRender{});
}

std::size_t countOutsideTimeWindow(const RenderResult& r, const std::pair<double, double>& window) {
    std::size_t outside = 0;
    for (const PixelRecord& px : r.pixels)
        outside += px.kind == PixelRecord::Object &&
                   insideTimeWindow<double>(px.emissionTime, window.first, window.second) == 0;
    return outside;
}

}  // namespace lc
