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
    std::memcpy(out, &h, sizeof h);
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

FramesReport renderFrames(const FrameSequence& sequence, const std::vector<int>& frames,
                          const FrameRenderOptions& options, const std::function<void(int, ColouredImage&&)>& done) {
    const dist::Processes& processes = dist::Processes::current();
    SceneCache scenes(sequence);
    // Every rank decides the same split from frame 0 of the list (same files, same result).
    FramesReport report;
    if (frames.empty()) return report;
    const Scene firstScene = scenes.get(frames.front());
    const bool banded = inBands(firstScene, options);
    // Automatic: 8 rows, or fewer so that every rank gets about 8 bands of a small image.
    const int bandRows = options.bandRows > 0
                             ? options.bandRows
                             : std::max(1, std::min(8, firstScene.camera.height / (8 * processes.size())));
    report.bandsPerFrame =
        banded && processes.distributed() ? std::max(1, (firstScene.camera.height + bandRows - 1) / bandRows) : 1;
    const int bands = report.bandsPerFrame;

    // Photo-objects for a camera-only path: the same past light cone in every frame.
    std::once_flag photosBuilt;
    std::shared_ptr<std::vector<PhotoSceneObject>> photos;
    auto sharedPhotos = [&](const Scene& scene) -> std::shared_ptr<const std::vector<PhotoSceneObject>> {
        if (!sequence.path().cameraOnly() || isSrScene(scene)) return nullptr;
#ifdef LIGHTCONE_WITH_VTK
        const bool godelShaders = options.gpu && shaderPathFor(scene) == ShaderPath::Godel;
#else
        const bool godelShaders = false;
#endif
        if (!godelShaders && (options.gpu || resolveMethod(scene) != RenderSettings::Method::PerVertex)) return nullptr;
        std::call_once(photosBuilt, [&] {
            photos = std::make_shared<std::vector<PhotoSceneObject>>(buildPhotoScene(scene, photoSceneOptions(scene)));
        });
        return photos;
    };

    const int tasks = static_cast<int>(frames.size()) * bands;
    const bool singleProcess = !processes.distributed();
    int tasksDone = 0;
    const int failingRank = failingRankForTests();
    auto work = [&](int task) -> std::string {
        if (processes.distributed() && processes.rank() == failingRank)
            throw std::runtime_error("failure injected by LIGHTCONE_TEST_FAIL_RANK (a test of failing ranks)");
        const int frame = frames[static_cast<std::size_t>(task / bands)], band = task % bands;
        BandHeader h;
        h.frame = frame;
        if (options.alreadyDone && options.alreadyDone(frame)) {
            h.skipped = 1;
            return encode(h, {});
        }
        Scene scene = scenes.get(frame);
        const int height = scene.camera.height;
        h.width = scene.camera.width;
        h.height = height;
        h.rowBegin = static_cast<int>(static_cast<long long>(height) * band / bands);
        h.rowEnd = static_cast<int>(static_cast<long long>(height) * (band + 1) / bands);
        ColouredImage image;
        // Within-frame progress only where this thread is rank 0's only renderer.
        ProgressCallback rows;
        if (singleProcess && options.progress) rows = [&](double f) { options.progress((tasksDone + f) / tasks); };
        if (options.gpu) {
#ifdef LIGHTCONE_WITH_VTK
            image.records = blankResult(scene.camera);
            image.rgb = renderShaderImage(scene, sharedPhotos(scene));
#else
            throw std::invalid_argument("--gpu needs a build with VTK");
#endif
            h.hasRgb = 1;
        } else if (banded) {
            if (h.rowBegin == h.rowEnd) return encode(h, image);
            scene.settings.rowBegin = h.rowBegin;
            scene.settings.rowEnd = h.rowEnd;
            image.records = render(scene, rows);
            if (!options.keepRecords) {  // shading is per pixel: the band's colours are the frame's
                image.rgb = shadePixels(scene, image.records);
                h.hasRgb = 1;
                h.hasRecords = 0;
            }
        } else {
            image = renderColouredImage(scene, rows, options.polygonDistortion, sharedPhotos(scene).get());
            h.hasRgb = 1;
        }
        return encode(h, image);
    };

    std::map<int, PartialFrame> partial;
    auto deliver = [&](int, std::string&& bytes) {
        ++tasksDone;
        const BandHeader h = headerOf(bytes);
        PartialFrame& p = partial[h.frame];
        if (p.bandsLeft == 0) p.bandsLeft = bands;
        if (h.skipped) {
            p.skipped = true;
            if (--p.bandsLeft == 0) {
                partial.erase(h.frame);
                ++report.skipped;
            }
        } else {
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
            if (h.hasRecords) {
                std::memcpy(img.records.pixels.data() + first, in, count * sizeof(PixelRecord));
                in += count * sizeof(PixelRecord);
            }
            if (h.hasRgb) {
                img.rgb.resize(3 * img.records.pixels.size());
                std::memcpy(img.rgb.data() + 3 * first, in, 3 * count * sizeof(float));
                p.shaded = true;
            }
            if (--p.bandsLeft == 0 && p.skipped) {  // another job wrote it meanwhile: keep that file
                partial.erase(h.frame);
                ++report.skipped;
            } else if (p.bandsLeft == 0) {
                ColouredImage finished = std::move(img);
                const bool shaded = p.shaded;
                partial.erase(h.frame);
                if (!shaded) {
                    const Scene scene = scenes.get(h.frame);
                    finished.rgb = shadePixels(scene, finished.records);
                }
                summarise(finished.records, std::chrono::steady_clock::now());
                scenes.forget(h.frame);
                ++report.rendered;
                done(h.frame, std::move(finished));
            }
        }
        if (options.progress) options.progress(static_cast<double>(tasksDone) / tasks);
    };
    if (processes.distributed()) {
        // Which frame failed, beside the rank and task the distributor names.
        auto framed = [&](int task) {
            try {
                return work(task);
            } catch (const std::exception& e) {
                throw std::runtime_error("frame " + std::to_string(frames[static_cast<std::size_t>(task / bands)]) +
                                         ": " + e.what());
            }
        };
        report.tasks = dist::runTasks(tasks, framed, deliver, options.schedule);
    } else {
        // One process: the tasks in order, their exceptions as they are (messages, exit codes).
        for (int task = 0; task < tasks; ++task) deliver(task, work(task));
    }
    return report;
}

}  // namespace lc::cli
