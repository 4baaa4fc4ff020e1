// SPDX-License-Identifier: BSD-3-Clause
#include "session_reactions.hpp"

#include "scene_read_job.hpp"

#include "active_scene.hpp"
#include "egocentric_image_widget.hpp"
#include "images_table.hpp"
#include "post_render_dock.hpp"
#include "render_controller.hpp"
#include "selection_link.hpp"
#include "spacetime_view_dock.hpp"
#include "status_reporter.hpp"
#include "workbench_docks.hpp"

#include "app/commands/commands.hpp"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

#include <fstream>

namespace lc::gui {
namespace {

bool isSessionText(const QString& path) {
    std::ifstream in(path.toStdString());
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head.find("\"lightcone_session\"") != std::string::npos;
}

}  // namespace

SessionReactions::SessionReactions(QMainWindow* window, ActiveScene* scene, RenderController* render,
                                   SelectionLink* selection, WorkbenchDocks* docks, StatusReporter* report)
    : QObject(window),
      window_(window),
      scene_(scene),
      render_(render),
      selection_(selection),
      docks_(docks),
      report_(report),
      reading_(new SceneReadJob(this)) {
    connect(reading_, &SceneReadJob::finished, this,
            [this](std::shared_ptr<lc::io::EditableScene> read, const QString& path) {
                // Edits made to the scene shown while this one was read: asked about now.
                if (!maybeSave()) {
                    report_->status("kept the scene shown; " + QFileInfo(path).fileName() + " was read but not opened");
                    docks_->imageView()->setNotice("", false);
                    return;
                }
                scene_->adopt(std::move(*read), path, QString());  // the one receiver: moved, not copied
                addRecent(path);
            });
    connect(reading_, &SceneReadJob::failed, this, [this](const QString& path, const QString& message) {
        docks_->imageView()->setNotice("could not open " + QFileInfo(path).fileName(), scene_->hasScene());
        report_->error("Cannot open the scene", message);
    });
    connect(reading_, &SceneReadJob::cancelled, this, [this](const QString& path) {
        const QString still = scene_->hasScene()
                                  ? "the scene shown is still " + QFileInfo(scene_->sceneFile()).fileName()
                                  : "no scene is open";
        report_->status("reading " + QFileInfo(path).fileName() + " cancelled: " + still +
                        " (a pick, an edit or Ctrl+R renders it again)");
        docks_->imageView()->setNotice("reading cancelled: " + still, true);
    });
}

bool SessionReactions::openFile(const QString& path) {
    return isSessionText(path) ? openSession(path) : openScene(path);
}

bool SessionReactions::openScene(const QString& path) {
    reading_->cancel();  // a read still running is no longer wanted
    const qint64 bytes = QFileInfo(path).size();
    if (bytes > kReadInBackgroundBytes) {
        // Seconds of parsing and checking: the window stays responsive, and what it shows now is
        // the previous scene's, so it says so at once.
        render_->cancel();
        reading_->start(path);
        const QString what =
            QString("reading %1 (%2 MB)...").arg(QFileInfo(path).fileName()).arg(bytes / 1e6, 0, 'f', 1);
        docks_->imageView()->setNotice(what + " Cancel keeps the scene shown before", true);
        docks_->imagesTable()->setRowCount(0);
        report_->status(what);
        return true;
    }
    try {
        scene_->adopt(lc::io::EditableScene::load(path.toStdString(), lc::cli::sceneReadOptions()), path, QString());
    } catch (const std::exception& e) {
        report_->error("Cannot open the scene", e.what());
        return false;
    }
    addRecent(path);
    return true;
}

bool SessionReactions::openSession(const QString& path) {
    reading_->cancel();
    lc::io::SessionFile session;
    lc::io::OpenedSession opened;
    try {
        session = lc::io::readSession(path.toStdString());
        opened = lc::io::openSessionScene(session, path.toStdString(), lc::cli::sceneReadOptions());
    } catch (const std::exception& e) {
        report_->error("Cannot open the session", e.what());
        return false;
    }
    QString sceneFile = QString::fromStdString(session.scenePath);
    if (QFileInfo(sceneFile).isRelative()) sceneFile = QFileInfo(path).dir().filePath(sceneFile);
    render_->setShadersEnabled(session.imageFromShaders, false);
    docks_->postRenderView()->setControls(session.postRender);  // drawn once the data is traced
    if (!session.windowGeometry.empty())
        window_->restoreGeometry(QByteArray::fromBase64(QByteArray::fromStdString(session.windowGeometry)));
    if (!session.windowState.empty())
        window_->restoreState(QByteArray::fromBase64(QByteArray::fromStdString(session.windowState)));
    scene_->adopt(std::move(opened.scene), sceneFile, path);
    scene_->restoreHistory(session.history);  // undoable again, back to the scene file
    if (!session.spacetimeCamera.empty()) docks_->spacetimeView()->restoreCamera(session.spacetimeCamera);
    selection_->restore(session.selectedObject, session.pickedI, session.pickedJ);
    if (!opened.notice.empty()) {
        report_->notice("Session opened from its saved copy", QString::fromStdString(opened.notice));
        scene_->undoStack()->resetClean();  // the session on disk no longer matches what a save would write
    }
    addRecent(path);
    return true;
}

lc::io::SessionFile SessionReactions::currentSession(const QString& sessionFile) const {
    lc::io::SessionFile s;
    s.scenePath = lc::io::scenePathForSession(scene_->sceneFile().toStdString(), sessionFile.toStdString());
    s.edits = scene_->scene().edits();
    s.sceneDocument = scene_->scene().document();
    // A pick still waiting for its data is the one to keep.
    const auto pending = selection_->pendingPick();
    s.pickedI = pending.first >= 0 ? pending.first : selection_->pickedI();
    s.pickedJ = pending.first >= 0 ? pending.second : selection_->pickedJ();
    s.selectedObject = selection_->selectedObject();
    s.imageFromShaders = render_->shadersEnabled();
    s.postRender = docks_->postRenderView()->controls();
    s.history = scene_->history();
    s.spacetimeCamera = docks_->spacetimeView()->cameraState();
    s.windowState = window_->saveState().toBase64().toStdString();
    s.windowGeometry = window_->saveGeometry().toBase64().toStdString();
    return s;
}

bool SessionReactions::saveSession(const QString& path) {
    if (!scene_->hasScene()) {
        report_->error("Nothing to save", "open a scene first");
        return false;
    }
    try {
        lc::io::writeSession(path.toStdString(), currentSession(path));
    } catch (const std::exception& e) {
        report_->error("Cannot save the session", e.what());
        return false;
    }
    scene_->setSaved(path);
    addRecent(path);
    report_->status("saved " + path);
    return true;
}

bool SessionReactions::save() {
    return scene_->sessionPath().isEmpty() ? saveAs() : saveSession(scene_->sessionPath());
}

bool SessionReactions::saveAs() {
    const QString path = QFileDialog::getSaveFileName(window_, "Save session", scene_->besideScene("session.lcsession"),
                                                      "Sessions (*.lcsession)");
    return !path.isEmpty() && saveSession(path);
}

bool SessionReactions::maybeSave() {
    if (scene_->undoStack()->isClean()) return true;
    const auto answer = QMessageBox::question(
        window_, "Unsaved changes", "The scene has edits that are not saved in a session. Save them?",
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel) return false;
    if (answer == QMessageBox::Discard) return true;
    return save();
}

void SessionReactions::chooseScene() {
    if (!maybeSave()) return;
    const QString path =
        QFileDialog::getOpenFileName(window_, "Open scene", QString(), "Scenes (*.json);;All files (*)");
    if (!path.isEmpty()) openScene(path);
}

void SessionReactions::chooseSession() {
    if (!maybeSave()) return;
    const QString path =
        QFileDialog::getOpenFileName(window_, "Open session", QString(), "Sessions (*.lcsession);;All files (*)");
    if (!path.isEmpty()) openSession(path);
}

void SessionReactions::setRecentMenu(QMenu* menu) {
    recent_ = menu;
    refreshRecentMenu();
}

void SessionReactions::addRecent(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value("recentFiles").toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    recent.removeAll(absolute);
    recent.prepend(absolute);
    while (recent.size() > 10) recent.removeLast();
    settings.setValue("recentFiles", recent);
    refreshRecentMenu();
}

void SessionReactions::refreshRecentMenu() {
    if (!recent_) return;
    recent_->clear();
    const QStringList recent = QSettings().value("recentFiles").toStringList();
    for (const QString& path : recent)
        connect(recent_->addAction(path), &QAction::triggered, this, [this, path] {
            if (maybeSave()) openFile(path);
        });
    recent_->setEnabled(!recent.isEmpty());
}

}  // namespace lc::gui
