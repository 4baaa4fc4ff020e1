// SPDX-License-Identifier: BSD-3-Clause
#include "images_table.hpp"

#include "light_path.hpp"

#include "core/render/photo_scene.hpp"
#include "core/scene/frame_camera.hpp"

#include <QHeaderView>
#include <QScrollBar>

namespace lc::gui {

ImagesTable::ImagesTable(QWidget* parent) : QTableWidget(0, 9, parent) {
    setObjectName("imagesTable");
    setHorizontalHeaderLabels({"winding", "branch", "psi (deg)", "phi (deg)", "emission t", "nu_obs/nu_em",
                               "affine depth", "pixel", "age (proper time)"});
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::SingleSelection);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // Rows as tall as their text: a fifth of a 1280 x 800 window shows four images whole, not three.
    verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    verticalHeader()->setMinimumSectionSize(fontMetrics().height() + 4);
}

int ImagesTable::heightForRows(int rows) const {
    return horizontalHeader()->sizeHint().height() + rows * (fontMetrics().height() + 6) + 2 * frameWidth() +
           horizontalScrollBar()->sizeHint().height();
}

void ImagesTable::showImagesOf(const lc::Scene& scene, int object) {
    setRowCount(0);
    images_.clear();
    pixels_.clear();
    directions_.clear();
    const std::optional<double> godel = scene.spacetime->godelRadius();
    const bool listable =
        godel && hasClosedFormLightPaths(scene) && object >= 0 && object < static_cast<int>(scene.spheres.size());
    if (!listable) {
        title_ = !godel ? QString::fromStdString(
                              "Images of the selected object: listed for Goedel scenes (this "
                              "scene's metric is '" +
                              scene.spacetime->name() + "')")
                 : scene.spheres.empty() ? QString("Images of the selected object: the scene has no sphere")
                 : object < 0            ? QString("Images of the selected object: click an object's pixel")
                                         : QString("Images of the selected object (a static observer's)");
        return;
    }
    const lc::SphereObject& s = scene.spheres[static_cast<std::size_t>(object)];
    a_ = *godel;
    std::vector<QString> ages;  // the body's proper time at emission, where its world line has one
    if (s.motion.moving()) {
        // The centre's own world line, as the photo-objects solve it: emission time and frequency
        // ratio differ from image to image.
        title_ = QString::fromStdString("Images of '" + s.name + "' (its centre, on its world line)");
        const bool byProperTime =
            s.motion.kind == lc::Motion::Kind::ProperTime || s.motion.kind == lc::Motion::Kind::FreeFall;
        for (const auto& mi : lc::imagesOfMovingCentre(scene, s, scene.settings.windings)) {
            images_.push_back(mi.image);
            ages.push_back(byProperTime ? QString::number(mi.tau, 'f', 4) : QString("-"));
        }
    } else {
        const lc::godel::ImageSet set =
            lc::godel::ObserverView(a_, scene.observer).images(s.centre.tail<3>(), scene.settings.windings);
        images_ = set.images;
        title_ = QString::fromStdString("Images of '" + s.name + "' (its centre)" +
                                        (set.status == lc::godel::ImageStatus::BeyondHorizon
                                             ? ": none, it lies beyond the observer's Goedel horizon (r >= 2a)"
                                         : images_.empty()
                                             ? ": none up to winding " + std::to_string(scene.settings.windings)
                                             : ""));
    }
    const auto axes = cameraAxes(scene);
    setRowCount(static_cast<int>(images_.size()));
    for (std::size_t n = 0; n < images_.size(); ++n) {
        const lc::godel::Image& im = images_[n];
        // The image's direction in the camera's frame, and the pixel it falls on.
        const lc::Vec3 d(im.direction.dot(axes[0]), im.direction.dot(axes[1]), im.direction.dot(axes[2]));
        directions_.push_back(d.normalized());
        pixels_.push_back(pixelOfDirection(lc::frameCamera(scene), d));
        const bool inView = pixels_.back().first >= 0;
        const lc::godel::SkyAngles seen = lc::godel::skyAngles(directions_.back());
        const QStringList cells{
            QString::number(im.winding), im.branch == lc::godel::Branch::Outbound ? "outbound" : "inbound",
            // psi and phi of the direction in the camera's frame (e3 the polar axis), as the
            // pixels and `lightcone images` give it, whatever isometry moved the observer.
            QString::number(seen.psi * 180 / lc::kPi, 'f', 2), QString::number(seen.phi0 * 180 / lc::kPi, 'f', 2),
            QString::number(im.emissionTime, 'f', 4), QString::number(im.frequencyRatio, 'f', 4),
            QString::number(im.lambda, 'f', 4),
            inView ? QString("%1, %2").arg(pixels_.back().first).arg(pixels_.back().second) : "outside the view",
            n < ages.size() ? ages[n] : QString("-")};
        for (int c = 0; c < cells.size(); ++c) setItem(static_cast<int>(n), c, new QTableWidgetItem(cells[c]));
    }
}

std::pair<int, int> ImagesTable::pixelOfRow(int row) const {
    return row >= 0 && row < static_cast<int>(pixels_.size()) ? pixels_[static_cast<std::size_t>(row)]
                                                              : std::pair{-1, -1};
}

std::optional<SelectedRay> ImagesTable::rayOfRow(int row) const {
    if (row < 0 || row >= static_cast<int>(images_.size())) return std::nullopt;
    const auto [i, j] = pixelOfRow(row);
    return SelectedRay{directions_[static_cast<std::size_t>(row)], images_[static_cast<std::size_t>(row)].lambda, i, j,
                       labelOfRow(row)};
}

std::vector<lc::Vec4> ImagesTable::lightPathOfRow(int row, int samples) const {
    std::vector<lc::Vec4> path;
    if (row < 0 || row >= static_cast<int>(images_.size())) return path;
    const lc::godel::Image& im = images_[static_cast<std::size_t>(row)];
    const auto ray = im.ray(a_);
    for (int k = 0; k <= samples; ++k) path.push_back(ray.cartesian(im.lambda * k / samples));
    return path;
}

int ImagesTable::rowSeenAlong(const lc::Vec3& direction) const {
    const lc::Vec3 n = direction.normalized();
    int best = -1;
    for (std::size_t k = 0; k < directions_.size(); ++k)
        if (best < 0 || directions_[k].dot(n) > directions_[static_cast<std::size_t>(best)].dot(n))
            best = static_cast<int>(k);
    return best;
}

QString ImagesTable::ageOfRow(int row) const {
    const QTableWidgetItem* cell = row >= 0 && row < rowCount() ? item(row, 8) : nullptr;
    return cell ? cell->text() : QString("-");
}

std::string ImagesTable::labelOfRow(int row) const {
    if (row < 0 || row >= static_cast<int>(images_.size())) return "";
    const lc::godel::Image& im = images_[static_cast<std::size_t>(row)];
    return "picked: image of winding " + std::to_string(im.winding) +
           (im.branch == lc::godel::Branch::Outbound ? ", outbound" : ", inbound");
}

}  // namespace lc::gui
