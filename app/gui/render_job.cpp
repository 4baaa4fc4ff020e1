// SPDX-License-Identifier: BSD-3-Clause
#include "render_job.hpp"

#include <QMetaObject>
#include <QPointer>

#include <chrono>

namespace lc::gui {

RenderJob::RenderJob(QObject* parent) : QObject(parent) {
    qRegisterMetaType<std::shared_ptr<const lc::ColouredImage>>("std::shared_ptr<const lc::ColouredImage>");
    qRegisterMetaType<std::shared_ptr<const std::vector<lc::PhotoSceneObject>>>(
        "std::shared_ptr<const std::vector<lc::PhotoSceneObject>>");
}

RenderJob::~RenderJob() {
    pending_.reset();
    if (cancel_) cancel_->store(true);
    if (worker_.joinable()) worker_.join();
}

void RenderJob::cancel() {
    if (cancel_) cancel_->store(true);
    pending_.reset();
    if (!running_) return;
    // The newest job ends here, at once: a Ctrl+R or a pick right after Cancel starts a new one
    // (queued behind the stopping worker), and what the old worker still posts is ignored.
    const int cancelledGeneration = ++generation_;
    running_ = false;
    // Reported unless a new job started meanwhile (Escape then Ctrl+R): a stale "cancelled" would
    // otherwise arrive after the new job began and report it stopped.
    QMetaObject::invokeMethod(
        this,
        [this, cancelledGeneration] {
            if (cancelledGeneration == generation_) emit cancelled();
        },
        Qt::QueuedConnection);
}

void RenderJob::start(const lc::Scene& scene, bool photoSceneFirst) {
    ++generation_;  // whatever the running worker still posts is for an older scene
    running_ = true;
    if (workerRunning_) {
        cancel_->store(true);
        pending_ = std::make_unique<Pending>(Pending{scene, photoSceneFirst});
        return;
    }
    launch(scene, photoSceneFirst);
}

void RenderJob::workerStopped() {
    if (worker_.joinable()) worker_.join();
    workerRunning_ = false;
    if (pending_) {
        const std::unique_ptr<Pending> next = std::move(pending_);
        launch(next->scene, next->photoSceneFirst);
    }
}

void RenderJob::launch(const lc::Scene& scene, bool photoSceneFirst) {
    const int generation = generation_;
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    workerRunning_ = true;
    // The worker posts to this object only; the destructor joins it before this object goes.
    QPointer<RenderJob> self(this);
    auto post = [self, generation](auto fn) {
        QMetaObject::invokeMethod(
            self.data(),
            [self, generation, fn] {
                if (self && generation == self->generation_) fn(*self);
            },
            Qt::QueuedConnection);
    };
    auto stopped = [self] {
        QMetaObject::invokeMethod(
            self.data(),
            [self] {
                if (self) self->workerStopped();
            },
            Qt::QueuedConnection);
    };
    worker_ = std::thread([scene, photoSceneFirst, cancelFlag = cancel_, post, stopped] {
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
                po.vertexLight = true;  // the shader image lights its vertices with them
                po.progress = progress;
                photos = std::make_shared<const std::vector<lc::PhotoSceneObject>>(lc::buildPhotoScene(scene, po));
                post([photos](RenderJob& job) { emit job.photoSceneReady(photos); });
            }
            // The per-vertex CPU renderer draws the same photo-objects: built once for both.
            auto image =
                std::make_shared<lc::ColouredImage>(lc::renderColouredImage(scene, progress, false, photos.get()));
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
        stopped();
    });
}

}  // namespace lc::gui
