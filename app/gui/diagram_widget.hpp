// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A diagram of a Goedel scene shown live: the r-phi diagram (vtkLightconeRPhiDiagram) or the
// t-r spacetime diagram (vtkLightconeTRDiagram). The diagram builds its chart, this widget moves
// the chart into its own vtkContextView drawn by the Qt widget, and can add one highlighted
// light path (a thick curve, its emission event marked) on top and emphasise one object's image
// paths. A left click without drag inside the plot area emits pointClicked at the diagram point
// (data units).
#include "core/scene/scene.hpp"

#include <QColor>
#include <QString>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkChartXY.h>
#include <vtkContextView.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "vtkLightconeGodelDiagram.h"

#include <vector>

class vtkPlot;
class vtkTable;

namespace lc::gui {

class DiagramWidget : public QVTKOpenGLNativeWidget {
    Q_OBJECT
public:
    enum Kind { RPhi, TR };
    explicit DiagramWidget(Kind kind, QWidget* parent = nullptr);
    Kind kind() const { return kind_; }
    ~DiagramWidget() override;

    // Rebuilds the chart (the highlight is dropped).
    void setScene(const lc::Scene& scene, int windings);
    void setWindings(int windings);
    // No diagram (scenes other than Goedel): an empty view.
    void clear();
    bool hasDiagram() const { return hasScene_; }

    // Events in the observer's chart (t, X, Y, z); drawn thick as the diagram draws events
    // (r-phi: x = X, y = Y; t-r: r = sqrt(X^2 + Y^2) across, the scene's t up), the last one
    // marked as the emission event. Replaces any earlier highlight. The plot's table keeps the
    // columns x, y, z, t of every sample.
    void highlightPath(const std::vector<lc::Vec4>& path, const std::string& label);
    void clearHighlight();
    // The image paths of sphere `object` emphasised, the others greyed; -1: all alike. Keeps the
    // highlighted light path.
    void setHighlightedObject(int object);

    // The chart's own legend, inside the widget beside the plot area (off: the plot fills the
    // widget); kept through rebuilds. The dock shows its legend as a list beside the widget.
    void setLegendVisible(bool visible);
    bool legendVisible() const { return legendVisible_; }
    // What the legend lists: each labelled plot's label and colour, in drawing order.
    struct LegendEntry {
        QString label;
        QColor colour;
    };
    std::vector<LegendEntry> legendEntries() const;

    vtkChartXY* chart() const { return chart_; }
    vtkPlot* highlightPlot() const { return highlight_; }  // null when nothing is highlighted
    vtkPlot* emissionPlot() const { return emission_; }    // the highlighted path's last event
    int numberOfImagePaths() const;
    // Objects beyond the diagram's MaxObjectsDrawn, drawn together without light paths.
    int numberOfObjectsSummarised() const;
    int numberOfHighlightedImagePaths() const;

signals:
    void pointClicked(double x, double y);
    void plotsChanged();  // rebuilt, or a path highlighted or cleared

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void rebuild();
    // r-phi: the axes' ranges widened so that a unit is as long across as up (the horizon is a
    // circle), around the ranges the diagram chose.
    void keepEqualScales();
    // Display pixel (VTK's, y up) -> data point, from the chart's axes; false outside the plot area.
    bool dataPointAt(int px, int py, double& x, double& y) const;

    vtkNew<vtkContextView> view_;
    // Where the diagram draws an event of the observer's chart.
    void plotPoint(const lc::Vec4& event, double& x, double& y) const;

    Kind kind_;
    double observerTime_ = 0;  // the t-r diagram's t is the scene's
    vtkSmartPointer<vtkLightconeGodelDiagram> diagram_;
    vtkSmartPointer<vtkChartXY> chart_;
    vtkPlot* highlight_ = nullptr;         // owned by chart_
    vtkPlot* emission_ = nullptr;          // owned by chart_
    std::vector<lc::Vec4> highlightPath_;  // what highlight_ draws, redrawn after a rebuild
    std::string highlightLabel_;
    bool hasScene_ = false;
    bool legendVisible_ = false;
    double baseRange_[4] = {0, 0, 0, 0};  // x0, x1, y0, y1 as the diagram built them
};

}  // namespace lc::gui
