// SPDX-License-Identifier: BSD-3-Clause
#include "persistent_layout_behavior.hpp"

#include "workbench_docks.hpp"

#include <QMainWindow>
#include <QSettings>
#include <QTimer>

namespace lc::gui {

PersistentLayoutBehavior::PersistentLayoutBehavior(QMainWindow* window, WorkbenchDocks* docks)
    : QObject(window), window_(window) {
    docks->rememberDefaultLayout();
    QSettings settings;
    window->restoreGeometry(settings.value("window/geometry").toByteArray());
    if (!window->restoreState(settings.value("window/state").toByteArray()))
        QTimer::singleShot(0, docks, &WorkbenchDocks::resetLayout);  // first run: once the window has its size
}

void PersistentLayoutBehavior::save() const {
    QSettings settings;
    settings.setValue("window/geometry", window_->saveGeometry());
    settings.setValue("window/state", window_->saveState());
}

}  // namespace lc::gui
