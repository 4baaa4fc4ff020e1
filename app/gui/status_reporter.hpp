// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Where the workbench tells the user what happened: a line in the status bar, an error in a
// window-modal dialog that does not block (the event loop and a running render go on), a notice.
// Every part of the window reports through this one object; tests read back what it said.
#include <QObject>
#include <QString>

class QStatusBar;
class QWidget;

namespace lc::gui {

class StatusReporter : public QObject {
    Q_OBJECT
public:
    StatusReporter(QStatusBar* bar, QWidget* dialogParent);

    void status(const QString& text);
    void error(const QString& title, const QString& text);
    void notice(const QString& title, const QString& text);

    QString statusText() const;
    QString lastError() const { return lastError_; }
    QString lastNotice() const { return lastNotice_; }

private:
    QStatusBar* bar_;
    QWidget* dialogParent_;
    QString lastError_, lastNotice_;
};

}  // namespace lc::gui
