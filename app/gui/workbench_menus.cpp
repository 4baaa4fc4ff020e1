// SPDX-License-Identifier: BSD-3-Clause
#include "workbench_menus.hpp"

#include "camera_edits.hpp"

#include "active_scene.hpp"
#include "camera_reaction.hpp"
#include "egocentric_image_widget.hpp"
#include "export_reaction.hpp"
#include "guide_window.hpp"
#include "help_dialogs.hpp"
#include "observer_time_slider.hpp"
#include "properties_panel.hpp"
#include "render_comparison.hpp"
#include "render_controller.hpp"
#include "shadow_outline_overlay.hpp"
#include "session_reactions.hpp"
#include "workbench_docks.hpp"

#include "readers/io/oiio_codec.hpp"
#include "readers/io/provenance.hpp"

#include <vtkRenderWindow.h>
#include <vtkVersion.h>

#include <QAction>
#include <QActionGroup>
#include <QDockWidget>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenuBar>
#include <QMessageBox>
#include <QToolBar>

namespace lc::gui {

WorkbenchMenus::WorkbenchMenus(QMainWindow* window, ActiveScene* scene, WorkbenchDocks* docks, RenderController* render,
                               SessionReactions* sessions, ExportReaction* exports, CameraReaction* camera,
                               ShadowOutlineOverlay* outline, RenderComparison* comparison)
    : QObject(window) {
    auto action = [this](QMenu* menu, const QString& text, const QKeySequence& keys, auto slot) {
        QAction* a = menu->addAction(text);
        if (!keys.isEmpty()) a->setShortcut(keys);
        connect(a, &QAction::triggered, this, slot);
        return a;
    };
    QMenu* file = window->menuBar()->addMenu("&File");
    QAction* open = action(file, "&Open scene...", QKeySequence::Open, [sessions] { sessions->chooseScene(); });
    sessions->setRecentMenu(file->addMenu("Open &recent"));
    action(file, "Open &session...", QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O),
           [sessions] { sessions->chooseSession(); });
    file->addSeparator();
    QAction* save = action(file, "&Save session", QKeySequence::Save, [sessions] { sessions->save(); });
    action(file, "Save session &as...", QKeySequence::SaveAs, [sessions] { sessions->saveAs(); });
    file->addSeparator();
    action(file, "Export &image (PNG/EXR)...", QKeySequence(Qt::CTRL | Qt::Key_E),
           [exports] { exports->chooseImage(); });
    action(file, "Export &diagram (SVG/PDF/PNG)...", QKeySequence(), [exports] { exports->chooseDiagram(); });
    action(file, "Export &figure (PDF/SVG/PNG)...", QKeySequence(), [exports] { exports->chooseFigure(); });
    action(file, "Export &VTK data (.vtp/.vti/.vtm)...", QKeySequence(), [exports] { exports->chooseVtkFolder(); });
    action(file, "Export images &table (CSV)...", QKeySequence(), [exports] { exports->chooseImagesTable(); });
    action(file, "Export &picked pixel (CSV)...", QKeySequence(), [exports] { exports->choosePick(); });
    file->addSeparator();
    action(file, "&Quit", QKeySequence::Quit, [window] { window->close(); });

    QMenu* edit = window->menuBar()->addMenu("&Edit");
    QAction* undo = scene->undoStack()->createUndoAction(window, "&Undo");
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = scene->undoStack()->createRedoAction(window, "&Redo");
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    PropertiesPanel* properties = docks->properties();
    action(edit, "Add &sphere", QKeySequence(), [scene] { scene->addSphere(); });
    action(edit, "Add &light", QKeySequence(), [scene] { scene->addLight(); });
    action(edit, "&Duplicate object or light", QKeySequence(Qt::CTRL | Qt::Key_D), [scene, properties] {
        const auto [list, index] = properties->currentElement();
        if (!list.isEmpty()) scene->duplicateElement(list, index);
    });
    action(edit, "Re&move object or light", QKeySequence(), [scene, properties] {
        const auto [list, index] = properties->currentElement();
        if (!list.isEmpty()) scene->removeElement(list, index);
    });

