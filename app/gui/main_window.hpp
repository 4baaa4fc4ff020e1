// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The Lightcone workbench (docs/GUI.md), assembled ParaView's way: the window only builds its
// parts and links them. The active scene (with its undo stack), the render controller, the docks,
// the selection linking, the reactions behind the menus (sessions, exports, camera) and the
// behaviours (render progress, persistent layout) are objects of their own; tests and callers
// talk to them.
#include <QMainWindow>

namespace lc::gui {

class ActiveScene;
class CameraReaction;
class ExportReaction;
class RenderComparison;
class PersistentLayoutBehavior;
class MetricReaction;
class RenderController;
class RenderProgressBehavior;
class SelectionLink;
class SessionReactions;
class ShadowOutlineOverlay;
class StatusReporter;
class WorkbenchDocks;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    ActiveScene* activeScene() const { return scene_; }
    RenderController* renderer() const { return render_; }
    WorkbenchDocks* docks() const { return docks_; }
    SelectionLink* selection() const { return selection_; }
    CameraReaction* camera() const { return camera_; }
    SessionReactions* sessions() const { return sessions_; }
    ExportReaction* exports() const { return exports_; }
    RenderComparison* comparison() const { return comparison_; }
    MetricReaction* metrics() const { return metrics_; }
    StatusReporter* report() const { return report_; }
    RenderProgressBehavior* progress() const { return progress_; }
    ShadowOutlineOverlay* shadowOutline() const { return outline_; }

    // The first size, centred in the screen's available area: 1400 x 860 where there is room,
    // never more than the area (a 1280 x 720 laptop screen).
    void fitInto(const QRect& available);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void linkEdits();
    void showScene();
    void updateTitle();

    StatusReporter* report_ = nullptr;
    ActiveScene* scene_ = nullptr;
    WorkbenchDocks* docks_ = nullptr;
    RenderController* render_ = nullptr;
    SelectionLink* selection_ = nullptr;
    CameraReaction* camera_ = nullptr;
    SessionReactions* sessions_ = nullptr;
    ExportReaction* exports_ = nullptr;
    RenderComparison* comparison_ = nullptr;
    MetricReaction* metrics_ = nullptr;
    RenderProgressBehavior* progress_ = nullptr;
    PersistentLayoutBehavior* layout_ = nullptr;
    ShadowOutlineOverlay* outline_ = nullptr;
};

}  // namespace lc::gui
