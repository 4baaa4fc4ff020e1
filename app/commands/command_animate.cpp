// SPDX-License-Identifier: BSD-3-Clause
// `lightcone animate`: a sequence of frames along a path (the observer's proper time, a camera
// pan or orbit, a sweep of a scene field), rendered by any method, optionally over MPI ranks,
// resumable, and made into a movie by ffmpeg when it is installed.
#include "app/cli/command_options.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/frame_renderer.hpp"
#include "app/commands/render_report.hpp"
#include "app/cli/progress_bar.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/session_file.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace lc::cli {
namespace {

namespace fs = std::filesystem;

// The first `name` on PATH that can be executed; empty when there is none.
std::string findOnPath(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
        start = end + 1;
    }
    return "";
}

const std::vector<std::string>& movieExtensions() {
    static const std::vector<std::string> ext{".mp4", ".mkv", ".mov", ".webm", ".gif"};
    return ext;
}

std::vector<int> framesToRender(const AnimateOptions& opt, int frames) {
    int first = 0, last = frames - 1;
    if (opt.frameRange) {
        first = opt.frameRange->first;
        last = opt.frameRange->second;
        if (last >= frames)
            throw std::invalid_argument("option --frames: the path has frames 0 to " + std::to_string(frames - 1) +
                                        ", not " + std::to_string(last));
    }
    std::vector<int> list;
    for (int k = first; k <= last; ++k) list.push_back(k);
    return list;
}

bool framesExist(const AnimateOptions& opt, int frame) {
    return fs::exists(opt.output.path(frame)) && (opt.data.empty() || fs::exists(opt.data.path(frame)));
}

