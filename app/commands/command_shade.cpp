// SPDX-License-Identifier: BSD-3-Clause
// `lightcone shade`: colour an image again from the per-pixel data of `render --data`, without
// tracing (seed 000 section 5.2): other textures and their (u, v) offset and scale, an emitter
// temperature seen through each pixel's frequency ratio, a window of emission times over a second
// texture, blinking lights; `--sweep` writes an image sequence of one of these.
#include "app/commands/commands.hpp"
#include "core/render/lensing_image.hpp"
#include "core/render/render.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/scene_reader.hpp"
#include "readers/io/image_io.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

namespace lc::cli {

namespace {
const char* const kPixelChannels[] = {"kind", "object", "u", "v", "frequency_ratio", "emission_time", "affine"};

// An object by index ("0") or by name.
std::size_t objectIndex(const Scene& scene, const std::string& key) {
    const std::size_t count = objectCount(scene);
    for (std::size_t k = 0; k < count; ++k) {
        const std::string& name =
            k < scene.spheres.size() ? scene.spheres[k].name : scene.meshes[k - scene.spheres.size()].name;
        if (key == name || key == std::to_string(k)) return k;
    }
    throw std::invalid_argument("option --texture: the scene has no object '" + key + "' (give an index 0 to " +
                                std::to_string(count ? count - 1 : 0) + " or an object's name)");
}

void applySweep(PostRender& post, const FieldSweep& sweep, int frame) {
    const double v = sweep.values.at(frame);
    if (sweep.field == "temperature") post.temperature = v;
    if (sweep.field == "u-offset") post.uOffset = v;
    if (sweep.field == "v-offset") post.vOffset = v;
    if (sweep.field == "blink-phase") post.blinkPhase = v;
    if (sweep.field == "time-window")
        post.timeWindow = std::make_pair(v, v + post.timeWindow->second - post.timeWindow->first);
}

io::ImageChannels rgbImage(const RenderResult& r, std::vector<float> rgb) {
    io::ImageChannels img;
    img.width = r.width;
    img.height = r.height;
    img.names = {"R", "G", "B"};
    img.data = std::move(rgb);
    return img;
}
}  // namespace

RenderResult readPixelData(const std::string& path, const Scene& scene) {
    io::ImageChannels data;
    try {
        data = io::readImageChannels(path);
    } catch (const std::exception& e) {
        // The file checks say what is wrong, not with which file: name it unless the reader did.
        const std::string why = e.what();
        throw std::runtime_error(why.find(path) == std::string::npos ? "pixel data '" + path + "' " + why : why);
    }
    std::map<std::string, std::size_t> channel;
    for (std::size_t c = 0; c < data.names.size(); ++c) channel[data.names[c]] = c;
    for (const char* need : kPixelChannels)
        if (!channel.count(need))
            throw std::invalid_argument("'" + path + "' has no channel '" + need +
                                        "' (hint: write it with lightcone render --data FILE.exr)");
    RenderResult r;
    r.width = data.width;
    r.height = data.height;
    r.pixels.resize(static_cast<std::size_t>(data.width) * data.height);
    // Written by render --magnification: all three or none.
    r.lensing = channel.count("magnification") && channel.count("shear") && channel.count("rotation");
    const std::size_t nc = data.names.size();
    for (std::size_t n = 0; n < r.pixels.size(); ++n) {
        const float* px = &data.data[n * nc];
        PixelRecord& p = r.pixels[n];
        for (const char* need : kPixelChannels)
            if (!std::isfinite(px[channel[need]]))
                throw std::invalid_argument("'" + path + "' has a non-finite '" + need + "' at pixel " +
                                            std::to_string(n));
        const float kind = px[channel["kind"]], object = px[channel["object"]];
        if (!(kind >= 0 && kind <= PixelRecord::Disk && object >= -1 && object <= 32767))
            throw std::invalid_argument("'" + path + "' has kind " + std::to_string(kind) + ", object " +
                                        std::to_string(object) + " at pixel " + std::to_string(n) +
                                        " (not written by lightcone render --data?)");
        p.kind = static_cast<std::int8_t>(kind);
        p.object = static_cast<std::int16_t>(object);
        p.u = px[channel["u"]];
        p.v = px[channel["v"]];
        p.frequencyRatio = px[channel["frequency_ratio"]];
        p.emissionTime = px[channel["emission_time"]];
        p.affine = px[channel["affine"]];
        if (p.kind == PixelRecord::Disk) {  // written since disks exist; older files have none
            for (const char* need : {"disk_radius", "intensity", "image_order"})
                if (!channel.count(need) || !std::isfinite(px[channel[need]]))
                    throw std::invalid_argument("'" + path + "' shows a disk at pixel " + std::to_string(n) +
                                                " but has no finite '" + need + "'");
            p.diskRadius = px[channel["disk_radius"]];
            p.intensity = px[channel["intensity"]];
            p.order = static_cast<std::int8_t>(std::clamp(px[channel["image_order"]], 0.0f, 127.0f));
            if (static_cast<std::size_t>(p.object) >= scene.disks.size())
                throw std::invalid_argument("'" + path + "' does not belong to this scene (disk " +
                                            std::to_string(p.object) + " at pixel " + std::to_string(n) + ")");
        }
        if (p.kind == PixelRecord::Sky && channel.count("end")) {  // written since two-ended metrics exist
            const float end = px[channel["end"]];
            if (!(end == 0 || end == 1))
                throw std::invalid_argument("'" + path + "' has end " + std::to_string(end) + " at pixel " +
                                            std::to_string(n) + " (expected 0, this side, or 1, the far side)");
            if (end == 1 && !scene.spacetime->hasOtherEnd())
                throw std::invalid_argument("'" + path + "' does not belong to this scene (pixel " + std::to_string(n) +
                                            " reached a far end; " + scene.spacetime->name() + " has one end)");
            p.end = static_cast<std::int8_t>(end);
        }
        if (r.lensing) {
            p.magnification = px[channel["magnification"]];
            p.shear = px[channel["shear"]];
            p.rotation = px[channel["rotation"]];
            if (!std::isfinite(p.magnification) || !std::isfinite(p.shear) || !std::isfinite(p.rotation))
                throw std::invalid_argument("'" + path + "' has a non-finite lensing channel at pixel " +
                                            std::to_string(n));
        }
        if (p.kind == PixelRecord::Object && (p.object < 0 || static_cast<std::size_t>(p.object) >= objectCount(scene)))
            throw std::invalid_argument("'" + path + "' does not belong to this scene (object " +
                                        std::to_string(p.object) + " at pixel " + std::to_string(n) + ")");
    }
    return r;
}

PostRender postRenderFor(const ShadeOptions& o, const Scene& scene) {
    const std::string folder = std::filesystem::path(o.scene).parent_path().string();
    auto load = [&](const std::string& name, const char* option) {
        try {
            return io::textureFromName(name, folder.empty() ? "." : folder);
        } catch (const std::exception& e) {
            throw std::invalid_argument(std::string("option ") + option + " '" + name + "': " + e.what() +
                                        " (use checker, earth, earth-night or an image file)");
        }
    };
    PostRender post;
    const std::size_t objects = objectCount(scene);
    for (const auto& [object, texture] : o.textures) {
        const TexturePtr t = load(texture, "--texture");
        if (object.empty())
            post.objectTextures.assign(objects, t);
        else {
            post.objectTextures.resize(objects);
            post.objectTextures[objectIndex(scene, object)] = t;
        }
    }
    if (!o.outsideTexture.empty()) post.outsideTexture = load(o.outsideTexture, "--outside-texture");
    post.uOffset = o.uOffset;
    post.vOffset = o.vOffset;
    post.uScale = o.uScale;
    post.vScale = o.vScale;
    post.temperature = o.temperature;
    post.timeWindow = o.timeWindow;
    if (o.blink) {
        post.blinkPeriod = (*o.blink)[0];
        post.blinkDuty = (*o.blink)[1];
        post.blinkPhase = (*o.blink)[2];
        post.blinkOffLevel = (*o.blink)[3];
    }
    return post;
}

int runShade(const std::vector<std::string>& argv) {
    const ShadeOptions o = parseShadeOptions(argv);
    if (o.sweep)
        prepareFrameFolder(o.frames, "-o", io::imageExtensions());  // as animate: -o window/%03d.png makes window/
    else
        io::checkOutputPath(o.output, io::imageExtensions(), "-o");
    const Scene scene = io::readScene(o.scene, sceneReadOptions());
    const RenderResult r = readPixelData(o.data, scene);
    if (o.show) {
        io::writeImage(o.output, rgbImage(r, lensingImage(r, *o.show)));
        std::printf("wrote %s from %s (no tracing): the pixels' %s\n", o.output.c_str(), o.data.c_str(),
                    o.showName.c_str());
        return 0;
    }
    const PostRender base = postRenderFor(o, scene);
    if (!o.sweep) {
        io::writeImage(o.output, rgbImage(r, shadePixels(scene, r, base)));
        std::printf("wrote %s from %s (no tracing)%s\n", o.output.c_str(), o.data.c_str(),
                    o.timeWindow ? (", " + std::to_string(countOutsideTimeWindow(r, *o.timeWindow)) +
                                    " object pixels outside the time window")
                                       .c_str()
                                 : "");
        return 0;
    }
    // Each frame is written atomically as soon as it is coloured (a long sequence needs no memory).
    const auto t0 = std::chrono::steady_clock::now();
    PixelShader shader(scene, r);  // what no setting changes, coloured once
    for (int f = 0; f < o.sweep->values.frames; ++f) {
        PostRender post = base;
        applySweep(post, *o.sweep, f);
        io::writeImage(o.frames.path(f), rgbImage(r, shader.shade(post)));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("wrote %d frames %s ... %s from %s (no tracing), %s %g to %g, %.3f s a frame\n", o.sweep->values.frames,
                o.frames.path(0).c_str(), o.frames.path(o.sweep->values.frames - 1).c_str(), o.data.c_str(),
                o.sweep->field.c_str(), o.sweep->values.from, o.sweep->values.to, seconds / o.sweep->values.frames);
    return 0;
}

}  // namespace lc::cli
