// SPDX-License-Identifier: BSD-3-Clause
// Frames as tasks over processes: bands of rows for per-pixel methods, whole frames otherwise.
#include "app/commands/frame_renderer.hpp"

#include "app/commands/commands.hpp"
#include "core/render/photo_scene.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <type_traits>

namespace lc::cli {
namespace {

static_assert(std::is_trivially_copyable_v<PixelRecord>, "pixel records travel between ranks as bytes");

// Frame scenes built at most once per process and frame while in use (a sweep re-reads the
// scene file per frame; bands of one frame share it).
class SceneCache {
public:
    explicit SceneCache(const FrameSequence& sequence) : sequence_(sequence) {}
    Scene get(int frame) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            const auto it = scenes_.find(frame);
            if (it != scenes_.end()) return it->second;
        }
        // Built outside the lock: rank 0's serving thread must not wait for a scene file read.
        Scene scene = sequence_.scene(frame);
        std::lock_guard<std::mutex> lock(mutex_);
        if (scenes_.size() >= 4) scenes_.erase(scenes_.begin());
        scenes_.emplace(frame, scene);
        return scene;
    }
    void forget(int frame) {
        std::lock_guard<std::mutex> lock(mutex_);
        scenes_.erase(frame);
    }

private:
    const FrameSequence& sequence_;
    std::mutex mutex_;
    std::map<int, Scene> scenes_;
};

bool inBands(const Scene& scene, const FrameRenderOptions& options) {
    if (options.gpu || options.polygonDistortion || isSrScene(scene)) return false;
    const RenderSettings::Method m = resolveMethod(scene);
    return m == RenderSettings::Method::Numeric || m == RenderSettings::Method::ClosedForm;
}

// One task's result: which rows of which frame, their records, and their colours when the
// task shaded them itself (whole frames).
struct BandHeader {
    std::int32_t frame = 0, width = 0, height = 0, rowBegin = 0, rowEnd = 0, hasRecords = 1, hasRgb = 0, skipped = 0;
    // The frame's render error estimate (RenderStats), carried by a band that is the whole frame.
    std::int32_t errorRays = 0, padding = 0;
    double errorMaxPixels = 0, errorMedianPixels = 0, errorTighterTolerance = 0;
    std::size_t bytes() const {
        const std::size_t pixels = static_cast<std::size_t>(rowEnd - rowBegin) * width;
        return sizeof(BandHeader) + (hasRecords ? pixels * sizeof(PixelRecord) : 0) +
               (hasRgb ? 3 * pixels * sizeof(float) : 0);
    }
};

std::string encode(const BandHeader& h, const ColouredImage& image) {
    const std::size_t first = static_cast<std::size_t>(h.rowBegin) * h.width;
    const std::size_t count = static_cast<std::size_t>(h.rowEnd - h.rowBegin) * h.width;
    std::string bytes(h.bytes(), '\0');
    char* out = bytes.data();
    BandHeader withError = h;
    const RenderStats& s = image.records.stats;
    withError.errorRays = s.errorRays;
    withError.errorMaxPixels = s.errorMaxPixels;
    withError.errorMedianPixels = s.errorMedianPixels;
    withError.errorTighterTolerance = s.errorTighterTolerance;
    std::memcpy(out, &withError, sizeof h);
    out += sizeof h;
    if (count == 0) return bytes;
    if (h.hasRecords) {
        std::memcpy(out, image.records.pixels.data() + first, count * sizeof(PixelRecord));
        out += count * sizeof(PixelRecord);
    }
    if (h.hasRgb) std::memcpy(out, image.rgb.data() + 3 * first, 3 * count * sizeof(float));
    return bytes;
}

BandHeader headerOf(const std::string& bytes) {
    BandHeader h;
    if (bytes.size() < sizeof h) throw std::runtime_error("a rank sent a truncated result");
    std::memcpy(&h, bytes.data(), sizeof h);
    return h;
}

