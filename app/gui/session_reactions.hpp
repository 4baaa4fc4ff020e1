// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// File > Open scene, Open session, Open recent, Save session, Save session as (ParaView's load
// and save-state reactions), and the unsaved-changes question before an edited scene is lost.
// Sessions (docs/SESSIONS.md) keep the scene's edits, the view (pick, selected object, shaders,
// post-rendering) and the window's layout; reopening one gives the same image.
#include "readers/io/session_file.hpp"

#include <QObject>
#include <QString>

class QMainWindow;
class QMenu;

namespace lc::gui {

class ActiveScene;
class RenderController;
class SelectionLink;
class SceneReadJob;
class StatusReporter;
class WorkbenchDocks;

class SessionReactions : public QObject {
    Q_OBJECT
public:
    SessionReactions(QMainWindow* window, ActiveScene* scene, RenderController* render, SelectionLink* selection,
                     WorkbenchDocks* docks, StatusReporter* report);

    // Each returns false after showing the reason in an error dialog; the current scene, session
    // and edits are then unchanged. openFile tells sessions (a JSON object with
    // "lightcone_session") from scenes.
    bool openFile(const QString& path);
    // A scene file over kReadInBackgroundBytes is read on a worker (reading()): true then means
    // the read started, and the scene (or the error) comes when it is done.
    bool openScene(const QString& path);
    static constexpr qint64 kReadInBackgroundBytes = 1 << 20;
    SceneReadJob* reading() const { return reading_; }
    bool openSession(const QString& path);
    bool saveSession(const QString& path);  // atomic; the session becomes the window's
    bool save();                            // File > Save session: the window's session, or Save as
    bool saveAs();                          // asks where, beside the scene
    // Before losing unsaved edits: save, discard or cancel (false).
    bool maybeSave();
    // File > Open scene..., Open session... (asking maybeSave first) and the Open recent menu.
    void chooseScene();
    void chooseSession();
    void setRecentMenu(QMenu* menu);

private:
    lc::io::SessionFile currentSession(const QString& sessionFile) const;
    void addRecent(const QString& path);
    void refreshRecentMenu();

    QMainWindow* window_;
    ActiveScene* scene_;
    RenderController* render_;
    SelectionLink* selection_;
    WorkbenchDocks* docks_;
    StatusReporter* report_;
    SceneReadJob* reading_;
    QMenu* recent_ = nullptr;
};

}  // namespace lc::gui
