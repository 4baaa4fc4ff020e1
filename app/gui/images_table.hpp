// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The images table: every image of the selected sphere's centre (Goedel, static observer): at
// rest from the inverse problem in closed form (lc::godel::ObserverView::images), moving from
// its world line (lc::imagesOfMovingCentre, as its photo-objects):
// winding, branch, direction, emission time, frequency ratio, affine depth and the pixel the
// image falls on in the current camera.
#include "selection_model.hpp"

#include "core/godel/images.hpp"
#include "core/scene/scene.hpp"

#include <QTableWidget>

#include <optional>
#include <utility>
#include <vector>

namespace lc::gui {

class ImagesTable : public QTableWidget {
    Q_OBJECT
public:
    explicit ImagesTable(QWidget* parent = nullptr);

    // Lists the images of `object` (an index into scene.spheres); an empty table where the
    // scene or object has none to list. title() says which.
    void showImagesOf(const lc::Scene& scene, int object);
    QString title() const { return title_; }
    // The height that shows the header and `rows` rows whole (the dock's default height).
    int heightForRows(int rows) const;

    // The pixel of a row's image, (-1, -1) when it falls outside the view.
    std::pair<int, int> pixelOfRow(int row) const;
    // The row's light path in the observer's chart (closed form), for the r-phi diagram.
    std::vector<lc::Vec4> lightPathOfRow(int row, int samples = 400) const;
    std::string labelOfRow(int row) const;
    // The row whose image lies nearest (in angle) to a viewing direction in the camera's frame: the
    // image a pick on an object's pixel belongs to; -1 for an empty table.
    int rowSeenAlong(const lc::Vec3& direction) const;
    // The row's age cell (the body's proper time at emission; "-" where its motion has none).
    QString ageOfRow(int row) const;
    // The row's image as a selection: its direction in the camera's frame, affine depth and pixel.
    std::optional<SelectedRay> rayOfRow(int row) const;

private:
    std::vector<lc::godel::Image> images_;
    std::vector<std::pair<int, int>> pixels_;
    std::vector<lc::Vec3> directions_;
    double a_ = 1;
    QString title_;
};

}  // namespace lc::gui
