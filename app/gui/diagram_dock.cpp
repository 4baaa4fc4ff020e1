// SPDX-License-Identifier: BSD-3-Clause
#include "diagram_dock.hpp"

#include <QCheckBox>
#include <QIcon>
#include <QLabel>
#include <QListWidget>
#include <QPixmap>
#include <QSplitter>
#include <QVBoxLayout>
#include <QStackedWidget>

#include <algorithm>

namespace lc::gui {

DiagramDock::DiagramDock(DiagramWidget::Kind kind, QWidget* parent)
    : QDockWidget(parent), title_(kind == DiagramWidget::RPhi ? "r-phi diagram" : "t-r diagram") {
    setWindowTitle(title_);
    setObjectName(kind == DiagramWidget::RPhi ? "diagramDock" : "trDiagramDock");
    diagram_ = new DiagramWidget(kind, this);
    diagram_->setObjectName(kind == DiagramWidget::RPhi ? "rphiDiagram" : "trDiagram");
    diagram_->setMinimumSize(240, 140);
    note_ = new QLabel(this);
    note_->setObjectName(kind == DiagramWidget::RPhi ? "diagramNote" : "trDiagramNote");
    note_->setWordWrap(true);
    note_->setAlignment(Qt::AlignCenter);
    note_->setMargin(12);
    // The legend on demand: a narrow dock gives the plot all its room.
    auto* chartPage = new QWidget(this);
    auto* layout = new QVBoxLayout(chartPage);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    legend_ = new QCheckBox("legend", chartPage);
    legend_->setObjectName("legendToggle");
    legend_->setToolTip("show the legend beside the plot (the exported diagrams always have it)");
    legendList_ = new QListWidget(chartPage);
    legendList_->setObjectName("legendList");
    legendList_->setVisible(false);
    legendList_->setWordWrap(true);
    legendList_->setSelectionMode(QAbstractItemView::NoSelection);
    auto* split = new QSplitter(Qt::Horizontal, chartPage);
    split->addWidget(diagram_);
    split->addWidget(legendList_);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    split->setChildrenCollapsible(false);
    connect(legend_, &QCheckBox::toggled, this, [this](bool on) {
        legendList_->setVisible(on);
        fillLegend();
    });
    connect(diagram_, &DiagramWidget::plotsChanged, this, &DiagramDock::fillLegend);
    layout->addWidget(legend_);
    layout->addWidget(split, 1);
    stack_ = new QStackedWidget(this);
    stack_->addWidget(chartPage);
    stack_->addWidget(note_);
    setWidget(stack_);
}

bool DiagramDock::setScene(const lc::Scene& scene) {
    QString why;
    if (scene.spacetime->godelRadius()) {
        try {
            diagram_->setScene(scene, std::min(scene.settings.windings, 50));
        } catch (const std::exception& e) {
            why = "No " + title_ + ": " + e.what();
        }
    } else {
        why = QString(diagram_->kind() == DiagramWidget::RPhi
                          ? "The r-phi diagram draws the Goedel universe's light rays in closed form, in the "
                            "observer's plane z = 0, with the horizon r = 2a."
                          : "The t-r diagram draws the Goedel observer's past light cone in closed form, the "
                            "horizon r = 2a and the band of closed timelike curves beyond it.") +
              QString(
                  " This scene's metric ('%1') has none: its null geodesics are in the spacetime view (3D), "
                  "each picked ray's deflection in the Accuracy dock.")
                  .arg(QString::fromStdString(scene.spacetime->name()));
    }
    if (!why.isEmpty()) diagram_->clear();
    note_->setText(why);
    stack_->setCurrentIndex(why.isEmpty() ? 0 : 1);
    setWindowTitle(why.isEmpty() ? title_ : title_ + " (Goedel only)");  // tabbed: short
    return why.isEmpty();
}

void DiagramDock::fillLegend() {
    if (!legend_->isChecked()) return;
    legendList_->clear();
    for (const DiagramWidget::LegendEntry& e : diagram_->legendEntries()) {
        QPixmap swatch(14, 14);
        swatch.fill(e.colour);
        legendList_->addItem(new QListWidgetItem(QIcon(swatch), e.label));
    }
}

QString DiagramDock::note() const { return stack_->currentIndex() == 1 ? note_->text() : QString(); }

}  // namespace lc::gui
