// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// File > Export image, Export diagram, Export figure, Export VTK data: the CLI's own writers
// (`lightcone render`, `diagram`, `figure`, `export`) on the edited scene, so the GUI's files equal the command line's
// byte for byte; with post-rendering on, the image is the post-rendered one (`lightcone shade`). Export images table
// and Export picked pixel write CSV (RFC 4180) for papers and scripts: the table as shown, and the picked pixel's
// per-pixel record with its viewing direction. The dialogs start beside the session or scene file, named after it.
#include <QObject>
#include <QString>

#include <functional>

class QWidget;

namespace lc::gui {

class ActiveScene;
class RenderController;
class SelectionLink;
class StatusReporter;
class WorkbenchDocks;

class ExportReaction : public QObject {
    Q_OBJECT
public:
    ExportReaction(QWidget* dialogParent, ActiveScene* scene, RenderController* render, WorkbenchDocks* docks,
                   SelectionLink* selection, StatusReporter* report);

    // Each returns false after showing "Cannot export the <what>" with the reason.
    bool exportImage(const QString& path);    // PNG/EXR of the CPU render, as `lightcone render`
    bool exportDiagram(const QString& path);  // SVG/PDF/PNG, as `lightcone diagram`
    bool exportVtk(const QString& folder);    // .vtp/.vti/.vtm, as `lightcone export`
    // SVG/PDF/PNG of the CPU render on angular axes, as `lightcone figure --quantity QUANTITY`.
    bool exportFigure(const QString& path, const QString& quantity = "image");
    bool exportImagesTable(const QString& path);  // .csv: the images table's header and rows as shown
    bool exportPick(const QString& path);         // .csv: field, value of the picked pixel's record
    // The menu actions: a dialog beside the scene, then the export.
    void chooseImage();
    void chooseDiagram();
    void chooseFigure();  // the file, then what the colours show
    void chooseVtkFolder();
    void chooseImagesTable();
    void choosePick();

private:
    bool exportWith(const QString& what, const QString& path, const std::function<void()>& write);

    QWidget* dialogParent_;
    ActiveScene* scene_;
    RenderController* render_;
    WorkbenchDocks* docks_;
    SelectionLink* selection_;
    StatusReporter* report_;
};

}  // namespace lc::gui
