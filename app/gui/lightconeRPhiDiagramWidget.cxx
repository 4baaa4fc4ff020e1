#include "lightconeRPhiDiagramWidget.h"

#include "lightconeInteractorClicks.h"

#include "vtkLightconeRPhiDiagram.h"

#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>

#include <stdexcept>

namespace lcgui {

RPhiDiagramWidget::RPhiDiagramWidget(QWidget* parent)
    : QVTKOpenGLNativeWidget(parent), diagram_(vtkSmartPointer<vtkLightconeRPhiDiagram>::New()) {
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

RPhiDiagramWidget::~RPhiDiagramWidget() = default;

void RPhiDiagramWidget::setScene(const lc::Scene& scene, int windings) {
    highlightPath_.clear();
    diagram_->SetScene(scene);
    diagram_->SetWindings(windings);
    hasScene_ = true;
    rebuild();
}

void RPhiDiagramWidget::setWindings(int windings) {
    diagram_->SetWindings(windings);
    if (hasScene_) rebuild();
}

void RPhiDiagramWidget::clear() {
    hasScene_ = false;
    highlightPath_.clear();
    view_->GetScene()->ClearItems();
    chart_ = nullptr;
    highlight_ = nullptr;
    renderWindow()->Render();
    update();
}

int RPhiDiagramWidget::numberOfImagePaths() const { return diagram_->GetNumberOfImagePaths(); }
int RPhiDiagramWidget::numberOfHighlightedImagePaths() const { return diagram_->GetNumberOfHighlightedImagePaths(); }

void RPhiDiagramWidget::setHighlightedObject(int object) {
    if (object == diagram_->GetHighlightedObject()) return;
    diagram_->SetHighlightedObject(object);
    if (!hasScene_) return;
    const std::vector<lc::Vec4> path = highlightPath_;
    rebuild();
    if (!path.empty()) highlightPath(path, highlightLabel_);
}

bool RPhiDiagramWidget::dataPointAt(int px, int py, double& x, double& y) const {
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

void RPhiDiagramWidget::rebuild() {
    diagram_->Build();
    // The diagram draws into its own (never shown) context view: take its chart over.
    vtkContextScene* source = diagram_->GetView()->GetScene();
    vtkSmartPointer<vtkChartXY> chart =
        source->GetNumberOfItems() > 0 ? vtkChartXY::SafeDownCast(source->GetItem(0)) : nullptr;
    if (!chart) throw std::logic_error("vtkLightconeRPhiDiagram built no vtkChartXY");
    source->RemoveItem(chart.Get());
    view_->GetScene()->ClearItems();
    view_->GetScene()->AddItem(chart);
    chart_ = chart;
    highlight_ = nullptr;
    renderWindow()->Render();
    update();
}

void RPhiDiagramWidget::highlightPath(const std::vector<lc::Vec4>& path, const std::string& label) {
    if (!chart_) return;
    clearHighlight();
    vtkNew<vtkTable> table;
    const char* names[4] = {"x", "y", "z", "t"};
    const int component[4] = {1, 2, 3, 0};
    for (int c = 0; c < 4; ++c) {
        vtkNew<vtkDoubleArray> column;
        column->SetName(names[c]);
        column->SetNumberOfValues(static_cast<vtkIdType>(path.size()));
        for (std::size_t k = 0; k < path.size(); ++k)
            column->SetValue(static_cast<vtkIdType>(k), path[k](component[c]));
        table->AddColumn(column);
    }
    highlightPath_ = path;
    highlightLabel_ = label;
    vtkPlot* plot = chart_->AddPlot(vtkChart::LINE);
    plot->SetInputData(table, 0, 1);
    plot->SetColor(0.85, 0.0, 0.55);
    plot->SetWidth(6.0f);
    plot->GetPen()->SetLineType(vtkPen::SOLID_LINE);
    plot->SetLabel(label);
    plot->SetLegendVisibility(true);
    highlight_ = plot;
    renderWindow()->Render();
    update();
}

void RPhiDiagramWidget::clearHighlight() {
    highlightPath_.clear();
    if (chart_ && highlight_) {
        chart_->RemovePlotInstance(highlight_);
        highlight_ = nullptr;
        renderWindow()->Render();
        update();
    }
}

}  // namespace lcgui
