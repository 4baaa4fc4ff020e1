// SPDX-License-Identifier: BSD-3-Clause
#include "metric_reaction.hpp"

#include "active_scene.hpp"
#include "metric_editor.hpp"
#include "properties_panel.hpp"
#include "workbench_docks.hpp"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>

namespace lc::gui {

MetricReaction::MetricReaction(QWidget* window, ActiveScene* scene, WorkbenchDocks* docks)
    : QObject(window), window_(window), scene_(scene) {
    // Queued: the edit rebuilds the chooser and the editor, not inside their own signals.
    const auto queued = Qt::QueuedConnection;
    connect(docks->properties(), &PropertiesPanel::formulaFileRequested, this, &MetricReaction::chooseFormulaFile,
            queued);
    MetricEditor* editor = docks->metricEditor();
    connect(editor, &MetricEditor::openFileRequested, this, &MetricReaction::chooseFormulaFile, queued);
    connect(
        editor, &MetricEditor::applyRequested, scene_,
        [this](const Json::Value& metric) { scene_->changeMetricToBlock(metric, "metric formula"); }, queued);
    connect(scene_, &ActiveScene::refused, editor, &MetricEditor::showProblem);
}

void MetricReaction::chooseFormulaFile() {
    if (!scene_->hasScene() || dialog_) return;
    const QString folder = QString::fromStdString(scene_->scene().baseDir());
    auto* dialog = new QFileDialog(window_, "Metric written as text (docs/METRICS.md)", folder,
                                   "Metric files (*.json);;All files (*)");
    dialog->setObjectName("metricFileDialog");
    dialog->setOption(QFileDialog::DontUseNativeDialog);
    dialog->setFileMode(QFileDialog::ExistingFile);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QFileDialog::fileSelected, scene_,
            [this](const QString& file) { scene_->changeMetricToFile(file); });
    dialog_ = dialog;
    dialog->open();
}

}  // namespace lc::gui
