// SPDX-License-Identifier: BSD-3-Clause
#include "export_reaction.hpp"

#include "active_scene.hpp"
#include "post_render_dock.hpp"
#include "render_controller.hpp"
#include "status_reporter.hpp"
#include "workbench_docks.hpp"

#include "app/commands/commands.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/image_io.hpp"

#include <QFileDialog>

#include <algorithm>

namespace lc::gui {

ExportReaction::ExportReaction(QWidget* dialogParent, ActiveScene* scene, RenderController* render,
                               WorkbenchDocks* docks, StatusReporter* report)
    : QObject(dialogParent),
      dialogParent_(dialogParent),
      scene_(scene),
      render_(render),
      docks_(docks),
      report_(report) {}

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

bool ExportReaction::exportVtk(const QString& folder) {
    return exportWith("VTK data", folder, [&] {
        if (!scene_->hasScene()) throw std::invalid_argument("open a scene first");
        lc::cli::exportScene(scene_->scene().scene(), folder.toStdString());
    });
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

void ExportReaction::chooseVtkFolder() {
    const QString folder = QFileDialog::getSaveFileName(dialogParent_, "Export VTK data to a folder",
                                                        scene_->besideScene("lightcone-export"));
    if (!folder.isEmpty()) exportVtk(folder);
}

}  // namespace lc::gui
