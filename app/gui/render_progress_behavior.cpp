// SPDX-License-Identifier: BSD-3-Clause
#include "render_progress_behavior.hpp"

#include "scene_read_job.hpp"

#include "render_controller.hpp"

#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>

namespace lc::gui {

RenderProgressBehavior::RenderProgressBehavior(RenderController* render, QStatusBar* bar)
    : QObject(bar), render_(render), progress_(new QProgressBar(bar)), cancel_(new QPushButton("Cancel", bar)) {
    progress_->setRange(0, 1000);
    progress_->setMaximumWidth(200);
    progress_->setVisible(false);
    cancel_->setObjectName("cancelRender");
    cancel_->setVisible(false);
    bar->addPermanentWidget(progress_);
    bar->addPermanentWidget(cancel_);
    connect(cancel_, &QPushButton::clicked, render, &RenderController::cancel);
    connect(render, &RenderController::progressed, this, [this](double f) {
        progress_->setValue(static_cast<int>(1000 * f));
        progress_->setVisible(true);
        cancel_->setVisible(true);
    });
    connect(render, &RenderController::stopped, this, [this] {
        if (reading_ && reading_->running()) return;  // the old scene's render stopped: the read goes on
        progress_->setVisible(false);
        cancel_->setVisible(false);
    });
}

void RenderProgressBehavior::watchReading(SceneReadJob* reading) {
    reading_ = reading;
    connect(cancel_, &QPushButton::clicked, reading, &SceneReadJob::cancel);
    connect(reading, &SceneReadJob::started, this, [this] {
        progress_->setRange(0, 0);
        progress_->setVisible(true);
        cancel_->setVisible(true);
    });
    auto stopped = [this] {
        progress_->setRange(0, 1000);
        if (render_->rendering()) return;  // the new scene's render began: its progress shows
        progress_->setVisible(false);
        cancel_->setVisible(false);
    };
    connect(reading, &SceneReadJob::finished, this, stopped);
    connect(reading, &SceneReadJob::failed, this, stopped);
    connect(reading, &SceneReadJob::cancelled, this, stopped);
}

}  // namespace lc::gui
