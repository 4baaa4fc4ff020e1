// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Where the workbench tells the user what happened: a line in the status bar; an error of an
// action the user just asked for (open, save, export) in a window-modal dialog that does not block
// (the event loop and a running render go on), a notice; and in the message bar above the views,
// without any dialog, what comes of edits, undo and redo and renders (a render that failed, an undo
// the reader no longer accepts, what a metric change moved), kept until closed or replaced.
// Every part of the window reports through this one object; tests read back what it said.
#include <QObject>
#include <QString>

class QFrame;
class QLabel;
class QStatusBar;
class QToolButton;
class QWidget;

namespace lc::gui {

class StatusReporter : public QObject {
    Q_OBJECT
public:
    // The message bar (messageBar(), hidden until it has something to say) is the window's to place.
    StatusReporter(QStatusBar* bar, QWidget* dialogParent);

    void status(const QString& text);
    void error(const QString& title, const QString& text);
    void notice(const QString& title, const QString& text);
    // In the message bar, no dialog: a problem (red; lastError() has it too) or information.
    void problem(const QString& title, const QString& text);
    void information(const QString& text);
    // Hides the message bar when it still shows `text` (a problem its cause has since mended).
    void dismiss(const QString& text);

    QString statusText() const;
    QString lastError() const { return lastError_; }
    QString lastNotice() const { return lastNotice_; }
    QFrame* messageBar() const { return messageBar_; }
    QString messageText() const;
    QToolButton* messageCloseButton() const { return close_; }

private:
    void showMessage(const QString& text, bool isProblem);

    QStatusBar* bar_;
    QWidget* dialogParent_;
    QFrame* messageBar_;
    QLabel* message_;
    QToolButton* close_;
    QString lastError_, lastNotice_;
};

}  // namespace lc::gui
