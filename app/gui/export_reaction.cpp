// SPDX-License-Identifier: BSD-3-Clause
#include "export_reaction.hpp"

#include "active_scene.hpp"
#include "images_table.hpp"
#include "post_render_dock.hpp"
#include "render_controller.hpp"
#include "selection_link.hpp"
#include "status_reporter.hpp"
#include "workbench_docks.hpp"

#include "app/commands/commands.hpp"
#include "core/scene/frame_camera.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/image_io.hpp"

#include <QFileDialog>
#include <QInputDialog>
#include <QStringList>

#include <algorithm>
#include <cstdio>

namespace lc::gui {

ExportReaction::ExportReaction(QWidget* dialogParent, ActiveScene* scene, RenderController* render,
                               WorkbenchDocks* docks, SelectionLink* selection, StatusReporter* report)
    : QObject(dialogParent),
      dialogParent_(dialogParent),
      scene_(scene),
      render_(render),
      docks_(docks),
      selection_(selection),
      report_(report) {}

namespace {

// One CSV cell (RFC 4180): quoted where it holds a comma, a quote or a line break.
QString csvCell(const QString& text) {
    if (!text.contains(',') && !text.contains('"') && !text.contains('\n')) return text;
    return '"' + QString(text).replace("\"", "\"\"") + '"';
}

QString csvRow(const QStringList& cells) {
    QStringList quoted;
    for (const QString& c : cells) quoted << csvCell(c);
    return quoted.join(',') + "\n";
}

// A number that reads back to the same double.
QString exactNumber(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

const char* kindName(int kind) {
    switch (kind) {
        case lc::PixelRecord::Object: return "object";
        case lc::PixelRecord::Sky: return "sky";
        case lc::PixelRecord::Horizon: return "horizon";
        case lc::PixelRecord::Failed: return "failed";
        case lc::PixelRecord::Disk: return "disk";
        default: return "background";
    }
}

}  // namespace

bool ExportReaction::exportWith(const QString& what, const QString& path, const std::function<void()>& write) {
    try {
        write();
    } catch (const std::exception& e) {
        report_->error("Cannot export the " + what, e.what());
        return false;
    }
    report_->status("wrote " + path);
    return true;
}

bool ExportReaction::exportImage(const QString& path) {
    return exportWith("image", path, [&] {
        const auto cpu = render_->cpuImageShared();
        if (!cpu) throw std::invalid_argument("the CPU render of this scene is not finished (or was cancelled)");
        lc::io::checkOutputPath(path.toStdString(), lc::io::imageExtensions(), "image file");
        PostRenderDock* post = docks_->postRenderView();
        if (!post->active()) {
            lc::cli::writeRenderOutputs(*cpu, path.toStdString());
            return;
        }
        // What the post-rendering dock shows, coloured by the CPU reference (as `lightcone shade`).
        lc::ColouredImage shaded{cpu->records,
                                 lc::shadePixels(scene_->scene().scene(), cpu->records, post->settings())};
        lc::cli::writeRenderOutputs(shaded, path.toStdString());
    });
}

bool ExportReaction::exportDiagram(const QString& path) {
    return exportWith("diagram", path, [&] {
        if (!scene_->hasScene()) throw std::invalid_argument("open a scene first");
        lc::io::checkOutputPath(path.toStdString(), {".svg", ".pdf", ".png"}, "diagram file");
        const lc::Scene& scene = scene_->scene().scene();
        lc::cli::writeDiagrams(scene, {path.toStdString()}, std::min(scene.settings.windings, 50));
    });
}

bool ExportReaction::exportFigure(const QString& path, const QString& quantity) {
    return exportWith("figure", path, [&] {
        const auto cpu = render_->cpuImageShared();
        if (!cpu) throw std::invalid_argument("the CPU render of this scene is not finished (or was cancelled)");
        lc::io::checkOutputPath(path.toStdString(), {".svg", ".pdf", ".png"}, "figure file");
        lc::cli::writeFigures(scene_->scene().scene(), *cpu, {path.toStdString()}, quantity.toStdString());
    });
}

bool ExportReaction::exportVtk(const QString& folder) {
    return exportWith("VTK data", folder, [&] {
        if (!scene_->hasScene()) throw std::invalid_argument("open a scene first");
        lc::cli::exportScene(scene_->scene().scene(), folder.toStdString());
    });
}

bool ExportReaction::exportImagesTable(const QString& path) {
    return exportWith("images table", path, [&] {
        lc::io::checkOutputPath(path.toStdString(), {".csv"}, "images table file");
        const ImagesTable* table = docks_->imagesTable();
        if (table->rowCount() == 0)
            throw std::invalid_argument("the images table is empty: " + table->title().toStdString());
        QStringList header;
        for (int c = 0; c < table->columnCount(); ++c) header << table->horizontalHeaderItem(c)->text();
        QString text = csvRow(header);
        for (int r = 0; r < table->rowCount(); ++r) {
            QStringList cells;
            for (int c = 0; c < table->columnCount(); ++c)
                cells << (table->item(r, c) ? table->item(r, c)->text() : "");
            text += csvRow(cells);
        }
        lc::io::writeFileAtomically(path.toStdString(), text.toStdString());
    });
}

bool ExportReaction::exportPick(const QString& path) {
    return exportWith("picked pixel", path, [&] {
        lc::io::checkOutputPath(path.toStdString(), {".csv"}, "picked pixel file");
        const auto cpu = render_->cpuImageShared();
        const int i = selection_->pickedI(), j = selection_->pickedJ();
        if (!cpu || i < 0 || j < 0 || i >= cpu->records.width || j >= cpu->records.height)
            throw std::invalid_argument("no pixel is picked in the finished CPU render: click one first");
        const lc::PixelRecord& p = cpu->records.pixels[static_cast<std::size_t>(j) * cpu->records.width + i];
        const lc::Vec3 n = lc::frameCamera(scene_->scene().scene()).direction(i, j).normalized();
        QString text = csvRow({"field", "value", "meaning"});
        auto row = [&](const char* field, const QString& value, const char* meaning) {
            text += csvRow({field, value, meaning});
        };
        row("i", QString::number(i), "pixel column, from the left");
        row("j", QString::number(j), "pixel row, from the top");
        row("direction_x", exactNumber(n(0)), "viewing direction in the camera's frame (e1, e2, e3)");
        row("direction_y", exactNumber(n(1)), "");
        row("direction_z", exactNumber(n(2)), "");
        row("kind", kindName(p.kind), "what the ray met");
        row("object", QString::number(p.object), "index of the object or disk met (-1: none)");
        row("u", exactNumber(p.u), "texture coordinate on the object, or the sky direction");
        row("v", exactNumber(p.v), "");
        row("g", exactNumber(p.frequencyRatio), "nu_observed / nu_emitted");
        row("emission_time", exactNumber(p.emissionTime), "coordinate time of the emission event");
        row("affine", exactNumber(p.affine), "affine length from the observer");
        row("steps", exactNumber(p.steps), "integration steps (0: closed form)");
        row("drift", exactNumber(p.drift), "|H| reached on the ray (null condition)");
        row("disk_radius", exactNumber(p.diskRadius), "Boyer-Lindquist radius of the disk hit (M)");
        row("disk_intensity", exactNumber(p.intensity), "observed bolometric intensity g^4 F / F_max");
        row("image_order", QString::number(p.order), "equatorial crossings before the disk (0: direct)");
        row("magnification", exactNumber(p.magnification), "1 / det A (render --magnification; 0: not traced)");
        row("shear", exactNumber(p.shear), "|gamma|");
        row("rotation", exactNumber(p.rotation), "radians");
        lc::io::writeFileAtomically(path.toStdString(), text.toStdString());
    });
}

void ExportReaction::chooseImagesTable() {
    const QString path = QFileDialog::getSaveFileName(dialogParent_, "Export images table",
                                                      scene_->besideScene("images") + ".csv", "CSV tables (*.csv)");
    if (!path.isEmpty()) exportImagesTable(path);
}

void ExportReaction::choosePick() {
    const QString path = QFileDialog::getSaveFileName(dialogParent_, "Export picked pixel",
                                                      scene_->besideScene("pixel") + ".csv", "CSV tables (*.csv)");
    if (!path.isEmpty()) exportPick(path);
}

void ExportReaction::chooseImage() {
    const QString path = QFileDialog::getSaveFileName(dialogParent_, "Export image", scene_->besideScene("image.png"),
                                                      "Images (*.png *.exr)");
    if (!path.isEmpty()) exportImage(path);
}

void ExportReaction::chooseDiagram() {
    const QString path = QFileDialog::getSaveFileName(
        dialogParent_, "Export diagram", scene_->besideScene("diagram.svg"), "Diagrams (*.svg *.pdf *.png)");
    if (!path.isEmpty()) exportDiagram(path);
}

void ExportReaction::chooseFigure() {
    const QString path = QFileDialog::getSaveFileName(dialogParent_, "Export figure", scene_->besideScene("figure.pdf"),
                                                      "Figures (*.pdf *.svg *.png)");
    if (path.isEmpty()) return;
    bool chosen = false;
    const QString quantity = QInputDialog::getItem(
        dialogParent_, "Export figure", "Colours show:", {"image", "redshift", "emission-time"}, 0, false, &chosen);
    if (chosen) exportFigure(path, quantity);
}

void ExportReaction::chooseVtkFolder() {
    const QString folder = QFileDialog::getSaveFileName(dialogParent_, "Export VTK data to a folder",
                                                        scene_->besideScene("lightcone-export"));
    if (!folder.isEmpty()) exportVtk(folder);
}

}  // namespace lc::gui
