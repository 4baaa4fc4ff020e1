// SPDX-License-Identifier: BSD-3-Clause
#include "main_window.hpp"

#include "render_comparison.hpp"

#include "active_scene.hpp"
#include "camera_reaction.hpp"
#include "export_reaction.hpp"
#include "metric_reaction.hpp"
#include "persistent_layout_behavior.hpp"
#include "properties_panel.hpp"
#include "render_controller.hpp"
#include "shadow_outline_overlay.hpp"
#include "render_progress_behavior.hpp"
#include "selection_link.hpp"
#include "session_reactions.hpp"
#include "status_reporter.hpp"
#include "workbench_docks.hpp"
#include "workbench_menus.hpp"

#include <QCloseEvent>
#include <QFileInfo>
#include <QStatusBar>
#include <QVBoxLayout>

#include <algorithm>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace lc::gui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName("main_window");
    report_ = new StatusReporter(statusBar(), this);
    scene_ = new ActiveScene(this);
    docks_ = new WorkbenchDocks(this);
    // The message bar above the image (the central widget).
    auto* central = new QWidget(this);
    auto* column = new QVBoxLayout(central);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    column->addWidget(report_->messageBar());
    column->addWidget(takeCentralWidget(), 1);
    setCentralWidget(central);
    render_ = new RenderController(scene_, docks_, report_, this);
    // The selection resets first on a new or edited scene: the views then show it, and the render starts.
    selection_ = new SelectionLink(scene_, render_, docks_, report_, this);
    connect(scene_, &ActiveScene::changed, this, &MainWindow::showScene);
    camera_ = new CameraReaction(scene_, render_, docks_->imageView(), this);
    sessions_ = new SessionReactions(this, scene_, render_, selection_, docks_, report_);
    exports_ = new ExportReaction(this, scene_, render_, docks_, selection_, report_);
    metrics_ = new MetricReaction(this, scene_, docks_);
    outline_ = new ShadowOutlineOverlay(scene_, render_, docks_->imageView(), report_, this);
    comparison_ = new RenderComparison(render_, docks_->imageView(), report_, this);
    new WorkbenchMenus(this, scene_, docks_, render_, sessions_, exports_, camera_, outline_, comparison_);
    progress_ = new RenderProgressBehavior(render_, statusBar());
    progress_->watchReading(sessions_->reading());
    layout_ = new PersistentLayoutBehavior(this, docks_);
    linkEdits();
    updateTitle();
    report_->status("File > Open scene (Ctrl+O) or Open session");
}

MainWindow::~MainWindow() = default;

void MainWindow::fitInto(const QRect& available) {
    const QSize wanted(std::min(1400, available.width()), std::min(860, available.height()));
    resize(wanted);
    move(available.x() + (available.width() - width()) / 2, available.y() + (available.height() - height()) / 2);
}

// The properties dock proposes edits; the active scene applies them or says why not.
void MainWindow::linkEdits() {
    PropertiesPanel* properties = docks_->properties();
    // Queued: an edit rebuilds the tree, which must not happen inside the tree's own signal.
    const auto queued = Qt::QueuedConnection;
    connect(
        properties, &PropertiesPanel::editRequested, scene_,
        [this](const QString& field, const Json::Value& value) {
            if (field == "metric.name" && value.isString())  // a name typed in the tree: the chooser's edit
                scene_->changeMetric(QString::fromStdString(value.asString()));
            else
                scene_->edit({{field.toStdString(), value}}, "edit " + field);
        },
        queued);
    connect(properties, &PropertiesPanel::metricChosen, scene_, &ActiveScene::changeMetric, queued);
    connect(properties, &PropertiesPanel::metricFileChosen, scene_, &ActiveScene::changeMetricToFile, queued);
    connect(properties, &PropertiesPanel::sphereAddRequested, scene_, &ActiveScene::addSphere, queued);
    connect(properties, &PropertiesPanel::lightAddRequested, scene_, &ActiveScene::addLight, queued);
    connect(properties, &PropertiesPanel::duplicateRequested, scene_, &ActiveScene::duplicateElement, queued);
    connect(properties, &PropertiesPanel::removeRequested, scene_, &ActiveScene::removeElement, queued);
    connect(scene_, &ActiveScene::refused, this, [this](const QString& field, const QString& reason) {
        docks_->showRefusal(*scene_, field, reason);
        report_->status("refused: " + field + ": " + reason);
    });
    connect(scene_, &ActiveScene::applyFailed, this,
            [this](const QString& message) { report_->problem("Cannot apply the edit", message); });
    connect(scene_, &ActiveScene::adjusted, this, [this](const QString& what) { report_->information(what); });
    connect(scene_->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(scene_, &ActiveScene::pathsChanged, this, &MainWindow::updateTitle);
}

void MainWindow::showScene() {
    updateTitle();
    const QString why = docks_->showScene(*scene_, selection_->selectedObject());
    if (!why.isEmpty()) report_->status(why);
#ifdef __GLIBC__
    // The previous scene's documents and views are freed by now: return the pages to the system
    // (a 30 MB scene's edits otherwise left the workbench's resident memory growing by GBs).
    malloc_trim(0);
#endif
    render_->start();
}

void MainWindow::updateTitle() {
    QString name = "no scene";
    if (!scene_->sessionPath().isEmpty())
        name = QFileInfo(scene_->sessionPath()).fileName();
    else if (!scene_->sceneFile().isEmpty())
        name = QFileInfo(scene_->sceneFile()).fileName();
    setWindowTitle(name + "[*] - Lightcone");
    setWindowModified(!scene_->undoStack()->isClean());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!sessions_->maybeSave()) {
        event->ignore();
        return;
    }
    render_->cancel();
    layout_->save();
    event->accept();
}

}  // namespace lc::gui
