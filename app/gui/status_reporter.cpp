// SPDX-License-Identifier: BSD-3-Clause
#include "status_reporter.hpp"

#include <QMessageBox>
#include <QStatusBar>

namespace lc::gui {

StatusReporter::StatusReporter(QStatusBar* bar, QWidget* dialogParent)
    : QObject(bar), bar_(bar), dialogParent_(dialogParent) {}

void StatusReporter::status(const QString& text) { bar_->showMessage(text); }

QString StatusReporter::statusText() const { return bar_->currentMessage(); }

void StatusReporter::error(const QString& title, const QString& text) {
    lastError_ = text;
    auto* box = new QMessageBox(QMessageBox::Critical, title, text, QMessageBox::Ok, dialogParent_);
    box->setObjectName("errorDialog");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void StatusReporter::notice(const QString& title, const QString& text) {
    lastNotice_ = text;
    auto* box = new QMessageBox(QMessageBox::Information, title, text, QMessageBox::Ok, dialogParent_);
    box->setObjectName("noticeDialog");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

}  // namespace lc::gui
