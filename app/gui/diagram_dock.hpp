// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A dock for one diagram of the scene (r-phi or t-r): the live DiagramWidget for Goedel scenes,
// and in its place, for every other scene, the sentence why there is none (the view explains
// itself instead of staying blank). The legend is off until its check box asks for it, so the
// plot fills a narrow dock; on, it is a list beside the plot (a splitter between them), which
// scrolls rather than taking the plot's room.
#include "diagram_widget.hpp"

#include <QDockWidget>

class QCheckBox;
class QLabel;
class QListWidget;
class QStackedWidget;

namespace lc::gui {

class DiagramDock : public QDockWidget {
    Q_OBJECT
public:
    DiagramDock(DiagramWidget::Kind kind, QWidget* parent = nullptr);

    // Draws the scene's diagram, or says why it has none (returns false then).
    bool setScene(const lc::Scene& scene);
    DiagramWidget* diagram() const { return diagram_; }
    QCheckBox* legendToggle() const { return legend_; }
    QListWidget* legendList() const { return legendList_; }
    // Why the dock shows no diagram (empty while it shows one).
    QString note() const;

private:
    QString title_;
    DiagramWidget* diagram_ = nullptr;
    QLabel* note_ = nullptr;
    QCheckBox* legend_ = nullptr;
    QListWidget* legendList_ = nullptr;
    void fillLegend();
    QStackedWidget* stack_ = nullptr;
};

}  // namespace lc::gui
