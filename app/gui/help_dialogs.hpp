// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Help > Contents: docs/GUI.md rendered (its screenshots included) in a window beside the
// workbench; Help > Keyboard shortcuts: every menu action with a shortcut, and what the mouse
// does in each view. Both open without blocking (the event loop and a render go on).
#include <QString>

class QMenuBar;
class QWidget;

namespace lc::gui {

// The folder of docs/GUI.md (the source tree's docs/, where the workbench is built).
QString guideDocsFolder();
void showGuideDialog(QWidget* parent);
void showShortcutsDialog(QWidget* parent, const QMenuBar* menus);

}  // namespace lc::gui
