// `lightcone shade`: colour an image again from the per-pixel data of `render --data`, without
// tracing: other textures (edit the scene), an emitter temperature, a window of emission times.
#include "app/commands.hpp"
#include "core/render/render.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/image_io.hpp"

#include <cmath>
#include <cstdio>
#include <map>

namespace lc::cli {

int runShade(const std::vector<std::string>& argv) {
    const ShadeOptions o = parseShadeOptions(argv);
    io::checkOutputPath(o.output, io::imageExtensions(), "-o");
    const Scene scene = io::readScene(o.scene, sceneReadOptions());
    const io::ImageChannels data = io::readImageChannels(o.data);
    std::map<std::string, std::size_t> channel;
    for (std::size_t c = 0; c < data.names.size(); ++c) channel[data.names[c]] = c;
    for (const char* need : {"kind", "object", "u", "v", "frequency_ratio", "emission_time", "affine"})
        if (!channel.count(need))
            throw std::invalid_argument("'" + o.data + "' has no channel '" + need +
                                        "' (hint: write it with lightcone render --data FILE.exr)");
    RenderResult r;
    r.width = data.width;
    r.height = data.height;
    r.pixels.resize(static_cast<std::size_t>(data.width) * data.height);
    const std::size_t nc = data.names.size();
    const bool window = o.timeWindow.has_value();
    const std::pair<double, double> w = o.timeWindow.value_or(std::make_pair(0.0, 0.0));
    std::size_t hidden = 0;
    for (std::size_t n = 0; n < r.pixels.size(); ++n) {
        const float* px = &data.data[n * nc];
        PixelRecord& p = r.pixels[n];
        for (const char* need : {"kind", "object", "u", "v", "frequency_ratio", "emission_time", "affine"})
            if (!std::isfinite(px[channel[need]]))
                throw std::invalid_argument("'" + o.data + "' has a non-finite '" + need + "' at pixel " +
                                            std::to_string(n));
        const float kind = px[channel["kind"]], object = px[channel["object"]];
        if (!(kind >= 0 && kind <= PixelRecord::Failed && object >= -1 && object <= 32767))
            throw std::invalid_argument("'" + o.data + "' has kind " + std::to_string(kind) + ", object " +
                                        std::to_string(object) + " at pixel " + std::to_string(n) +
                                        " (not written by lightcone render --data?)");
        p.kind = static_cast<std::int8_t>(kind);
        p.object = static_cast<std::int16_t>(object);
        p.u = px[channel["u"]];
        p.v = px[channel["v"]];
        p.frequencyRatio = px[channel["frequency_ratio"]];
        p.emissionTime = px[channel["emission_time"]];
        p.affine = px[channel["affine"]];
        if (p.kind == PixelRecord::Object &&
            (p.object < 0 || static_cast<std::size_t>(p.object) >= scene.spheres.size() + scene.meshes.size()))
            throw std::invalid_argument("the data file does not belong to this scene (object index out of range)");
        if (window && p.kind == PixelRecord::Object && (p.emissionTime < w.first || p.emissionTime > w.second)) {
            p.kind = PixelRecord::Background;  // emitted outside the time window
            ++hidden;
        }
    }
    Scene shaded = scene;
    if (o.temperature) {
        const double T = *o.temperature;
        for (auto& s : shaded.spheres) s.temperature = T;
        for (auto& m : shaded.meshes) m.temperature = T;
    }
    io::ImageChannels img;
    img.width = r.width;
    img.height = r.height;
    img.names = {"R", "G", "B"};
    img.data = shadePixels(shaded, r);
    const std::string& out = o.output;
    io::writeImage(out, img);
    std::printf("wrote %s from %s (no tracing)%s\n", out.c_str(), o.data.c_str(),
                window ? (", " + std::to_string(hidden) + " object pixels outside the time window").c_str() : "");
    return 0;
}

}  // namespace lc::cli
