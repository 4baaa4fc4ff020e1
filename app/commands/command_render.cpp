// SPDX-License-Identifier: BSD-3-Clause
// `lightcone render`: the CPU reference image of a scene, plus its per-pixel data.
#include "app/cli/command_options.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/frame_renderer.hpp"
#include "app/cli/progress_bar.hpp"
#include "app/commands/render_report.hpp"
#include "app/commands/svg_plot.hpp"
#include "core/analysis/disk_observables.hpp"
#include "core/metrics/godel.hpp"
#include "core/render/render.hpp"
#include "core/render/special_relativity.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/scene_reader.hpp"
#include "readers/io/session_file.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace lc::cli {
namespace {

io::ImageChannels pixelData(const RenderResult& r, const std::vector<float>& rgb) {
    io::ImageChannels img;
    img.width = r.width;
    img.height = r.height;
    img.names = {
        "R",      "G",     "B",     "kind",        "object",    "u",           "v",  "frequency_ratio", "emission_time",
        "affine", "drift", "steps", "disk_radius", "intensity", "image_order", "end"};
    if (r.lensing) img.names.insert(img.names.end(), {"magnification", "shear", "rotation"});
    img.data.reserve(img.names.size() * r.pixels.size());
    for (std::size_t n = 0; n < r.pixels.size(); ++n) {
        const PixelRecord& p = r.pixels[n];
        for (float v :
             {rgb[3 * n], rgb[3 * n + 1], rgb[3 * n + 2], float(p.kind), float(p.object), p.u, p.v, p.frequencyRatio,
              p.emissionTime, p.affine, p.drift, p.steps, p.diskRadius, p.intensity, float(p.order), float(p.end)})
            img.data.push_back(v);
        if (r.lensing) img.data.insert(img.data.end(), {p.magnification, p.shear, p.rotation});
    }
    return img;
}

// A NaN or infinity anywhere in the result is a failed render, reported instead of written.
void requireFiniteResult(const RenderResult& r, const std::vector<float>& rgb) {
    std::size_t bad = 0, first = 0;
    for (std::size_t n = 0; n < r.pixels.size(); ++n) {
        const PixelRecord& p = r.pixels[n];
        bool ok = std::isfinite(p.u) && std::isfinite(p.v) && std::isfinite(p.frequencyRatio) &&
                  std::isfinite(p.emissionTime) && std::isfinite(p.affine) && std::isfinite(p.drift) &&
                  std::isfinite(p.intensity) && std::isfinite(p.diskRadius) && std::isfinite(p.magnification) &&
                  std::isfinite(p.shear) && std::isfinite(p.rotation);
        for (int c = 0; c < 3 && 3 * n + 2 < rgb.size(); ++c) ok = ok && std::isfinite(rgb[3 * n + c]);
        if (!ok && bad++ == 0) first = n;
    }
    if (bad)
        throw std::runtime_error(
            std::to_string(bad) + " pixels came out non-finite (first at column " + std::to_string(first % r.width) +
            ", row " + std::to_string(first / r.width) +
            "); nothing was written (hint: lower the speeds, coordinates or colours of the scene)");
}

// The scene file, or a session's scene with its edits (GUI/CLI parity: the same image).
Scene loadScene(const RenderOptions& opt) {
    if (opt.session.empty()) return io::readScene(opt.scene, sceneReadOptions());
    const io::OpenedSession opened =
        io::openSessionScene(io::readSession(opt.session), opt.session, sceneReadOptions());
    if (!opened.notice.empty()) std::fprintf(stderr, "note: %s\n", opened.notice.c_str());
    return opened.scene.scene();
}

// The disk's observed spectrum as CSV (frequency, F_nu, nu F_nu) and/or an SVG plot of log nu F_nu.
void writeSpectrum(const Scene& scene, const RenderResult& result, const std::vector<std::string>& files) {
    if (files.empty()) return;
    const std::vector<SpectrumBin> bins = diskSpectrum(scene, result);
    std::ostringstream csv;
    csv.precision(10);
    csv << "frequency_Hz,F_nu_Mdot_per_M2_Hz,nu_F_nu_Mdot_per_M2\n";
    std::vector<double> x;
    PlotColumn column{"log10 nu F_nu (Mdot / M^2)", {}};
    for (const SpectrumBin& b : bins) {
        csv << b.frequencyHz << ',' << b.fluxDensity << ',' << b.frequencyHz * b.fluxDensity << '\n';
        x.push_back(std::log10(b.frequencyHz));
        const double nuFnu = b.frequencyHz * b.fluxDensity;
        column.values.push_back(nuFnu > 0 ? std::log10(nuFnu) : std::nan(""));
    }
    io::OutputSet outputs;
    for (const std::string& f : files)
        outputs.add(f,
                    f.size() > 4 && f.substr(f.size() - 4) == ".svg" ? svgPlots("log10 frequency (Hz)", x, {column})
                                                                     : csv.str(),
                    "--spectrum");
    outputs.commit();
    for (const std::string& f : files) std::printf("wrote %s\n", f.c_str());
}

}  // namespace

