// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// While the CPU render runs: a progress bar and a Cancel button in the status bar (ParaView's
// progress behaviour), gone when it stops.
#include <QObject>

class QProgressBar;
class QPushButton;
class QStatusBar;

namespace lc::gui {

class RenderController;
class SceneReadJob;

class RenderProgressBehavior : public QObject {
    Q_OBJECT
public:
    RenderProgressBehavior(RenderController* render, QStatusBar* bar);
    // A scene read in the background: the bar busy (no fraction to show) and Cancel stops it.
    void watchReading(SceneReadJob* reading);
    QPushButton* cancelButton() const { return cancel_; }
    QProgressBar* progressBar() const { return progress_; }

private:
    RenderController* render_;
    QProgressBar* progress_;
    QPushButton* cancel_;
    SceneReadJob* reading_ = nullptr;
};

}  // namespace lc::gui
