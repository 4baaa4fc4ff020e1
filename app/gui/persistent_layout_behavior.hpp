// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The window's size and docks as the user left them (ParaView's persistent main window state
// behaviour): restored from QSettings on start (the default layout on the first run), saved when
// the window closes.
#include <QObject>

class QMainWindow;

namespace lc::gui {

class WorkbenchDocks;

class PersistentLayoutBehavior : public QObject {
    Q_OBJECT
public:
    PersistentLayoutBehavior(QMainWindow* window, WorkbenchDocks* docks);
    void save() const;

private:
    QMainWindow* window_;
};

}  // namespace lc::gui