// Frames being assembled on rank 0.
struct PartialFrame {
    ColouredImage image;
    int bandsLeft = 0;
    bool shaded = false;
    bool skipped = false;  // some band found the frame written already (--resume)
};

// Test hook (tests/app/test_distributed_render.cpp): the rank named by LIGHTCONE_TEST_FAIL_RANK
// fails each task it gets, to show that one rank's failure ends the whole run, nothing written.
int failingRankForTests() {
    const char* rank = std::getenv("LIGHTCONE_TEST_FAIL_RANK");
    return rank ? std::atoi(rank) : -1;
}

}  // namespace

void printTaskReport(const dist::TaskReport& report, int frames) {
    double busiest = 0, total = 0;
    for (std::size_t r = 0; r < report.ranks.size(); ++r) {
        const dist::RankReport& rank = report.ranks[r];
        std::printf("rank %zu: %d tasks, busy %.3f s (%.0f %% of %.3f s), sent %.2f MB\n", r, rank.tasks,
                    rank.busySeconds, report.seconds > 0 ? 100 * rank.busySeconds / report.seconds : 0.0,
                    report.seconds, rank.bytesSent / 1e6);
        busiest = std::max(busiest, rank.busySeconds);
        total += rank.busySeconds;
    }
    const double mean = report.ranks.empty() ? 0 : total / report.ranks.size();
    std::printf("load imbalance %.3f (busiest rank / mean); %.2f MB gathered to rank 0, %.2f MB per frame\n",
                mean > 0 ? busiest / mean : 1.0, report.bytesToRoot / 1e6,
                frames > 0 ? report.bytesToRoot / 1e6 / frames : 0.0);
}

namespace {

// How a frame list is cut into tasks: whole frames, or bands of rows of every frame. Every rank
// decides the same split from the first frame of the list (same files, same result).
struct TaskLayout {
    bool banded = false;
    int bands = 1;  // per frame
    int tasks = 0;
};

TaskLayout layoutTasks(const Scene& first, const FrameRenderOptions& options, int frames) {
    const dist::Processes& processes = dist::Processes::current();
    TaskLayout layout;
    layout.banded = inBands(first, options);
    // Automatic: 8 rows, or fewer so that every rank gets about 8 bands of a small image.
    const int bandRows = options.bandRows > 0 ? options.bandRows
                                              : std::max(1, std::min(8, first.camera.height / (8 * processes.size())));
    if (layout.banded && processes.distributed())
        layout.bands = std::max(1, (first.camera.height + bandRows - 1) / bandRows);
    layout.tasks = frames * layout.bands;
    return layout;
}

// Photo-objects for a camera-only path: the same past light cone in every frame, built once.
class SharedPhotos {
public:
    SharedPhotos(const FrameSequence& sequence, const FrameRenderOptions& options)
        : sequence_(sequence), options_(options) {}
    // Null where each frame builds its own (the scene changes, or the method has no photo-objects).
    std::shared_ptr<const std::vector<PhotoSceneObject>> operator()(const Scene& scene) {
        if (!sequence_.path().cameraOnly() || isSrScene(scene)) return nullptr;
#ifdef LIGHTCONE_WITH_VTK
        const bool godelShaders = options_.gpu && shaderPathFor(scene) == ShaderPath::Godel;
#else
        const bool godelShaders = false;
#endif
        if (!godelShaders && (options_.gpu || resolveMethod(scene) != RenderSettings::Method::PerVertex))
            return nullptr;
        std::call_once(built_, [&] {
            PhotoSceneOptions options = photoSceneOptions(scene);
            options.vertexLight = godelShaders;  // the CPU per-vertex renderer lights per pixel
            photos_ = std::make_shared<std::vector<PhotoSceneObject>>(buildPhotoScene(scene, options));
        });
        return photos_;
    }

private:
    const FrameSequence& sequence_;
    const FrameRenderOptions& options_;
    std::once_flag built_;
    std::shared_ptr<std::vector<PhotoSceneObject>> photos_;
};

// One task on whichever rank gets it: a frame or a band of rows of it, rendered and encoded.
class TaskRenderer {
public:
    TaskRenderer(SceneCache& scenes, const std::vector<int>& frames, const TaskLayout& layout,
                 const FrameRenderOptions& options, SharedPhotos& photos, const int& tasksDone)
        : scenes_(scenes),
          frames_(frames),
          layout_(layout),
          options_(options),
          photos_(photos),
          tasksDone_(tasksDone) {}

