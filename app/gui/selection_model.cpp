// SPDX-License-Identifier: BSD-3-Clause
#include "selection_model.hpp"

namespace lc::gui {

void SelectionModel::selectRay(const SelectedRay& ray) {
    ray_ = ray;
    emit raySelected(ray);
}

void SelectionModel::clearRay() {
    ray_.reset();
    emit rayCleared();
}

void SelectionModel::selectObject(int object) {
    if (object == object_) return;
    object_ = object;
    emit objectSelected(object);
}

}  // namespace lc::gui