    QMenu* view = window->menuBar()->addMenu("&View");
    for (QDockWidget* dock : docks->docks()) view->addAction(dock->toggleViewAction());
    view->addSeparator();
    QAction* reset = action(view, "Reset &view", QKeySequence(Qt::CTRL | Qt::Key_R), [camera] { camera->resetView(); });
    QAction* panorama = view->addAction("&Panorama projection");
    panorama->setCheckable(true);
    camera->setPanoramaAction(panorama);
    QAction* shaders = view->addAction("Image from &shaders (GPU) where available");
    shaders->setCheckable(true);
    shaders->setChecked(render->shadersEnabled());
    render->setShadersAction(shaders);
    connect(shaders, &QAction::triggered, render, [render](bool on) { render->setShadersEnabled(on); });
    QAction* shadow = view->addAction("Shadow &outline");
    shadow->setObjectName("shadowOutlineAction");
    shadow->setCheckable(true);
    connect(shadow, &QAction::triggered, outline, [outline](bool on) { outline->setShown(on); });
    // Compare: pin an image, then this one beside it, their difference, or blinking.
    QMenu* compare = view->addMenu("&Compare with a pinned image");
    compare->setObjectName("compareMenu");
    QAction* pin =
        action(compare, "&Pin this image", QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P), [scene, comparison] {
            QString label = QFileInfo(scene->sceneFile()).fileName();
            if (scene->undoStack()->index() > 0)
                label += " after '" + scene->undoStack()->text(scene->undoStack()->index() - 1) + "'";
            comparison->pin(label);
        });
    pin->setObjectName("pinImageAction");
    compare->addSeparator();
    auto* modes = new QActionGroup(compare);
    const std::pair<const char*, RenderComparison::Mode> kinds[] = {{"&Off", RenderComparison::Off},
                                                                    {"&Side by side", RenderComparison::SideBySide},
                                                                    {"&Difference", RenderComparison::Difference},
                                                                    {"&Blink", RenderComparison::Blink}};
    for (const auto& [text, mode] : kinds) {
        QAction* a = compare->addAction(text);
        a->setCheckable(true);
        a->setChecked(mode == RenderComparison::Off);
        a->setObjectName(QString("compareMode%1").arg(static_cast<int>(mode)));
        modes->addAction(a);
        connect(a, &QAction::triggered, comparison, [comparison, m = mode] { comparison->setMode(m); });
    }
    // A refused mode (nothing pinned) falls back to Off: the menu follows.
    connect(comparison, &RenderComparison::modeChanged, compare,
            [modes](int mode) { modes->actions().at(mode)->setChecked(true); });
    view->addSeparator();
    action(view, "Reset &layout", QKeySequence(), [docks] { docks->resetLayout(); });

    QMenu* help = window->menuBar()->addMenu("&Help");
    action(help, "&Guide (on a property: its section)", QKeySequence::HelpContents, [window, docks] {
        const auto [page, section] = docks->guideTarget();
        GuideWindow::showGuide(window, page, section);
    });
    action(help, "Keyboard &shortcuts", QKeySequence(), [window] { showShortcutsDialog(window, window->menuBar()); });
    action(help, "&About Lightcone", QKeySequence(),
           [window, docks] { QMessageBox::about(window, "About Lightcone", aboutText(*docks)); });

    QToolBar* tools = window->addToolBar("Main");
    tools->setObjectName("mainToolBar");
    for (QAction* a : {open, save, undo, redo, reset, panorama}) tools->addAction(a);
    // The observer's proper time: one edit of observer.position per choice.
    tools->addSeparator();
    tools->addWidget(docks->observerTimeSlider());
    connect(docks->observerTimeSlider(), &ObserverTimeSlider::timeChosen, scene, [scene](double t) {
        if (!scene->hasScene()) return;
        const lc::Vec4& x = scene->scene().scene().observer;
        Json::Value position(Json::arrayValue);
        position.append(readableNumber(t));  // the slider's time; the place as the scene has it
        for (int k = 1; k < 4; ++k) position.append(x(k));
        scene->edit({{"observer.position", position}}, "observer time");
    });
}

QString WorkbenchMenus::aboutText(const WorkbenchDocks& docks) {
    QString gl = "unknown";
    vtkRenderWindow* window = docks.imageView()->renderWindow();
    const std::string caps = window ? window->ReportCapabilities() : "";
    const auto at = caps.find("OpenGL renderer string:");
    if (at != std::string::npos) {
        const auto end = caps.find('\n', at);
        gl = QString::fromStdString(caps.substr(at + 23, end - at - 23)).trimmed();
    }
    return QString(
               "<b>Lightcone %1</b> (commit %6)<br>what an observer sees in a relativistic spacetime<br><br>"
               "VTK %2<br>Qt %3<br>OpenImageIO %4<br>OpenGL renderer: %5<br><br>BSD-3-Clause licence")
        .arg(QString::fromStdString(lc::io::versionNumber()), vtkVersion::GetVTKVersion(), qVersion(),
             lc::io::oiioCodec().version, gl, QString::fromStdString(lc::io::buildCommit()));
}

}  // namespace lc::gui