    std::string operator()(int task) {
        const dist::Processes& processes = dist::Processes::current();
        if (processes.distributed() && processes.rank() == failingRankForTests())
            throw std::runtime_error("failure injected by LIGHTCONE_TEST_FAIL_RANK (a test of failing ranks)");
        const int frame = frames_[static_cast<std::size_t>(task / layout_.bands)], band = task % layout_.bands;
        BandHeader h;
        h.frame = frame;
        if (options_.alreadyDone && options_.alreadyDone(frame)) {
            h.skipped = 1;
            return encode(h, {});
        }
        Scene scene = scenes_.get(frame);
        const int height = scene.camera.height;
        h.width = scene.camera.width;
        h.height = height;
        h.rowBegin = static_cast<int>(static_cast<long long>(height) * band / layout_.bands);
        h.rowEnd = static_cast<int>(static_cast<long long>(height) * (band + 1) / layout_.bands);
        return encode(h, render(scene, h));
    }

private:
    ColouredImage render(Scene& scene, BandHeader& h) {
        ColouredImage image;
        // Within-frame progress only where this thread is rank 0's only renderer.
        ProgressCallback rows;
        if (!dist::Processes::current().distributed() && options_.progress)
            rows = [this](double f) { options_.progress((tasksDone_ + f) / layout_.tasks); };
        if (options_.gpu) {
#ifdef LIGHTCONE_WITH_VTK
            image.records = blankResult(scene.camera);
            image.rgb = renderShaderImage(scene, photos_(scene));
#else
            throw std::invalid_argument("--gpu needs a build with VTK");
#endif
            h.hasRgb = 1;
        } else if (layout_.banded) {
            if (h.rowBegin == h.rowEnd) return image;
            scene.settings.rowBegin = h.rowBegin;
            scene.settings.rowEnd = h.rowEnd;
            image.records = lc::render(scene, rows);
            if (!options_.keepRecords) {  // shading is per pixel: the band's colours are the frame's
                image.rgb = shadePixels(scene, image.records);
                h.hasRgb = 1;
                h.hasRecords = 0;
            }
        } else {
            image = renderColouredImage(scene, rows, options_.polygonDistortion, photos_(scene).get());
            h.hasRgb = 1;
        }
        return image;
    }

    SceneCache& scenes_;
    const std::vector<int>& frames_;
    const TaskLayout& layout_;
    const FrameRenderOptions& options_;
    SharedPhotos& photos_;
    const int& tasksDone_;
};

// Rank 0: the tasks' results joined into frames; each finished frame is shaded if its bands were
// not, and handed to `done`.
class FrameAssembler {
public:
    FrameAssembler(SceneCache& scenes, int bands, FramesReport& report,
                   const std::function<void(int, ColouredImage&&)>& done)
        : scenes_(scenes), bands_(bands), report_(report), done_(done) {}

