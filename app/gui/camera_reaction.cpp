// SPDX-License-Identifier: BSD-3-Clause
#include "camera_reaction.hpp"

#include "active_scene.hpp"
#include "camera_edits.hpp"
#include "egocentric_image_widget.hpp"
#include "render_controller.hpp"

#include <QAction>

namespace lc::gui {

CameraReaction::CameraReaction(ActiveScene* scene, RenderController* render, EgocentricImageWidget* image,
                               QObject* parent)
    : QObject(parent), scene_(scene), render_(render), image_(image) {
    connect(image_, &EgocentricImageWidget::dragged, this, &CameraReaction::lookAround);
    connect(image_, &EgocentricImageWidget::zoomed, this, &CameraReaction::zoom);
}

void CameraReaction::setPanoramaAction(QAction* action) {
    panorama_ = action;
    connect(panorama_, &QAction::triggered, this, &CameraReaction::setPanorama);
    connect(scene_, &ActiveScene::changed, this, [this] {
        panorama_->setChecked(scene_->scene().scene().camera.projection == lc::Camera::Projection::Panorama);
    });
}

void CameraReaction::lookAround(double dx, double dy) {
    if (!scene_->hasScene() || !scene_->edit(lookAroundEdits(scene_->scene().scene(), dx, dy), "look around"))
        image_->clearDragPreview();
}

void CameraReaction::zoom(int steps) {
    if (scene_->hasScene() && steps != 0)
        scene_->edit({zoomEdit(scene_->scene().scene().camera, steps)}, steps > 0 ? "zoom in" : "zoom out");
}

void CameraReaction::resetView() {
    if (!scene_->hasScene()) return;
    const auto edits = resetViewEdits(scene_->scene());
    if (!edits.empty()) scene_->edit(edits, "reset view");
    // Ctrl+R traces what a cancel left untraced, also when the reset was refused or changed
    // nothing (no edit, no render: the window would wait for data that never comes).
    if (!render_->cpuImage() && !render_->rendering()) render_->start();
}

void CameraReaction::setPanorama(bool panorama) {
    if (!scene_->hasScene()) return;
    const lc::Camera& camera = scene_->scene().scene().camera;
    const bool is = camera.projection == lc::Camera::Projection::Panorama;
    if (is != panorama && !scene_->edit(projectionEdits(camera, panorama), panorama ? "panorama" : "pinhole") &&
        panorama_)
        panorama_->setChecked(is);
}

}  // namespace lc::gui
