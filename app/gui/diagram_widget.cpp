// SPDX-License-Identifier: BSD-3-Clause
#include "diagram_widget.hpp"

#include "interactor_clicks.hpp"

#include "vtkLightconeRPhiDiagram.h"
#include "vtkLightconeTRDiagram.h"

#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>

#include <cmath>
#include <stdexcept>

namespace lc::gui {

DiagramWidget::DiagramWidget(Kind kind, QWidget* parent) : QVTKOpenGLNativeWidget(parent), kind_(kind) {
    if (kind == RPhi)
        diagram_ = vtkSmartPointer<vtkLightconeRPhiDiagram>::New();
    else
        diagram_ = vtkSmartPointer<vtkLightconeTRDiagram>::New();
    vtkNew<vtkGenericOpenGLRenderWindow> window;
    setRenderWindow(window);
    view_->SetRenderWindow(window);
    view_->SetInteractor(interactor());
    view_->GetRenderer()->SetBackground(1, 1, 1);
    observeClicks(interactor(), [this](int px, int py) {  // a drag pans the chart instead
        double x = 0, y = 0;
        if (dataPointAt(px, py, x, y)) emit pointClicked(x, y);
    });
}

DiagramWidget::~DiagramWidget() = default;

void DiagramWidget::setScene(const lc::Scene& scene, int windings) {
    highlightPath_.clear();
    diagram_->SetScene(scene);
    observerTime_ = scene.observer(0);
    diagram_->SetWindings(windings);
    hasScene_ = true;
    rebuild();
}

void DiagramWidget::setWindings(int windings) {
    diagram_->SetWindings(windings);
    if (hasScene_) rebuild();
}

void DiagramWidget::clear() {
    hasScene_ = false;
    highlightPath_.clear();
    view_->GetScene()->ClearItems();
    chart_ = nullptr;
    highlight_ = emission_ = nullptr;
    renderWindow()->Render();
    update();
}

void DiagramWidget::setLegendVisible(bool visible) {
    legendVisible_ = visible;
    if (!chart_) return;
    chart_->SetShowLegend(visible);
    renderWindow()->Render();
    keepEqualScales();  // the legend takes room from the plot
    update();
}

std::vector<DiagramWidget::LegendEntry> DiagramWidget::legendEntries() const {
    std::vector<LegendEntry> entries;
    if (!chart_) return entries;
    for (vtkIdType k = 0; k < chart_->GetNumberOfPlots(); ++k) {
        vtkPlot* plot = chart_->GetPlot(k);
        if (!plot->GetLegendVisibility() || plot->GetLabel().empty()) continue;
        unsigned char rgb[3];
        plot->GetColor(rgb);
        entries.push_back({QString::fromStdString(plot->GetLabel()), QColor(rgb[0], rgb[1], rgb[2])});
    }
    return entries;
}

int DiagramWidget::numberOfImagePaths() const { return diagram_->GetNumberOfImagePaths(); }
int DiagramWidget::numberOfObjectsSummarised() const { return diagram_->GetNumberOfObjectsSummarised(); }
int DiagramWidget::numberOfHighlightedImagePaths() const { return diagram_->GetNumberOfHighlightedImagePaths(); }

void DiagramWidget::setHighlightedObject(int object) {
    if (object == diagram_->GetHighlightedObject()) return;
    diagram_->SetHighlightedObject(object);
    if (!hasScene_) return;
    const std::vector<lc::Vec4> path = highlightPath_;
    rebuild();
    if (!path.empty()) highlightPath(path, highlightLabel_);
}

bool DiagramWidget::dataPointAt(int px, int py, double& x, double& y) const {
    if (!chart_) return false;
    // Each axis spans its data range between its two end points (scene pixels).
    auto along = [](vtkAxis* axis, int c, int p, double& value) {
        const float p1 = axis->GetPoint1()[c], p2 = axis->GetPoint2()[c];
        if (p2 == p1) return false;
        const double f = (p - p1) / (p2 - p1);
        value = axis->GetMinimum() + f * (axis->GetMaximum() - axis->GetMinimum());
        return f >= 0 && f <= 1;
    };
    const bool inX = along(chart_->GetAxis(vtkAxis::BOTTOM), 0, px, x);
    return along(chart_->GetAxis(vtkAxis::LEFT), 1, py, y) && inX;
}

void DiagramWidget::rebuild() {
    diagram_->Build();
    // The diagram draws into its own (never shown) context view: take its chart over.
    vtkContextScene* source = diagram_->GetView()->GetScene();
    vtkSmartPointer<vtkChartXY> chart =
        source->GetNumberOfItems() > 0 ? vtkChartXY::SafeDownCast(source->GetItem(0)) : nullptr;
    if (!chart) throw std::logic_error("the diagram built no vtkChartXY");
    source->RemoveItem(chart.Get());
    view_->GetScene()->ClearItems();
    view_->GetScene()->AddItem(chart);
    chart_ = chart;
    chart_->SetShowLegend(legendVisible_);
    highlight_ = emission_ = nullptr;
    vtkAxis* x = chart_->GetAxis(vtkAxis::BOTTOM);
    vtkAxis* y = chart_->GetAxis(vtkAxis::LEFT);
    baseRange_[0] = x->GetMinimum();
    baseRange_[1] = x->GetMaximum();
    baseRange_[2] = y->GetMinimum();
    baseRange_[3] = y->GetMaximum();
    renderWindow()->Render();
    keepEqualScales();
    update();
    emit plotsChanged();
}

void DiagramWidget::keepEqualScales() {
    if (kind_ != RPhi || !chart_) return;
    vtkAxis* x = chart_->GetAxis(vtkAxis::BOTTOM);
    vtkAxis* y = chart_->GetAxis(vtkAxis::LEFT);
    // Twice: new tick labels may move the plot area's edges a little.
    for (int pass = 0; pass < 2; ++pass) {
        const double across = x->GetPoint2()[0] - x->GetPoint1()[0], up = y->GetPoint2()[1] - y->GetPoint1()[1];
        if (!(across > 0 && up > 0)) return;
        const double cx = 0.5 * (baseRange_[0] + baseRange_[1]), cy = 0.5 * (baseRange_[2] + baseRange_[3]);
        const double perPixel =
            std::max((baseRange_[1] - baseRange_[0]) / across, (baseRange_[3] - baseRange_[2]) / up);
        x->SetBehavior(vtkAxis::FIXED);
        y->SetBehavior(vtkAxis::FIXED);
        x->SetRange(cx - 0.5 * perPixel * across, cx + 0.5 * perPixel * across);
        y->SetRange(cy - 0.5 * perPixel * up, cy + 0.5 * perPixel * up);
        chart_->RecalculateBounds();
        renderWindow()->Render();
    }
}

void DiagramWidget::resizeEvent(QResizeEvent* event) {
    QVTKOpenGLNativeWidget::resizeEvent(event);
    if (chart_) {
        renderWindow()->Render();  // the axes take the new size
        keepEqualScales();
    }
}

void DiagramWidget::plotPoint(const lc::Vec4& event, double& x, double& y) const {
    if (kind_ == RPhi) {
        x = event(1);
        y = event(2);
    } else {
        x = std::hypot(event(1), event(2));
        y = event(0) + observerTime_;
    }
}

void DiagramWidget::highlightPath(const std::vector<lc::Vec4>& path, const std::string& label) {
    if (!chart_ || path.empty()) return;
    clearHighlight();
    vtkNew<vtkTable> table;
    const char* names[6] = {"x", "y", "z", "t", "plot_x", "plot_y"};
    const int component[4] = {1, 2, 3, 0};
    for (int c = 0; c < 6; ++c) {
        vtkNew<vtkDoubleArray> column;
        column->SetName(names[c]);
        column->SetNumberOfValues(static_cast<vtkIdType>(path.size()));
        for (std::size_t k = 0; k < path.size(); ++k) {
            double x = 0, y = 0;
            plotPoint(path[k], x, y);
            column->SetValue(static_cast<vtkIdType>(k), c < 4 ? path[k](component[c]) : c == 4 ? x : y);
        }
        table->AddColumn(column);
    }
    highlightPath_ = path;
    highlightLabel_ = label;
    vtkPlot* plot = chart_->AddPlot(vtkChart::LINE);
    plot->SetInputData(table, 4, 5);
    plot->SetColor(0.85, 0.0, 0.55);
    plot->SetWidth(6.0f);
    plot->GetPen()->SetLineType(vtkPen::SOLID_LINE);
    plot->SetLabel(label);
    plot->SetLegendVisibility(true);
    highlight_ = plot;
    // Its emission event: where the light left the object.
    vtkNew<vtkTable> end;
    for (int c = 4; c < 6; ++c) {
        vtkNew<vtkDoubleArray> column;
        column->SetName(names[c]);
        column->InsertNextValue(table->GetValue(table->GetNumberOfRows() - 1, c).ToDouble());
        end->AddColumn(column);
    }
    auto* marker = vtkPlotPoints::SafeDownCast(chart_->AddPlot(vtkChart::POINTS));
    marker->SetInputData(end, 0, 1);
    marker->SetColor(0.85, 0.0, 0.55);
    marker->SetMarkerStyle(vtkPlotPoints::DIAMOND);
    marker->SetMarkerSize(14.0f);
    marker->SetLabel("its emission event");
    emission_ = marker;
    renderWindow()->Render();
    update();
    emit plotsChanged();
}

void DiagramWidget::clearHighlight() {
    highlightPath_.clear();
    if (chart_ && highlight_) {
        chart_->RemovePlotInstance(highlight_);
        chart_->RemovePlotInstance(emission_);
        highlight_ = emission_ = nullptr;
        renderWindow()->Render();
        update();
        emit plotsChanged();
    }
}

}  // namespace lc::gui
