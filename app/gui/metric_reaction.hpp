// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Where the workbench takes a metric written as text: the metric chooser's "formula file..." and
// the metric editor's Open button ask for a metric file (a non-native, window-modal dialog that
// does not block, beside the scene), which becomes the scene's metric in one undoable edit; the
// editor's Apply makes its text the scene's metric; the reader's refusal is shown in the editor.
#include <QFileDialog>
#include <QObject>
#include <QPointer>

class QWidget;

namespace lc::gui {

class ActiveScene;
class WorkbenchDocks;

class MetricReaction : public QObject {
    Q_OBJECT
public:
    MetricReaction(QWidget* window, ActiveScene* scene, WorkbenchDocks* docks);

    void chooseFormulaFile();
    // The dialog while it is open (tests choose a file in it as a user does); null otherwise.
    QFileDialog* fileDialog() const { return dialog_; }

private:
    QWidget* window_;
    ActiveScene* scene_;
    QPointer<QFileDialog> dialog_;
};

}  // namespace lc::gui
