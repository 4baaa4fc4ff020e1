// `lightcone render`: the CPU reference image of a scene, plus its per-pixel data.
#include "app/commands.hpp"
#include "core/metrics/godel.hpp"
#include "core/render.hpp"
#include "core/render_sr.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/scene_reader.hpp"

#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace lc::cli {
namespace {

// A one-line progress bar on stderr, redrawn only when the percentage changes.
class ProgressBar {
public:
    explicit ProgressBar(bool enabled) : enabled_(enabled), tty_(::isatty(2)) {}
    void operator()(double f) {
        if (!enabled_) return;
        const int pct = static_cast<int>(100 * f);
        if (pct == last_) return;
        if (!tty_) {  // logs: a line every 10 %
            if (pct / 10 != last_ / 10 || last_ < 0) std::fprintf(stderr, "progress %3d%%\n", pct);
            last_ = pct;
            return;
        }
        last_ = pct;
        const int filled = pct * 40 / 100;
        std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################", 40 - filled, "", pct);
        if (pct == 100) std::fprintf(stderr, "\n");
        std::fflush(stderr);
    }

private:
    bool enabled_, tty_;
    int last_ = -1;
};

io::ImageChannels pixelData(const RenderResult& r, const std::vector<float>& rgb) {
    io::ImageChannels img;
    img.width = r.width;
    img.height = r.height;
    img.names = {"R", "G", "B", "kind", "object", "u", "v", "frequency_ratio", "emission_time", "affine", "drift", "steps"};
    img.data.reserve(img.names.size() * r.pixels.size());
    for (std::size_t n = 0; n < r.pixels.size(); ++n) {
        const PixelRecord& p = r.pixels[n];
        for (float v : {rgb[3 * n], rgb[3 * n + 1], rgb[3 * n + 2], float(p.kind), float(p.object), p.u, p.v,
                        p.frequencyRatio, p.emissionTime, p.affine, p.drift, p.steps})
            img.data.push_back(v);
    }
    return img;
}

}  // namespace

int runRender(const Args& args) {
    args.allow({"-o", "--output", "--width", "--height", "--stepper", "--tolerance", "--windings", "--threads",
                "--method", "--data", "--quiet", "--gpu", "--orbit-frames"});
    if (args.positional().size() != 1) throw std::invalid_argument("render expects one scene file");
    const std::string output = args.get("-o", args.get("--output", "lightcone.png"));
    Scene scene = io::readScene(args.positional()[0], sceneReadOptions());
    if (args.has("--width")) scene.camera.width = static_cast<int>(args.number("--width", 0));
    if (args.has("--height")) scene.camera.height = static_cast<int>(args.number("--height", 0));
    if (args.has("--stepper")) scene.settings.trace.stepper = parseStepper(args.get("--stepper"));
    if (args.has("--tolerance")) scene.settings.trace.absTol = scene.settings.trace.relTol = args.number("--tolerance", 0);
    if (args.has("--threads")) scene.settings.threads = static_cast<int>(args.number("--threads", 0));
    if (args.has("--windings")) {
        const double n = args.number("--windings", 0);
        if (n < 0 || n > 1000 || n != std::floor(n)) throw std::invalid_argument("--windings expects an integer in [0, 1000]");
        scene.settings.windings = static_cast<int>(n);
        // Goedel rays are followed for the windings asked for: (N + 1) 2 pi a of affine length.
        if (const auto* g = dynamic_cast<const GodelCartesian*>(scene.spacetime.get()))
            scene.settings.trace.maxAffine = (scene.settings.windings + 1) * 2 * kPi * g->a();
    }
    if (args.has("--method") && args.get("--method") != "polygon_distortion")
        scene.settings.method = parseRenderMethod(args.get("--method"));
    scene.camera.validate();

    if (args.has("--gpu")) {
#ifdef LIGHTCONE_WITH_VTK
        if (args.has("--data")) throw std::invalid_argument("--data comes from the CPU renderers (leave out --gpu)");
        return renderWithShaders(scene, output, static_cast<int>(args.number("--orbit-frames", 36)),
                                 args.get("--method") == "polygon_distortion");
#else
        throw std::invalid_argument("--gpu needs a build with VTK");
#endif
    }
    ProgressBar bar(!args.has("--quiet"));
    RenderResult result;
    std::vector<float> rgb;
    const bool specialRelativity = isSpecialRelativityScene(scene);
    if (specialRelativity) {
        SpecialRelativityResult sr = renderSpecialRelativity(scene, args.get("--method") == "polygon_distortion");
        result = std::move(sr.records);
        rgb = std::move(sr.rgb);
    } else {
        result = render(scene, [&bar](double f) { bar(f); });
        rgb = shadePixels(scene, result);
    }
    io::ImageChannels img;
    img.width = result.width;
    img.height = result.height;
    img.names = {"R", "G", "B"};
    img.data = rgb;
    io::writeImage(output, img);
    if (args.has("--data")) io::writeImage(args.get("--data"), pixelData(result, rgb));

    const RenderStats& s = result.stats;
    const RenderSettings::Method method = resolveMethod(scene);
    if (specialRelativity)
        std::printf("rendered %s: %dx%d, special relativity, %s with Doppler and searchlight\n", scene.source.c_str(),
                    result.width, result.height,
                    args.get("--method") == "polygon_distortion" ? "polygon distortion" : "local ray tracing");
    else if (method != RenderSettings::Method::Numeric)
        std::printf("rendered %s: %dx%d, %s, method %s (closed-form geodesics, no ODE)\n", scene.source.c_str(),
                    result.width, result.height, scene.spacetime->name().c_str(), renderMethodName(method).c_str());
    else
        std::printf("rendered %s: %dx%d, %s, %s tol %.1e\n", scene.source.c_str(), result.width, result.height,
                    scene.spacetime->name().c_str(), stepperName(scene.settings.trace.stepper).c_str(),
                    scene.settings.trace.relTol);
    if (s.rays > 0)
        std::printf("time %.3f s (%.0f rays/s), mean %.1f steps/ray\n", s.seconds, s.rays / s.seconds, s.meanSteps);
    else
        std::printf("time %.3f s\n", s.seconds);
    if (!specialRelativity && method == RenderSettings::Method::PerVertex)
        std::printf("vertex images from the inverse problem (exact null geodesics; no drift to report)\n");
    else if (!specialRelativity)
        std::printf("worst null-condition drift |H| = %.3e\n", s.worstDrift);
    std::printf("object pixels %zu; stops:", s.hits);
    for (std::size_t k = 0; k < s.stopCounts.size(); ++k)
        if (s.stopCounts[k]) std::printf(" %s=%zu", stopReasonName(static_cast<StopReason>(k)).c_str(), s.stopCounts[k]);
    std::printf("\nwrote %s%s%s\n", output.c_str(), args.has("--data") ? " and " : "", args.get("--data").c_str());
    return 0;
}

}  // namespace lc::cli
