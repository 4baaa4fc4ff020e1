// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Where the user guide is (Help > Guide: guide_window.hpp); Help > Keyboard shortcuts: every menu
// action with a shortcut, and what the mouse does in each view, in a window that does not block
// (the event loop and a render go on).
#include <QString>

class QMenuBar;
class QWidget;

namespace lc::gui {

// The folder of docs/guide/ (the source tree's docs/, where the workbench is built).
QString guideDocsFolder();
void showShortcutsDialog(QWidget* parent, const QMenuBar* menus);

}  // namespace lc::gui
