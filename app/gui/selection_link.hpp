// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The linked views' behaviour (ParaView's selection linking): a pick in the image, the r-phi
// diagram, the 3D view or the images table selects a ray or an object in the one SelectionModel,
// and each selection is drawn in every view. A pick made before the per-pixel data exists is
// answered when it does, and starts the trace when none runs (no state waits for nothing).
#include "selection_model.hpp"

#include <QObject>

#include <utility>

namespace lc::gui {

class ActiveScene;
class RenderController;
class StatusReporter;
class WorkbenchDocks;

class SelectionLink : public QObject {
    Q_OBJECT
public:
    SelectionLink(ActiveScene* scene, RenderController* render, WorkbenchDocks* docks, StatusReporter* report,
                  QObject* parent);

    SelectionModel* selectionModel() { return &selection_; }
    int selectedObject() const { return selection_.object(); }
    int pickedI() const { return picked_.first; }
    int pickedJ() const { return picked_.second; }
    // The pixel a pick waits for (the data is being traced); (-1, -1): none.
    std::pair<int, int> pendingPick() const { return pending_; }
    // The pixel marked for the selected ray ((-1, -1): none).
    std::pair<int, int> markedPixel() const { return marked_; }
    // What a session restores: the object of the images table and a pick answered once traced.
    void restore(int selectedObject, int pickI, int pickJ);

public slots:
    void pickPixel(int i, int j);
    // The fan ray (plane z = 0) passing closest to the r-phi diagram's point (x, y), selected.
    void pickDiagramPoint(double x, double y);
    void selectImageRow(int row);

private:
    void sceneReplaced();
    void sceneChanged();
    void renderFinished();
    void showRay(const SelectedRay& ray);
    void clearRay();
    void showObject(int object);
    void fillImagesTable();

    ActiveScene* scene_;
    RenderController* render_;
    WorkbenchDocks* docks_;
    StatusReporter* report_;
    SelectionModel selection_;
    std::pair<int, int> picked_{-1, -1}, pending_{-1, -1}, marked_{-1, -1};
};

}  // namespace lc::gui