void writeRenderOutputs(const ColouredImage& image, const std::string& output, const std::string& data,
                        const std::vector<io::ImageLabel>& labels, const std::vector<std::string>& report) {
    requireFiniteResult(image.records, image.rgb);
    io::ImageChannels img;
    img.width = image.records.width;
    img.height = image.records.height;
    img.names = {"R", "G", "B"};
    img.data = image.rgb;
    io::drawLabels(img, labels);
    // The image and its data appear together or not at all.
    io::OutputSet outputs;
    outputs.add(output, io::encodeImage(output, img), "-o");
    if (!data.empty()) {
        io::ImageChannels records = pixelData(image.records, image.rgb);
        std::string text;
        for (const std::string& line : report) text += line + "\n";
        if (!text.empty()) records.attributes.emplace_back("lightcone:report", text);
        outputs.add(data, io::encodeImage(data, records), "--data");
    }
    outputs.commit();
}

int runRender(const std::vector<std::string>& argv) {
    const RenderOptions opt = parseRenderOptions(argv);
    // Every output is checked before the work starts, so a bad path costs no render time.
    io::checkOutputPath(opt.output, io::imageExtensions(), "-o");
    if (!opt.data.empty()) io::checkOutputPath(opt.data, io::multiChannelImageExtensions(), "--data");
    for (const std::string& s : opt.spectrum) io::checkOutputPath(s, {".csv", ".svg"}, "--spectrum");
    Scene scene = loadScene(opt);
    opt.applyTo(scene);
    if (!opt.spectrum.empty() && scene.disks.empty())
        throw std::invalid_argument("--spectrum needs a scene with an accretion disk; " + scene.source + " has none");
    const std::string& output = opt.output;

    if (opt.gpu) {
        if (dist::Processes::current().distributed())
            throw std::invalid_argument(
                "render --gpu draws on one process; leave out mpirun (animate --gpu shares "
                "frames among ranks)");
#ifdef LIGHTCONE_WITH_VTK
        return renderWithShaders(scene, output, opt.orbitFrames, opt.polygonDistortion);
#else
        throw std::invalid_argument("--gpu needs a build with VTK");
#endif
    }
    const dist::Processes& processes = dist::Processes::current();
    warnAboutFixedSteps(scene);
    ProgressBar bar(!opt.quiet && processes.root());
    ColouredImage image;
    if (processes.distributed()) {
        // Bands of rows over the ranks, assembled on rank 0 (app/commands/frame_renderer.hpp).
        AnimationPath still;
        still.still = true;
        const FrameSequence one(loadEditableScene(opt), still, [&opt](Scene& s) { opt.applyTo(s); });
        FrameRenderOptions how;
        how.polygonDistortion = opt.polygonDistortion;
        how.bandRows = opt.tileRows;
        how.schedule = opt.staticSchedule ? dist::Schedule::Static : dist::Schedule::Dynamic;
        how.progress = [&bar](double f) { bar(f); };
        const auto t0 = std::chrono::steady_clock::now();
        const FramesReport report =
            renderFrames(one, {0}, how, [&image](int, ColouredImage&& frame) { image = std::move(frame); });
        if (!processes.root()) return 0;
        image.records.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("distributed over %d processes, %d bands of rows\n", processes.size(), report.bandsPerFrame);
        printTaskReport(report.tasks, 1);
    } else {
        image = renderColouredImage(
            scene, [&bar](double f) { bar(f); }, opt.polygonDistortion);
    }
    const std::vector<AgeImage> ages = ageImages(scene);  // travellers' images, solved once
    const RenderResult& result = image.records;
    const RenderReport report = renderReport(scene, result, opt.polygonDistortion);
    writeRenderOutputs(image, output, opt.data, ageLabels(scene, ages), report.figures());
    for (const std::string& line : report.lines()) std::printf("%s\n", line.c_str());
    if (!scene.disks.empty()) writeSpectrum(scene, result, opt.spectrum);
    // Travellers: every image of each one's centre with its age (proper time at emission).
    for (const AgeImage& age : ages)
        std::printf("image of '%s': proper time %.4f at emission, emitted at t = %.4f\n", age.name.c_str(),
                    age.properTime, age.emissionTime);
    std::printf("wrote %s%s%s\n", output.c_str(), opt.data.empty() ? "" : " and ", opt.data.c_str());
    return 0;
}

}  // namespace lc::cli
