#include "lightconeRPhiDiagramWidget.h"

#include "vtkLightconeRPhiDiagram.h"

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
}

RPhiDiagramWidget::~RPhiDiagramWidget() = default;

void RPhiDiagramWidget::setScene(const lc::Scene& scene, int windings) {
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
    view_->GetScene()->ClearItems();
    chart_ = nullptr;
    highlight_ = nullptr;
    renderWindow()->Render();
    update();
}

int RPhiDiagramWidget::numberOfImagePaths() const { return diagram_->GetNumberOfImagePaths(); }

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
    if (chart_ && highlight_) {
        chart_->RemovePlotInstance(highlight_);
        highlight_ = nullptr;
        renderWindow()->Render();
        update();
    }
}

}  // namespace lcgui
