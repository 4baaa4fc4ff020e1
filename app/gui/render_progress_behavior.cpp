// SPDX-License-Identifier: BSD-3-Clause
#include "render_progress_behavior.hpp"

#include "render_controller.hpp"

#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>

namespace lc::gui {

RenderProgressBehavior::RenderProgressBehavior(RenderController* render, QStatusBar* bar)
    : QObject(bar), progress_(new QProgressBar(bar)), cancel_(new QPushButton("Cancel", bar)) {
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
        progress_->setVisible(false);
        cancel_->setVisible(false);
    });
}

}  // namespace lc::gui
