// SPDX-License-Identifier: BSD-3-Clause
#include "spacetime_view_dock.hpp"

#include "interactor_clicks.hpp"

#include "core/curvature/curvature_field.hpp"
#include "vtkLightconeOutputChart.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

namespace lc::gui {
namespace {

using View = vtkLightconeSpacetimeView;

// Killing combinations c1 d/dt + c2 d/dphi + c3 d/dz + c4 xi4 + c5 xi5 offered for the glyphs and orbits.
struct Combination {
    const char* name;
    double c[5];
};
const Combination kCombinations[] = {{"d/dphi (rotation)", {0, 1, 0, 0, 0}},
                                     {"d/dt (time)", {1, 0, 0, 0, 0}},
                                     {"d/dt + 0.5 d/dphi", {1, 0.5, 0, 0, 0}},
                                     {"d/dz", {0, 0, 1, 0, 0}},
                                     {"xi4", {0, 0, 0, 1, 0}},
                                     {"xi5", {0, 0, 0, 0, 1}}};

}  // namespace

SpacetimeViewDock::SpacetimeViewDock(QWidget* parent) : QDockWidget("Spacetime view (3D)", parent) {
    setObjectName("spacetimeDock");
    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* toggles = new QGridLayout;
    for (int layer = 0; layer < View::NUMBER_OF_LAYERS; ++layer) {
        auto* box = new QCheckBox(View::GetLayerName(layer), content);
        box->setObjectName(QString("layer_%1").arg(layer));
        box->setChecked(view_->GetLayerVisibility(layer));
        connect(box, &QCheckBox::toggled, this, [this, layer](bool on) {
            view_->SetLayerVisibility(layer, on);
            refresh();
        });
        toggles->addWidget(box, layer / 3, layer % 3);  // three columns: the dock fits a 1280 px window
        toggles_[static_cast<std::size_t>(layer)] = box;
    }
    layout->addLayout(toggles);

    auto* choices = new QGridLayout;  // two rows: the dock fits a 1280 px window
    chart_ = new QComboBox(content);
    chart_->setObjectName("spacetimeChart");
    chart_->addItem("embedding (X, Y, z)", vtkLightconeOutputChart::EMBEDDING);
    chart_->addItem("r, phi, t", vtkLightconeOutputChart::RPHIT);
    chart_->addItem("X, Y, t", vtkLightconeOutputChart::XYT);
    connect(chart_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        view_->SetOutputChart(chart_->itemData(index).toInt());
        updateToggles();
        refresh();
    });
    combination_ = new QComboBox(content);
    combination_->setObjectName("killingCombination");
    for (const Combination& c : kCombinations) combination_->addItem(c.name);
    combination_->setToolTip(
        "the Killing field of the glyphs (coloured by its norm, signed by its causal character) "
        "and of the orbits");
    connect(combination_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        view_->SetKillingCombination(kCombinations[index].c);
        refresh();
    });
    choices->addWidget(new QLabel("chart", content), 0, 0);
    choices->addWidget(chart_, 0, 1);
    choices->addWidget(new QLabel("Killing field", content), 0, 2);
    choices->addWidget(combination_, 0, 3);
    curvature_ = new QComboBox(content);
    curvature_->setObjectName("curvatureQuantity");
    // Long names ("dominant_energy_violation") must not widen the dock and squeeze the image.
    curvature_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    curvature_->setMinimumContentsLength(12);
    for (const auto& q : lc::curvatureQuantities()) {
        curvature_->addItem(q.name);
        curvature_->setItemData(curvature_->count() - 1, q.meaning, Qt::ToolTipRole);
    }
    curvature_->setToolTip(
        "what the curvature layer shows on the observer's plane (docs/CURVATURE.md); matter and tides as the "
        "static observers measure them, the normal ones where there are none");
    connect(curvature_, &QComboBox::currentTextChanged, this, [this](const QString& name) {
        view_->SetCurvatureQuantity(name.toStdString());
        refresh();
    });
    curvatureStyle_ = new QComboBox(content);
    curvatureStyle_->setObjectName("curvatureStyle");
    for (int style = 0; style < View::NUMBER_OF_CURVATURE_STYLES; ++style)
        curvatureStyle_->addItem(View::GetCurvatureStyleName(style), style);
    curvatureStyle_->setToolTip(
        "how the curvature layer draws its quantity: on the observer's plane, or in the cube around it as six "
        "isosurfaces at the colour bar's levels, or by volume rendering (opaque where the quantity is large)");
    connect(curvatureStyle_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        view_->SetCurvatureStyle(curvatureStyle_->itemData(index).toInt());
        refresh();
    });
    choices->addWidget(new QLabel("curvature", content), 1, 0);
    choices->addWidget(curvature_, 1, 1);
    choices->addWidget(curvatureStyle_, 1, 3);
    choices->setColumnStretch(4, 1);
    layout->addLayout(choices);

    widget_ = new QVTKOpenGLNativeWidget(content);
    widget_->setObjectName("spacetimeView");
    widget_->setMinimumSize(240, 100);
    vtkNew<vtkGenericOpenGLRenderWindow> window;
    widget_->setRenderWindow(window);
    window->AddRenderer(view_->GetRenderer());
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    widget_->interactor()->SetInteractorStyle(style);
    observeClicks(widget_->interactor(), [this](int x, int y) {  // a drag turns the camera instead
        const View::PickResult hit = view_->Pick(x, y);
        if (hit.Kind == View::PickResult::RAY) emit rayPicked(hit.Direction, hit.Ray);
        if (hit.Kind == View::PickResult::OBJECT) emit objectPicked(hit.Object);
    });
    layout->addWidget(widget_, 1);
    setWidget(content);
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible && stale_) refresh();
    });
    updateToggles();
}

SpacetimeViewDock::~SpacetimeViewDock() = default;

void SpacetimeViewDock::setScene(const lc::Scene& scene) {
    view_->SetScene(scene);
    updateToggles();
    refresh();
}

void SpacetimeViewDock::restoreCamera(const std::vector<double>& state) {
    view_->SetCameraState(state);
    refresh();
}

void SpacetimeViewDock::clear() {
    view_->ClearScene();
    updateToggles();
    refresh();
}

void SpacetimeViewDock::showRay(const SelectedRay& ray) {
    view_->SetHighlightedRay(ray.direction, ray.affine);
    refresh();
}

void SpacetimeViewDock::clearRay() {
    view_->ClearHighlightedRay();
    refresh();
}

void SpacetimeViewDock::showObject(int object) {
    view_->SetSelectedObject(object);
    refresh();
}

void SpacetimeViewDock::updateToggles() {
    for (int layer = 0; layer < View::NUMBER_OF_LAYERS; ++layer) {
        QCheckBox* box = toggles_[static_cast<std::size_t>(layer)];
        const std::string why = view_->GetLayerUnavailableReason(layer);
        box->setEnabled(why.empty());
        box->setToolTip(why.empty() ? QString("show or hide the %1").arg(View::GetLayerName(layer))
                                    : QString("not available: %1").arg(QString::fromStdString(why)));
    }
}

void SpacetimeViewDock::refresh() {
    if (!isVisible()) {
        stale_ = true;
        return;
    }
    stale_ = false;
    view_->Update();
    widget_->renderWindow()->Render();
    widget_->update();
}

}  // namespace lc::gui
