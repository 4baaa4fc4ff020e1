// SPDX-License-Identifier: BSD-3-Clause
#include "selection_link.hpp"

#include "accuracy_panel.hpp"
#include "active_scene.hpp"
#include "diagram_dock.hpp"
#include "egocentric_image_widget.hpp"
#include "images_table.hpp"
#include "light_path.hpp"
#include "render_controller.hpp"
#include "spacetime_view_dock.hpp"
#include "status_reporter.hpp"
#include "workbench_docks.hpp"

#include "core/scene/frame_camera.hpp"

#include <QCursor>
#include <QDockWidget>
#include <QSignalBlocker>
#include <QToolTip>

#include <cstdio>

namespace lc::gui {

SelectionLink::SelectionLink(ActiveScene* scene, RenderController* render, WorkbenchDocks* docks,
                             StatusReporter* report, QObject* parent)
    : QObject(parent), scene_(scene), render_(render), docks_(docks), report_(report) {
    connect(scene_, &ActiveScene::replaced, this, &SelectionLink::sceneReplaced);
    connect(scene_, &ActiveScene::changed, this, &SelectionLink::sceneChanged);
    connect(render_, &RenderController::finished, this, &SelectionLink::renderFinished);
    // Every link between the views goes through the selection model: a view tells it what was
    // selected, and showRay / showObject draw that in every view.
    connect(&selection_, &SelectionModel::raySelected, this, &SelectionLink::showRay);
    connect(&selection_, &SelectionModel::rayCleared, this, &SelectionLink::clearRay);
    connect(&selection_, &SelectionModel::objectSelected, this, &SelectionLink::showObject);
    EgocentricImageWidget* image = docks_->imageView();
    connect(image, &EgocentricImageWidget::pixelPicked, this, &SelectionLink::pickPixel);
    connect(image, &EgocentricImageWidget::pixelHovered, this, [this, image](int i, int j) {
        const lc::ColouredImage* cpu = render_->cpuImage();
        if (!cpu || i >= cpu->records.width || j >= cpu->records.height) return;
        const auto& p = cpu->records.pixels[static_cast<std::size_t>(j) * cpu->records.width + i];
        QToolTip::showText(QCursor::pos(), QString::fromStdString(describePixel(scene_->scene().scene(), p, i, j)),
                           image);
    });
    SpacetimeViewDock* spacetime = docks_->spacetimeView();
    connect(spacetime, &SpacetimeViewDock::rayPicked, this, [this](const lc::Vec3& direction, int ray) {
        if (!scene_->hasScene()) return;
        const auto [i, j] = pixelOfDirection(lc::frameCamera(scene_->scene().scene()), direction);
        selection_.selectRay({direction, 0, i, j,
                              ray < 0 ? "picked in the 3D view" : "picked in the 3D view: ray " + std::to_string(ray)});
        report_->status(i < 0 ? QString("picked ray %1 in the 3D view: outside the image").arg(ray)
                              : QString("picked ray %1 in the 3D view: pixel (%2, %3)").arg(ray).arg(i).arg(j));
    });
    connect(spacetime, &SpacetimeViewDock::objectPicked, &selection_, &SelectionModel::selectObject);
    connect(docks_->diagramView(), &DiagramWidget::pointClicked, this, &SelectionLink::pickDiagramPoint);
    ImagesTable* table = docks_->imagesTable();
    connect(table, &QTableWidget::itemSelectionChanged, this, [this, table] {
        const auto rows = table->selectionModel()->selectedRows();
        selectImageRow(rows.isEmpty() ? -1 : rows.first().row());
    });
}

void SelectionLink::restore(int selectedObject, int pickI, int pickJ) {
    if (selectedObject < static_cast<int>(scene_->scene().scene().spheres.size()))
        selection_.selectObject(selectedObject);
    fillImagesTable();
    pending_ = {pickI, pickJ};  // picked again when the per-pixel data is traced
}

void SelectionLink::sceneReplaced() {
    selection_.clearRay();
    selection_.selectObject(scene_->scene().scene().spheres.empty() ? -1
                                                                    : 0);  // the images table starts with the first
}

void SelectionLink::sceneChanged() {
    const lc::Scene& scene = scene_->scene().scene();
    if (scene.spheres.size() <= static_cast<std::size_t>(std::max(selection_.object(), 0)))
        selection_.selectObject(scene.spheres.empty() ? -1 : 0);
    selection_.clearRay();
    picked_ = pending_ = {-1, -1};  // a pick waiting for the old scene's data is void
    docks_->imageView()->markPixel(-1, -1);
    marked_ = {-1, -1};
    fillImagesTable();
}

void SelectionLink::renderFinished() {
    fillImagesTable();
    if (pending_.first >= 0) {
        const auto [i, j] = pending_;
        pending_ = {-1, -1};
        pickPixel(i, j);
    }
}

void SelectionLink::pickPixel(int i, int j) {
    if (!scene_->hasScene()) return;
    const lc::ColouredImage* cpu = render_->cpuImage();
    if (!cpu) {  // picked while tracing (or after a cancel): answered when the data is there
        pending_ = {i, j};
        if (!render_->rendering()) render_->start();  // no way into a state that waits for nothing
        report_->status("tracing the per-pixel data; the pick follows when it is done");
        return;
    }
    const lc::RenderResult& r = cpu->records;
    if (i < 0 || j < 0 || i >= r.width || j >= r.height) return;
    picked_ = {i, j};
    const lc::Scene& scene = scene_->scene().scene();
    const lc::PixelRecord& p = r.pixels[static_cast<std::size_t>(j) * r.width + i];
    std::string text = describePixel(scene, p, i, j);
    docks_->accuracyPanel()->showPick(scene, p, i, j);
    const bool onObject = p.kind == lc::PixelRecord::Object;
    if (onObject) {
        selection_.selectObject(p.object);  // first: it refills the images table
        // The image the pixel belongs to: its row selected (without re-selecting its ray: the pick's
        // own ray stays), and the body's age in that image said, the time traveller's point.
        ImagesTable* table = docks_->imagesTable();
        if (const int row = table->rowSeenAlong(lc::frameCamera(scene).direction(i, j)); row >= 0) {
            const QSignalBlocker quiet(table);
            table->selectRow(row);
            text += "; its image in row " + std::to_string(row + 1) + " of the images table (" +
                    table->labelOfRow(row).substr(std::string("picked: ").size()) + ")";
            if (const QString age = table->ageOfRow(row); age != "-")
                text += ", age (proper time) at emission " + age.toStdString();
        }
    }
    // The pixel's ray leaves along its camera direction, in the static frame of an observer at rest.
    if (scene.observerVelocity.tail<3>().norm() == 0) {
        const auto at = text.find('\'');
        const std::string name =
            at == std::string::npos ? std::string("object") : text.substr(at, text.find('\'', at + 1) - at + 1);
        selection_.selectRay({lc::frameCamera(scene).direction(i, j), onObject ? p.affine : 0.0, i, j,
                              onObject ? "picked: light path to " + name : "picked: pixel ray"});
    } else {
        selection_.clearRay();
    }
    report_->status(QString::fromStdString(text));
}

void SelectionLink::pickDiagramPoint(double x, double y) {
    if (!scene_->hasScene() || !hasClosedFormLightPaths(scene_->scene().scene())) return;
    const lc::Scene& scene = scene_->scene().scene();
    const PlanarRayHit hit = nearestPlanarRay(scene, x, y);
    const auto [i, j] = pixelOfDirection(lc::frameCamera(scene), hit.direction);
    char label[96];
    std::snprintf(label, sizeof label, "picked in the r-phi diagram: ray at phi = %.1f deg", hit.phi0 * 180 / lc::kPi);
    selection_.selectRay({hit.direction, hit.affine, i, j, label});
    report_->status(QString("%1, affine %2: %3")
                        .arg(label)
                        .arg(hit.affine, 0, 'f', 3)
                        .arg(i < 0 ? QString("outside the image") : QString("pixel (%1, %2)").arg(i).arg(j)));
}

void SelectionLink::selectImageRow(int row) {
    if (const auto ray = docks_->imagesTable()->rayOfRow(row)) selection_.selectRay(*ray);
}

void SelectionLink::showRay(const SelectedRay& ray) {
    const lc::Scene& scene = scene_->scene().scene();
    // The diagram draws light paths that end on an object (closed form, Goedel); the t-r diagram
    // draws the same path against time, ending at its emission event.
    const bool drawn = ray.affine > 0 && hasClosedFormLightPaths(scene) && docks_->diagramView()->hasDiagram();
    const std::vector<lc::Vec4> path =
        drawn ? lightPathAlong(scene, ray.direction, ray.affine) : std::vector<lc::Vec4>{};
    for (DiagramDock* dock : {docks_->rPhiDiagramDock(), docks_->trDiagramDock()})
        if (drawn)
            dock->diagram()->highlightPath(path, ray.label);
        else
            dock->diagram()->clearHighlight();
    docks_->spacetimeView()->showRay(ray);
    marked_ = {ray.i, ray.j};
    docks_->imageView()->markPixel(ray.i, ray.j);
}

void SelectionLink::clearRay() {
    for (DiagramDock* dock : {docks_->rPhiDiagramDock(), docks_->trDiagramDock()}) dock->diagram()->clearHighlight();
    docks_->spacetimeView()->clearRay();
    marked_ = {-1, -1};
    docks_->imageView()->markPixel(-1, -1);
}

void SelectionLink::showObject(int object) {
    fillImagesTable();
    for (DiagramDock* dock : {docks_->rPhiDiagramDock(), docks_->trDiagramDock()})
        dock->diagram()->setHighlightedObject(object);
    docks_->spacetimeView()->showObject(object);
}

void SelectionLink::fillImagesTable() {
    if (!scene_->hasScene()) return;
    docks_->imagesTable()->showImagesOf(scene_->scene().scene(), selection_.object());
    docks_->imagesDock()->setWindowTitle(docks_->imagesTable()->title());
}

}  // namespace lc::gui
