// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The camera as the user moves it (ParaView's camera reactions): a drag in the image looks
// around, the wheel zooms, View > Panorama projection and View > Reset view (Ctrl+R). Each is one
// undoable edit of the active scene (camera_edits); Ctrl+R with the file's view already
// traces what a cancel left untraced.
#include <QObject>

class QAction;

namespace lc::gui {

class ActiveScene;
class EgocentricImageWidget;
class RenderController;

class CameraReaction : public QObject {
    Q_OBJECT
public:
    CameraReaction(ActiveScene* scene, RenderController* render, EgocentricImageWidget* image, QObject* parent);
    // View > Panorama projection: kept checked as the scene is.
    void setPanoramaAction(QAction* action);

public slots:
    // Turns the camera by a drag of (dx, dy) image pixels: the view follows the hand.
    void lookAround(double dx, double dy);
    void zoom(int steps);  // wheel: +1 narrows the field of view by 10 %
    void resetView();      // the scene file's camera direction, field of view and projection
    void setPanorama(bool panorama);

private:
    ActiveScene* scene_;
    RenderController* render_;
    EgocentricImageWidget* image_;
    QAction* panorama_ = nullptr;
};

}  // namespace lc::gui
