// `lightcone shade`: colour an image again from the per-pixel data of `render --data`, without
// tracing: other textures (edit the scene), an emitter temperature, a window of emission times.
#include "app/commands.hpp"
#include "core/render.hpp"
#include "readers/io/image_io.hpp"

#include <cstdio>
#include <map>

namespace lc::cli {

int runShade(const Args& args) {
    args.allow({"-o", "--output", "--time-window", "--temperature"});
    if (args.positional().size() != 2) throw std::invalid_argument("shade expects a scene file and a data file (render --data)");
    const Scene scene = io::readScene(args.positional()[0], sceneReadOptions());
    const io::ImageChannels data = io::readImageChannels(args.positional()[1]);
    std::map<std::string, std::size_t> channel;
    for (std::size_t c = 0; c < data.names.size(); ++c) channel[data.names[c]] = c;
    for (const char* need : {"kind", "object", "u", "v", "frequency_ratio", "emission_time", "affine"})
        if (!channel.count(need))
            throw std::invalid_argument("'" + args.positional()[1] + "' has no channel '" + need +
                                        "' (hint: write it with lightcone render --data FILE.exr)");
    RenderResult r;
    r.width = data.width;
    r.height = data.height;
    r.pixels.resize(static_cast<std::size_t>(data.width) * data.height);
    const std::size_t nc = data.names.size();
    const bool window = args.has("--time-window");
    const auto w = window ? args.numbers("--time-window", 2) : std::vector<double>{0, 0};
    std::size_t hidden = 0;
    for (std::size_t n = 0; n < r.pixels.size(); ++n) {
        const float* px = &data.data[n * nc];
        PixelRecord& p = r.pixels[n];
        p.kind = static_cast<std::int8_t>(px[channel["kind"]]);
        p.object = static_cast<std::int16_t>(px[channel["object"]]);
        p.u = px[channel["u"]];
        p.v = px[channel["v"]];
        p.frequencyRatio = px[channel["frequency_ratio"]];
        p.emissionTime = px[channel["emission_time"]];
        p.affine = px[channel["affine"]];
        if (p.kind == PixelRecord::Object &&
            (p.object < 0 || static_cast<std::size_t>(p.object) >= scene.spheres.size() + scene.meshes.size()))
            throw std::invalid_argument("the data file does not belong to this scene (object index out of range)");
        if (window && p.kind == PixelRecord::Object && (p.emissionTime < w[0] || p.emissionTime > w[1])) {
            p.kind = PixelRecord::Background;  // emitted outside the time window
            ++hidden;
        }
    }
    Scene shaded = scene;
    if (args.has("--temperature")) {
        const double T = args.number("--temperature", 6000);
        for (auto& s : shaded.spheres) s.temperature = T;
        for (auto& m : shaded.meshes) m.temperature = T;
    }
    io::ImageChannels img;
    img.width = r.width;
    img.height = r.height;
    img.names = {"R", "G", "B"};
    img.data = shadePixels(shaded, r);
    const std::string out = args.get("-o", args.get("--output", "shaded.png"));
    io::writeImage(out, img);
    std::printf("wrote %s from %s (no tracing)%s\n", out.c_str(), args.positional()[1].c_str(),
                window ? (", " + std::to_string(hidden) + " object pixels outside the time window").c_str() : "");
    return 0;
}

}  // namespace lc::cli
