// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The spacetime view (views/spacetime/vtkLightconeSpacetimeView) as a dock of the workbench: a checkbox per
// layer (disabled, with the reason as tooltip, where the scene or chart has no such layer), the
// chart, the Killing combination and the curvature layer's quantity and style (slice, isosurfaces, volume), and the 3D
// view with ParaView's camera interaction (vtkInteractorStyleTrackballCamera). A click without drag picks: a ray emits
// rayPicked, an object's photo-object or world line objectPicked. Hidden, it only remembers that it is stale.
#include "selection_model.hpp"

#include "core/scene/scene.hpp"
#include "vtkLightconeSpacetimeView.h"

#include <QDockWidget>

#include <vtkNew.h>

#include <array>
#include <vector>

class QCheckBox;
class QComboBox;
class QVTKOpenGLNativeWidget;

namespace lc::gui {

class SpacetimeViewDock : public QDockWidget {
    Q_OBJECT
public:
    explicit SpacetimeViewDock(QWidget* parent = nullptr);
    ~SpacetimeViewDock() override;

    void setScene(const lc::Scene& scene);
    void clear();
    // The selection drawn: the ray (traced by the view's own null geodesic source) and the object.
    void showRay(const SelectedRay& ray);
    void clearRay();
    void showObject(int object);

    vtkLightconeSpacetimeView* view() const { return view_; }
    QVTKOpenGLNativeWidget* renderWidget() const { return widget_; }
    QCheckBox* layerToggle(int layer) const { return toggles_.at(static_cast<std::size_t>(layer)); }
    QComboBox* chartChoice() const { return chart_; }
    QComboBox* combinationChoice() const { return combination_; }
    QComboBox* curvatureChoice() const { return curvature_; }
    QComboBox* curvatureStyleChoice() const { return curvatureStyle_; }
    // The view's 3D camera for sessions (vtkLightconeSpacetimeView::GetCameraState), and set back.
    std::vector<double> cameraState() const { return view_->GetCameraState(); }
    void restoreCamera(const std::vector<double>& state);
    // Brings the view up to date and draws it (only while the dock is visible).
    void refresh();

signals:
    // A click on ray `ray` of the fan (-1: the highlighted ray) leaving the observer along `direction`.
    void rayPicked(const lc::Vec3& direction, int ray);
    void objectPicked(int object);

private:
    void updateToggles();

    vtkNew<vtkLightconeSpacetimeView> view_;
    QVTKOpenGLNativeWidget* widget_ = nullptr;
    std::array<QCheckBox*, vtkLightconeSpacetimeView::NUMBER_OF_LAYERS> toggles_{};
    QComboBox* chart_ = nullptr;
    QComboBox* combination_ = nullptr;
    QComboBox* curvature_ = nullptr;
    QComboBox* curvatureStyle_ = nullptr;
    bool stale_ = false;
};

}  // namespace lc::gui