    void add(const std::string& bytes) {
        const BandHeader h = headerOf(bytes);
        PartialFrame& p = partial_[h.frame];
        if (p.bandsLeft == 0) p.bandsLeft = bands_;
        if (!h.skipped)
            copyBand(h, bytes, p);
        else
            p.skipped = true;
        if (--p.bandsLeft > 0) return;
        if (p.skipped) {  // another job wrote it meanwhile: keep that file
            partial_.erase(h.frame);
            ++report_.skipped;
            return;
        }
        finish(h.frame, p);
    }

private:
    void copyBand(const BandHeader& h, const std::string& bytes, PartialFrame& p) {
        ColouredImage& img = p.image;
        if (img.records.pixels.empty()) {
            img.records.width = h.width;
            img.records.height = h.height;
            img.records.pixels.resize(static_cast<std::size_t>(h.width) * h.height);
        }
        if (h.width != img.records.width || h.height != img.records.height)
            throw std::runtime_error("bands of frame " + std::to_string(h.frame) + " disagree on its size");
        const std::size_t first = static_cast<std::size_t>(h.rowBegin) * h.width;
        const std::size_t count = static_cast<std::size_t>(h.rowEnd - h.rowBegin) * h.width;
        if (bytes.size() != h.bytes())
            throw std::runtime_error("a rank sent a result of the wrong size for frame " + std::to_string(h.frame));
        const char* in = bytes.data() + sizeof h;
        if (h.errorRays > 0) {
            RenderStats& s = img.records.stats;
            s.errorRays = h.errorRays;
            s.errorMaxPixels = h.errorMaxPixels;
            s.errorMedianPixels = h.errorMedianPixels;
            s.errorTighterTolerance = h.errorTighterTolerance;
        }
        if (h.hasRecords) {
            std::memcpy(img.records.pixels.data() + first, in, count * sizeof(PixelRecord));
            in += count * sizeof(PixelRecord);
        }
        if (h.hasRgb) {
            img.rgb.resize(3 * img.records.pixels.size());
            std::memcpy(img.rgb.data() + 3 * first, in, 3 * count * sizeof(float));
            p.shaded = true;
        }
    }

    void finish(int frame, PartialFrame& p) {
        ColouredImage finished = std::move(p.image);
        const bool shaded = p.shaded;
        partial_.erase(frame);
        // The ranks' bands carry the records, not the result's flags.
        finished.records.lensing = scenes_.get(frame).settings.magnification;
        if (!shaded) finished.rgb = shadePixels(scenes_.get(frame), finished.records);
        summarise(finished.records, std::chrono::steady_clock::now());
        scenes_.forget(frame);
        ++report_.rendered;
        done_(frame, std::move(finished));
    }

    SceneCache& scenes_;
    const int bands_;
    FramesReport& report_;
    const std::function<void(int, ColouredImage&&)>& done_;
    std::map<int, PartialFrame> partial_;
};

}  // namespace

FramesReport renderFrames(const FrameSequence& sequence, const std::vector<int>& frames,
                          const FrameRenderOptions& options, const std::function<void(int, ColouredImage&&)>& done) {
    FramesReport report;
    if (frames.empty()) return report;
    SceneCache scenes(sequence);
    const TaskLayout layout = layoutTasks(scenes.get(frames.front()), options, static_cast<int>(frames.size()));
    report.bandsPerFrame = layout.bands;
    SharedPhotos photos(sequence, options);
    int tasksDone = 0;
    TaskRenderer work(scenes, frames, layout, options, photos, tasksDone);
    FrameAssembler assembler(scenes, layout.bands, report, done);
    auto deliver = [&](int, std::string&& bytes) {
        ++tasksDone;
        assembler.add(bytes);
        if (options.progress) options.progress(static_cast<double>(tasksDone) / layout.tasks);
    };
    if (dist::Processes::current().distributed()) {
        // Which frame failed, beside the rank and task the distributor names.
        auto framed = [&](int task) {
            try {
                return work(task);
            } catch (const std::exception& e) {
                throw std::runtime_error(
                    "frame " + std::to_string(frames[static_cast<std::size_t>(task / layout.bands)]) + ": " + e.what());
            }
        };
        report.tasks = dist::runTasks(layout.tasks, framed, deliver, options.schedule);
    } else {
        // One process: the tasks in order, their exceptions as they are (messages, exit codes).
        for (int task = 0; task < layout.tasks; ++task) deliver(task, work(task));
    }
    return report;
}

}  // namespace lc::cli