// ffmpeg reads the frames (its %0Nd patterns are ours) into a temporary file beside the movie,
// renamed over it when ffmpeg succeeds: a failed encode replaces nothing.
void encodeMovie(const std::string& ffmpeg, const AnimateOptions& opt, int frames) {
    const fs::path movie(opt.movie);
    const fs::path temporary =
        movie.parent_path() / (".lightcone-movie-" + std::to_string(::getpid()) + "-" + movie.filename().string());
    const std::string fps = std::to_string(opt.fps);
    // -frames:v: frames of an earlier, longer run beyond this path's last stay out of the movie.
    std::vector<std::string> args{
        ffmpeg,          "-nostdin", "-y", "-loglevel",          "error",     "-framerate",          fps,
        "-start_number", "0",        "-i", opt.output.pattern(), "-frames:v", std::to_string(frames)};
    if (movie.extension() != ".gif")  // players want even sizes and 4:2:0 chroma
        for (const char* a : {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p"}) args.emplace_back(a);
    args.push_back(temporary.string());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::fflush(nullptr);
    const pid_t child = ::fork();
    if (child < 0) throw std::runtime_error("--movie: cannot start ffmpeg");
    if (child == 0) {
        ::execv(argv[0], argv.data());
        std::_Exit(127);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw std::runtime_error("--movie: ffmpeg failed making " + opt.movie + " from " + opt.output.pattern() +
                                 " (its message is above); the frames are kept");
    }
    fs::rename(temporary, movie);
}

}  // namespace

// The frames' render error estimates (core/render/error_estimate, computed by lc::render for each
// whole frame the numeric tracer draws), summed up for the run's summary.
struct FramesErrorEstimate {
    double worstPixels = 0, tighterTolerance = 0;
    int worstFrame = -1, raysPerFrame = 0;
    std::vector<double> medians;

    void add(int frame, const RenderStats& s) {
        if (s.errorRays <= 0) return;
        if (worstFrame < 0 || s.errorMaxPixels > worstPixels) worstPixels = s.errorMaxPixels, worstFrame = frame;
        medians.push_back(s.errorMedianPixels);
        raysPerFrame = std::max(raysPerFrame, s.errorRays);
        tighterTolerance = s.errorTighterTolerance;
    }
    bool empty() const { return medians.empty(); }
    int frames() const { return static_cast<int>(medians.size()); }
    double medianOfMedians() const {
        std::vector<double> m = medians;
        std::nth_element(m.begin(), m.begin() + m.size() / 2, m.end());
        return m[m.size() / 2];
    }
};

int runAnimate(const std::vector<std::string>& argv) {
    const AnimateOptions opt = parseAnimateOptions(argv);
    const dist::Processes& processes = dist::Processes::current();
    // Every output and tool is checked before the first frame is traced.
    std::string ffmpeg;
    if (!opt.movie.empty()) {
        io::checkOutputPath(opt.movie, movieExtensions(), "--movie");
        ffmpeg = findOnPath("ffmpeg");
        if (ffmpeg.empty())
            throw std::invalid_argument(
                "--movie needs ffmpeg (Debian package ffmpeg), which is not on PATH; leave out --movie to write the "
                "frames alone");
        const std::string ext = fs::path(opt.output.pattern()).extension().string();
        if (ext != ".png" && ext != ".jpg" && ext != ".jpeg")
            throw std::invalid_argument("--movie is made from PNG or JPEG frames (-o frames/%04d.png), not " + ext);
    }
    if (opt.render.gpu && !std::getenv("DISPLAY"))
        throw std::runtime_error("the shader renderers draw through GLX and need an X display (hint: xvfb-run -a)");
    io::EditableScene base = loadEditableScene(opt.render);
    // The command line's path replaces the scene's "animation" block as a whole.
    const AnimationPath path = opt.path.empty() ? base.scene().animation : opt.path;
    const RenderOptions overrides = opt.render;
    const FrameSequence sequence(std::move(base), path, [overrides](Scene& s) { overrides.applyTo(s); });
    const std::vector<int> frames = framesToRender(opt, sequence.size());
    // Only a run that will render makes the frames' folder.
    if (processes.root()) {
        prepareFrameFolder(opt.output, "-o", io::imageExtensions());
        if (!opt.data.empty()) prepareFrameFolder(opt.data, "--data", io::multiChannelImageExtensions());
    }

    warnAboutFixedSteps(sequence.scene(0));
    ProgressBar bar(processes.root() && !opt.render.quiet, "frames ");
    FrameRenderOptions how;
    how.gpu = opt.render.gpu;
    how.polygonDistortion = opt.render.polygonDistortion;
    how.bandRows = opt.render.tileRows;
    how.keepRecords = !opt.data.empty();
    how.schedule = opt.render.staticSchedule ? dist::Schedule::Static : dist::Schedule::Dynamic;
    if (opt.resume) how.alreadyDone = [&opt](int frame) { return framesExist(opt, frame); };
    how.progress = [&bar](double f) { bar(f); };
    const auto t0 = std::chrono::steady_clock::now();
    FramesErrorEstimate error;
    const FramesReport report = renderFrames(sequence, frames, how, [&](int frame, ColouredImage&& image) {
        error.add(frame, image.records.stats);
        const Scene scene = sequence.scene(frame);
        writeRenderOutputs(image, opt.output.path(frame), opt.data.empty() ? "" : opt.data.path(frame),
                           ageLabels(scene, ageImages(scene)));
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!processes.root()) return 0;

    const Scene first = sequence.scene(frames.front());
    std::printf("animated %s: frames %d to %d of %d, %dx%d, %s; %d rendered, %d skipped (already written)\n",
                first.source.c_str(), frames.front(), frames.back(), sequence.size(), first.camera.width,
                first.camera.height,
                opt.render.gpu     ? "shaders"
                : isSrScene(first) ? "special relativity"
                                   : renderMethodName(resolveMethod(first)).c_str(),
                report.rendered, report.skipped);
    std::printf("time %.3f s (%.3f s per rendered frame) on %d process%s", seconds,
                report.rendered ? seconds / report.rendered : 0.0, processes.size(), processes.size() > 1 ? "es" : "");
    if (processes.distributed()) std::printf(", %d bands per frame", report.bandsPerFrame);
    std::printf("\n");
    if (processes.distributed()) printTaskReport(report.tasks, report.rendered);
    if (!error.empty())
        std::printf(
            "estimated error: escape directions within %.2g px (frame %d; median of the frames' medians %.2g px) "
            "over %d frames, on %d sampled sky rays a frame traced again at tolerance %.1e\n",
            error.worstPixels, error.worstFrame, error.medianOfMedians(), error.frames(), error.raysPerFrame,
            error.tighterTolerance);
    std::printf("wrote %s\n", opt.output.pattern().c_str());
    if (!opt.movie.empty()) {
        for (int k = 0; k < sequence.size(); ++k)
            if (!fs::exists(opt.output.path(k)))
                throw std::runtime_error("--movie needs every frame; " + opt.output.path(k) +
                                         " is missing (render the other --frames first)");
        encodeMovie(ffmpeg, opt, sequence.size());
        std::printf("wrote %s (%d frames at %d fps)\n", opt.movie.c_str(), sequence.size(), opt.fps);
    }
    return 0;
}

}  // namespace lc::cli
