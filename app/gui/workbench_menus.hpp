// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The workbench's menus and toolbar (ParaView's menu builders): each action triggers a reaction
// or edits the active scene; nothing here holds state of its own.
#include <QObject>
#include <QString>

class QMainWindow;

namespace lc::gui {

class ActiveScene;
class CameraReaction;
class ExportReaction;
class RenderController;
class SessionReactions;
class RenderComparison;
class ShadowOutlineOverlay;
class WorkbenchDocks;

class WorkbenchMenus : public QObject {
    Q_OBJECT
public:
    WorkbenchMenus(QMainWindow* window, ActiveScene* scene, WorkbenchDocks* docks, RenderController* render,
                   SessionReactions* sessions, ExportReaction* exports, CameraReaction* camera,
                   ShadowOutlineOverlay* outline, RenderComparison* comparison);
    // Help > About: the versions and the OpenGL renderer.
    static QString aboutText(const WorkbenchDocks& docks);
};

}  // namespace lc::gui
