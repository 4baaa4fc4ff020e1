// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The CPU work of a scene off the GUI thread, with progress and Cancel: first, where asked, the
// Goedel photo-objects the shader renderer draws (photoSceneReady), then the CPU image with its
// per-pixel data (lc::renderColouredImage, as `lightcone render`). One worker at a time:
// starting a job while one runs cancels it and queues the new one, which starts when the old
// one has stopped (so cancelled work never piles up on the cores); only the newest job's
// signals are emitted, always on the GUI thread.
#include "core/render/photo_scene.hpp"
#include "core/render/special_relativity.hpp"

#include <QObject>

#include <atomic>
#include <memory>
#include <thread>
#include <vector>

namespace lc::gui {

class RenderJob : public QObject {
    Q_OBJECT
public:
    explicit RenderJob(QObject* parent = nullptr);
    ~RenderJob() override;  // cancels and waits for every worker

    void start(const lc::Scene& scene, bool photoSceneFirst = false);
    // Ends the newest job at once (running() is false, cancelled() follows); its worker stops
    // within about one image row per thread (RenderCancelled).
    void cancel();
    bool running() const { return running_; }

signals:
    void progressed(double fraction);
    void photoSceneReady(std::shared_ptr<const std::vector<lc::PhotoSceneObject>> photos);
    void finished(std::shared_ptr<const lc::ColouredImage> image);
    void failed(const QString& message);
    void cancelled();

private:
    void launch(const lc::Scene& scene, bool photoSceneFirst);
    void workerStopped();

    std::thread worker_;
    std::shared_ptr<std::atomic<bool>> cancel_;
    bool workerRunning_ = false;
    struct Pending {
        lc::Scene scene;
        bool photoSceneFirst = false;
    };
    std::unique_ptr<Pending> pending_;
    int generation_ = 0;
    bool running_ = false;
};

}  // namespace lc::gui
