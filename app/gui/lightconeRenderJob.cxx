#include "lightconeRenderJob.h"


#include <QMetaObject>
#include <QPointer>

#include <chrono>

namespace lcgui {

RenderJob::RenderJob(QObject* parent) : QObject(parent) {
    qRegisterMetaType<std::shared_ptr<const lc::ColouredImage>>("std::shared_ptr<const lc::ColouredImage>");
    qRegisterMetaType<std::shared_ptr<const std::vector<lc::PhotoSceneObject>>>("std::shared_ptr<const std::vector<lc::PhotoSceneObject>>");
}

RenderJob::~RenderJob() {
    for (auto& w : workers_) w.cancel->store(true);
    for (auto& w : workers_) w.thread.join();
}

void RenderJob::reapFinishedWorkers() {
    for (auto it = workers_.begin(); it != workers_.end();) {
        if (it->done->load()) {
            it->thread.join();
            it = workers_.erase(it);
        } else {
            ++it;
        }
    }
}

void RenderJob::cancel() {
    for (auto& w : workers_) w.cancel->store(true);
}

void RenderJob::start(const lc::Scene& scene, bool photoSceneFirst) {
    cancel();  // an older render finishes its current rows in the background and is dropped
    reapFinishedWorkers();
    const int generation = ++generation_;
    running_ = true;
    Worker w{std::thread(), std::make_shared<std::atomic<bool>>(false), std::make_shared<std::atomic<bool>>(false)};
    // The worker only posts to this object through a QPointer checked on the GUI thread; the
    // destructor joins every worker before this object goes away.
    QPointer<RenderJob> self(this);
    auto post = [self, generation](auto fn) {
        QMetaObject::invokeMethod(
            self.data(), [self, generation, fn] {
                if (self && generation == self->generation_) fn(*self);
            },
            Qt::QueuedConnection);
    };
    w.thread = std::thread([scene, photoSceneFirst, cancelFlag = w.cancel, doneFlag = w.done, post] {
        auto lastPost = std::chrono::steady_clock::now();
        auto progress = [&](double f) {
            if (cancelFlag->load()) throw lc::RenderCancelled();
            const auto now = std::chrono::steady_clock::now();
            if (now - lastPost > std::chrono::milliseconds(50)) {  // a few updates per second are enough
                lastPost = now;
                post([f](RenderJob& job) { emit job.progressed(f); });
            }
        };
        try {
            std::shared_ptr<const std::vector<lc::PhotoSceneObject>> photos;
            if (photoSceneFirst) {
                lc::PhotoSceneOptions po = lc::photoSceneOptions(scene);
                po.progress = progress;
                photos = std::make_shared<const std::vector<lc::PhotoSceneObject>>(lc::buildPhotoScene(scene, po));
                post([photos](RenderJob& job) { emit job.photoSceneReady(photos); });
            }
            // The per-vertex CPU renderer draws the same photo-objects: built once for both.
            auto image = std::make_shared<lc::ColouredImage>(lc::renderColouredImage(scene, progress, false, photos.get()));
            if (cancelFlag->load()) throw lc::RenderCancelled();
            post([image](RenderJob& job) {
                job.running_ = false;
                emit job.finished(image);
            });
        } catch (const lc::RenderCancelled&) {
            post([](RenderJob& job) {
                job.running_ = false;
                emit job.cancelled();
            });
        } catch (const std::exception& e) {
            const QString message = QString::fromStdString(e.what());
            post([message](RenderJob& job) {
                job.running_ = false;
                emit job.failed(message);
            });
        }
        doneFlag->store(true);
    });
    workers_.push_back(std::move(w));
}

}  // namespace lcgui
