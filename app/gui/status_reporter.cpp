// SPDX-License-Identifier: BSD-3-Clause
#include "status_reporter.hpp"

#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QStatusBar>
#include <QToolButton>

namespace lc::gui {

StatusReporter::StatusReporter(QStatusBar* bar, QWidget* dialogParent)
    : QObject(bar), bar_(bar), dialogParent_(dialogParent) {
    messageBar_ = new QFrame(dialogParent);
    messageBar_->setObjectName("messageBar");
    messageBar_->setFrameShape(QFrame::StyledPanel);
    auto* layout = new QHBoxLayout(messageBar_);
    layout->setContentsMargins(6, 2, 2, 2);
    message_ = new QLabel(messageBar_);
    message_->setObjectName("messageText");
    message_->setWordWrap(true);
    message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(message_, 1);
    close_ = new QToolButton(messageBar_);
    close_->setObjectName("messageClose");
    close_->setText("Close");
    close_->setToolTip("Hide this message");
    layout->addWidget(close_, 0, Qt::AlignTop);
    connect(close_, &QToolButton::clicked, messageBar_, &QWidget::hide);
    messageBar_->hide();
}

void StatusReporter::status(const QString& text) { bar_->showMessage(text); }

QString StatusReporter::statusText() const { return bar_->currentMessage(); }

void StatusReporter::error(const QString& title, const QString& text) {
    lastError_ = text;
    auto* box = new QMessageBox(QMessageBox::Critical, title, text, QMessageBox::Ok, dialogParent_);
    box->setObjectName("errorDialog");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void StatusReporter::problem(const QString& title, const QString& text) {
    lastError_ = text;
    showMessage(title + ": " + text, true);
}

void StatusReporter::information(const QString& text) { showMessage(text, false); }

void StatusReporter::dismiss(const QString& text) {
    if (!messageBar_->isHidden() && message_->text() == text) messageBar_->hide();
}

void StatusReporter::showMessage(const QString& text, bool isProblem) {
    message_->setText(text);
    message_->setStyleSheet(isProblem ? "color: #b00020" : "");
    messageBar_->show();
}

QString StatusReporter::messageText() const { return messageBar_->isHidden() ? QString() : message_->text(); }

void StatusReporter::notice(const QString& title, const QString& text) {
    lastNotice_ = text;
    auto* box = new QMessageBox(QMessageBox::Information, title, text, QMessageBox::Ok, dialogParent_);
    box->setObjectName("noticeDialog");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

}  // namespace lc::gui
