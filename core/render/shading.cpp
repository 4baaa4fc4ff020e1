// SPDX-License-Identifier: BSD-3-Clause
// Colour from per-pixel data: texture lookups, black-body colours and day/night only, no
// tracing ("render once, explore after": lightcone shade calls this again with new settings).
#include "core/colour/blackbody.hpp"
#include "core/colour/srgb.hpp"
#include "core/numerics/parallel.hpp"
#include "core/render/post_render.hpp"
#include "core/render/render.hpp"

namespace lc {

namespace {

// Black-body colours come from the table every renderer shares (the shaders' Planck texture):
// within an 8-bit level of the Planck integral, a lookup instead of an integral per pixel.
const colour::BlackbodyTable& blackbodyTable() {
    static const colour::BlackbodyTable& table = *colour::standardBlackbodyTable();  // built on first use
    return table;
}

Eigen::Vector2d shownUv(const PixelRecord& px, const PostRender& post) {
    return retexturedUv<double>(px.u, px.v, post.uOffset, post.vOffset, post.uScale, post.vScale);
}

ObjectPixelSamples sampleObject(const Scene& scene, const PixelRecord& px, const PostRender& post) {
    const std::size_t k = static_cast<std::size_t>(px.object);
    const TexturePtr& chosen = shownTexture(scene, post, k);
    const double T = post.temperature.value_or(objectTemperature(scene, k));
    const Eigen::Vector2d uv = shownUv(px, post);
    ObjectPixelSamples s;
    if (T > 0)  // a black-body emitter, seen at the shifted temperature D T
        s.own = blackbodyTable().lookupLinear(shiftedTemperature<double>(px.frequencyRatio, T),
                                              colour::ToneMap::ColourOnly);
    else
        s.own = chosen ? chosen->sample(uv(0), uv(1)) : Vec3(0.8, 0.8, 0.8);
    const TexturePtr& night = objectNightTexture(scene, k);
    if (!scene.lights.empty() && night) s.night = night->sample(uv(0), uv(1));
    return s;
}

// The object's colour from its samples: time window, blink, day and night.
Vec3 finishObject(const Scene& scene, const PixelRecord& px, const PostRender& post, const ObjectPixelSamples& s) {
    const bool inside = !post.timeWindow ||
                        insideTimeWindow<double>(px.emissionTime, post.timeWindow->first, post.timeWindow->second) > 0;
    const bool hidden = !inside && !post.outsideTexture;
    Vec3 c;
    if (!inside) {
        const Eigen::Vector2d uv = shownUv(px, post);
        c = post.outsideTexture ? post.outsideTexture->sample(uv(0), uv(1)) : scene.background;
    } else
        c = s.own;
    if (post.blinkPeriod > 0)
        c *= blinkLevel<double>(px.emissionTime, post.blinkPeriod, post.blinkDuty, post.blinkPhase, post.blinkOffLevel);
    if (!scene.lights.empty() && !hidden) {
        const Vec3 light(px.light[0], px.light[1], px.light[2]);
        const bool hasNight = static_cast<bool>(objectNightTexture(scene, static_cast<std::size_t>(px.object)));
        c = dayNightColour(c, hasNight ? &s.night : nullptr, light);
    }
    return c;
}

// A disk pixel's light before the time window and blinking: Page-Thorne black body at g T with its
// bolometric brightness, the flux, or its texture. Depends on the temperature setting only.
// `temperatureFactor`: the pixel's diskTemperatureFactor (a sweep keeps it).
Vec3 diskEmission(const Scene& scene, const PixelRecord& px, const PostRender& post, double temperatureFactor) {
    if (px.object < 0 || static_cast<std::size_t>(px.object) >= scene.disks.size()) return scene.background;
    const DiskObject& d = scene.disks[static_cast<std::size_t>(px.object)];
    switch (d.emission) {
        case DiskObject::Emission::Texture: return d.texture ? d.texture->sample(px.u, px.v) : Vec3(0.8, 0.8, 0.8);
        case DiskObject::Emission::Flux: return Vec3::Constant(px.intensity);
        case DiskObject::Emission::Blackbody: {
            // diskLocalTemperature, its factor kept: peak * diskTemperatureFactor(intensity, g).
            const double T = post.temperature.value_or(d.temperature) * temperatureFactor;
            return blackbodyTable().lookupLinear(shiftedTemperature<double>(px.frequencyRatio, T),
                                                 colour::ToneMap::ColourOnly) *
                   px.intensity;
        }
    }
    return scene.background;
}

// The disk pixel's colour from its emission: time window and blinking.
Vec3 finishDisk(const Scene& scene, const PixelRecord& px, const PostRender& post, const Vec3& emission) {
    if (px.object < 0 || static_cast<std::size_t>(px.object) >= scene.disks.size()) return scene.background;
    if (post.timeWindow &&
        insideTimeWindow<double>(px.emissionTime, post.timeWindow->first, post.timeWindow->second) == 0)
        return post.outsideTexture ? post.outsideTexture->sample(px.u, px.v) : scene.background;
    Vec3 c = emission;
    if (post.blinkPeriod > 0)
        c *= blinkLevel<double>(px.emissionTime, post.blinkPeriod, post.blinkDuty, post.blinkPhase, post.blinkOffLevel);
    return c;
}

// A sky pixel: the texture, or with a black-body sky its light at g T, brightness g^4 times the
// texture's luminance (docs/SCENES.md "sky"); no light where g <= 0 (none reaches the observer).
// A star field (a texture of black-body light) is shifted star by star: each direction's own T
// and brightness.
// Black-body light of `temperature` and `brightness` seen with frequency ratio g: Planck's colour
// of g T, brightness g^4 b (the GLSL twin: glsl/blackbody_light).
Vec3 shiftedBlackbodyLight(double g, double temperature, double brightness) {
    if (!(g > 0) || !(brightness > 0)) return Vec3::Zero();
    return blackbodyTable().lookupLinear(shiftedTemperature<double>(g, temperature), colour::ToneMap::ColourOnly) *
           shiftedBrightness<double>(g, brightness);
}

Vec3 skyColour(const Scene& scene, const PixelRecord& px) {
    const TexturePtr& sky = px.end ? scene.otherSky : scene.sky;
    if (const LightMap* light = sky && !px.end ? sky->lightMap() : nullptr) {
        const LightMap::Light l = light->at(px.u, px.v);
        return shiftedBlackbodyLight(px.frequencyRatio, l.temperature, l.brightness);
    }
    const Vec3 base = sky ? sky->sample(px.u, px.v) : scene.background;
    if (!scene.skyTemperature || px.end) return base;
    // A uniform black-body sky: the texture's luminance is the brightness.
    const double luminance = 0.2126 * base(0) + 0.7152 * base(1) + 0.0722 * base(2);
    return shiftedBlackbodyLight(px.frequencyRatio, *scene.skyTemperature, luminance);
}

// One pixel's colour from its record (lc::shadePixels).
Vec3 pixelColour(const Scene& scene, const PixelRecord& px, const PostRender& post) {
    switch (px.kind) {
        case PixelRecord::Object: return finishObject(scene, px, post, sampleObject(scene, px, post));
        case PixelRecord::Sky: return skyColour(scene, px);
        case PixelRecord::Horizon: return Vec3::Zero();
        case PixelRecord::Failed: return Vec3(1, 0, 1);  // visible on purpose
        case PixelRecord::Disk:
            return finishDisk(
                scene, px, post,
                diskEmission(scene, px, post, diskTemperatureFactor<double>(px.intensity, px.frequencyRatio)));
        default: return scene.background;
    }
}

}  // namespace

std::size_t objectCount(const Scene& scene) { return scene.spheres.size() + scene.meshes.size(); }

const TexturePtr& shownTexture(const Scene& scene, const PostRender& post, std::size_t k) {
    if (k < post.objectTextures.size() && post.objectTextures[k]) return post.objectTextures[k];
    return k < scene.spheres.size() ? scene.spheres[k].texture : scene.meshes[k - scene.spheres.size()].texture;
}

const TexturePtr& objectNightTexture(const Scene& scene, std::size_t k) {
    static const TexturePtr none;
    return k < scene.spheres.size() ? scene.spheres[k].nightTexture : none;
}

double objectTemperature(const Scene& scene, std::size_t k) {
    return k < scene.spheres.size() ? scene.spheres[k].temperature : scene.meshes[k - scene.spheres.size()].temperature;
}

namespace {
// Whether any pixel's colour may come from the black-body table.
bool usesBlackbodyColours(const Scene& scene, const PostRender& post) {
    if (post.temperature || scene.skyTemperature || (scene.sky && scene.sky->lightMap())) return true;
    for (const auto& sphere : scene.spheres)
        if (sphere.temperature > 0) return true;
    for (const auto& mesh : scene.meshes)
        if (mesh.temperature > 0) return true;
    for (const DiskObject& disk : scene.disks)
        if (disk.emission == DiskObject::Emission::Blackbody) return true;
    return false;
}
}  // namespace

std::vector<float> shadePixels(const Scene& scene, const RenderResult& r, const PostRender& post) {
    std::vector<float> rgb(3 * r.pixels.size());
    // Built before the threads need it (its own loop is parallel), and only when a colour comes
    // from it: 130 ms of a small render's start-up otherwise (bench/bench_startup).
    if (usesBlackbodyColours(scene, post)) (void)blackbodyTable();
    FirstError error;
    const auto pixels = static_cast<std::ptrdiff_t>(r.pixels.size());
    // Every core: pixels are independent (a temperature sweep is a table lookup per pixel).
#pragma omp parallel for schedule(static, 4096)
    for (std::ptrdiff_t n = 0; n < pixels; ++n)
        error.run([&] {
            const Vec3 c = pixelColour(scene, r.pixels[static_cast<std::size_t>(n)], post);
            for (int k = 0; k < 3; ++k) rgb[static_cast<std::size_t>(3 * n + k)] = static_cast<float>(c(k));
        });
    error.rethrow();
    return rgb;
}

PixelShader::PixelShader(const Scene& scene, const RenderResult& data)
    : scene_(scene), data_(data), frame_(shadePixels(scene, data)) {
    for (std::size_t n = 0; n < data.pixels.size(); ++n) {
        if (data.pixels[n].kind == PixelRecord::Object) objects_.push_back(n);
        if (data.pixels[n].kind == PixelRecord::Disk) {
            disks_.push_back(n);
            diskFactor_.push_back(
                diskTemperatureFactor<double>(data.pixels[n].intensity, data.pixels[n].frequencyRatio));
        }
    }
}

namespace {

// The settings an object pixel's samples depend on (sampleObject) are the same in a and b.
bool sameObjectSampling(const PostRender& a, const PostRender& b) {
    return a.objectTextures == b.objectTextures && a.uOffset == b.uOffset && a.vOffset == b.vOffset &&
           a.uScale == b.uScale && a.vScale == b.vScale && a.temperature == b.temperature;
}

// Colours pixels[k] = finish(k) for every k, on every core.
template <class Finish>
void colourEach(const std::vector<std::size_t>& pixels, std::vector<float>& rgb, Finish&& finish) {
    FirstError error;
    const auto count = static_cast<std::ptrdiff_t>(pixels.size());
#pragma omp parallel for schedule(static, 1024)
    for (std::ptrdiff_t k = 0; k < count; ++k)
        error.run([&] {
            const std::size_t n = pixels[static_cast<std::size_t>(k)];
            const Vec3 c = finish(static_cast<std::size_t>(k), n);
            for (int q = 0; q < 3; ++q) rgb[3 * n + static_cast<std::size_t>(q)] = static_cast<float>(c(q));
        });
    error.rethrow();
}

}  // namespace

const std::vector<float>& PixelShader::shade(const PostRender& post) {
    const auto& px = data_.pixels;
    // Samples (texture lookups, black bodies) again only where their settings changed: a sweep
    // of the time window or the blinking reuses them, and a texture sweep the disks' light.
    const bool resampleObjects = !last_ || !sameObjectSampling(*last_, post);
    const bool resampleDisks = !last_ || last_->temperature != post.temperature;
    if (resampleObjects) objectSamples_.resize(objects_.size());
    if (resampleDisks) diskLight_.resize(disks_.size());
    colourEach(objects_, frame_, [&](std::size_t k, std::size_t n) {
        if (resampleObjects) objectSamples_[k] = sampleObject(scene_, px[n], post);
        return finishObject(scene_, px[n], post, objectSamples_[k]);
    });
    colourEach(disks_, frame_, [&](std::size_t k, std::size_t n) {
        if (resampleDisks) diskLight_[k] = diskEmission(scene_, px[n], post, diskFactor_[k]);
        return finishDisk(scene_, px[n], post, diskLight_[k]);
    });
    last_ = post;
    return frame_;
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
