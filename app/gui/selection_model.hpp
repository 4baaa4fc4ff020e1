// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What is selected, shared by the linked views (egocentric image, r-phi diagram, spacetime view,
// images table): one light ray and one object. A view that selects something tells this model;
// the main window answers its signals by showing the selection in every view, so no view knows
// another. A ray is a direction at the observer, so each view draws it in its own way: the image
// marks its pixel, the diagram its closed-form path, the 3D view the null geodesic source's ray.
#include "core/numerics/types.hpp"

#include <QObject>

#include <optional>
#include <string>

namespace lc::gui {

struct SelectedRay {
    lc::Vec3 direction = lc::Vec3::UnitX();  // unit, the observer's static frame (the camera's, observer at rest)
    double affine = 0;                       // where it ends: the emission event on an object; 0: on none
    int i = -1, j = -1;                      // the pixel it lands on; (-1, -1) outside the image
    std::string label;                       // the diagram's legend entry
};

class SelectionModel : public QObject {
    Q_OBJECT
public:
    explicit SelectionModel(QObject* parent = nullptr) : QObject(parent) {}

    void selectRay(const SelectedRay& ray);
    void clearRay();
    // An index into the scene's objects (spheres, then meshes, as lc::PixelRecord::object); -1: none.
    // Emits objectSelected only when the object changes.
    void selectObject(int object);

    const std::optional<SelectedRay>& ray() const { return ray_; }
    int object() const { return object_; }

signals:
    void raySelected(const lc::gui::SelectedRay& ray);
    void rayCleared();
    void objectSelected(int object);

private:
    std::optional<SelectedRay> ray_;
    int object_ = -1;
};

}  // namespace lc::gui
