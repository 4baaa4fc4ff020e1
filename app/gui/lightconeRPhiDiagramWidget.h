#ifndef lightconeRPhiDiagramWidget_h
#define lightconeRPhiDiagramWidget_h
// The r-phi diagram of vtkLightconeRPhiDiagram shown live: the diagram builds its chart, this
// widget moves the chart into its own vtkContextView drawn by the Qt widget, and can add one
// highlighted light path (a thick curve) on top and emphasise one object's image paths. A left
// click without drag inside the plot area emits pointClicked at the diagram point (data units).
#include "core/scene/scene.hpp"

#include <QVTKOpenGLNativeWidget.h>

#include <vtkChartXY.h>
#include <vtkContextView.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "vtkLightconeRPhiDiagram.h"

#include <vector>

class vtkPlot;
class vtkTable;

namespace lcgui {

class RPhiDiagramWidget : public QVTKOpenGLNativeWidget {
    Q_OBJECT
public:
    explicit RPhiDiagramWidget(QWidget* parent = nullptr);
    ~RPhiDiagramWidget() override;

    // Rebuilds the chart (the highlight is dropped).
    void setScene(const lc::Scene& scene, int windings);
    void setWindings(int windings);
    // No diagram (scenes other than Goedel): an empty view.
    void clear();
    bool hasDiagram() const { return hasScene_; }

    // Events in the observer's chart (t, X, Y, z); drawn as x = X, y = Y, thick. Replaces any
    // earlier highlight. The plot's table keeps the columns x, y, z, t of every sample.
    void highlightPath(const std::vector<lc::Vec4>& path, const std::string& label);
    void clearHighlight();
    // The image paths of sphere `object` emphasised, the others greyed; -1: all alike. Keeps the
    // highlighted light path.
    void setHighlightedObject(int object);

    vtkChartXY* chart() const { return chart_; }
    vtkPlot* highlightPlot() const { return highlight_; }  // null when nothing is highlighted
    int numberOfImagePaths() const;
    int numberOfHighlightedImagePaths() const;

signals:
    void pointClicked(double x, double y);

private:
    void rebuild();
    // Display pixel (VTK's, y up) -> data point, from the chart's axes; false outside the plot area.
    bool dataPointAt(int px, int py, double& x, double& y) const;

    vtkNew<vtkContextView> view_;
    vtkSmartPointer<vtkLightconeRPhiDiagram> diagram_;
    vtkSmartPointer<vtkChartXY> chart_;
    vtkPlot* highlight_ = nullptr;         // owned by chart_
    std::vector<lc::Vec4> highlightPath_;  // what highlight_ draws, redrawn after a rebuild
    std::string highlightLabel_;
    bool hasScene_ = false;
};

}  // namespace lcgui

#endif
