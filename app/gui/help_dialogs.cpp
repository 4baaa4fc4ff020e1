// SPDX-License-Identifier: BSD-3-Clause
#include "help_dialogs.hpp"

#include "readers/io/install_layout.hpp"

#include <QAction>
#include <QDialog>
#include <QDir>
#include <QHeaderView>
#include <QMenu>
#include <QMenuBar>
#include <QTableWidget>
#include <QVBoxLayout>

namespace lc::gui {
namespace {

QDialog* helpWindow(QWidget* parent, const QString& name, const QString& title, QWidget* content, QSize size) {
    auto* dialog = new QDialog(parent);
    dialog->setObjectName(name);
    dialog->setWindowTitle(title);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* layout = new QVBoxLayout(dialog);
    content->setParent(dialog);
    layout->addWidget(content);
    dialog->resize(size);
    dialog->show();  // modeless: the workbench stays usable beside it
    return dialog;
}

// The menus' actions, "File > Open scene..." with their shortcuts, in menu order.
void collectShortcuts(const QMenu* menu, const QString& path, QList<QPair<QString, QString>>& rows) {
    for (QAction* a : menu->actions()) {
        QString text = a->text();
        text.remove('&');
        if (a->menu()) {
            collectShortcuts(a->menu(), path + " > " + text, rows);
            continue;
        }
        if (!a->shortcut().isEmpty())
            rows.append({path + " > " + text, a->shortcut().toString(QKeySequence::NativeText)});
    }
}

}  // namespace

// Installed: PREFIX/share/doc/lightcone/docs; in a build tree inside the checkout: its docs/.
// Found from the program's file (io/install_layout), so nothing installed names the sources.
QString guideDocsFolder() {
    for (const char* relative : {"share/doc/lightcone/docs/guide/index.md", "docs/guide/index.md"})
        if (const auto guide = io::findAboveProgram(relative))
            return QString::fromStdString(guide->parent_path().parent_path().string());
    return "share/doc/lightcone/docs";
}

void showShortcutsDialog(QWidget* parent, const QMenuBar* menus) {
    QList<QPair<QString, QString>> rows;
    for (QAction* a : menus->actions())
        if (a->menu()) {
            QString text = a->text();
            text.remove('&');
            collectShortcuts(a->menu(), text, rows);
        }
    // What the mouse does: no menu action says it.
    rows.append(qMakePair(QString("Image: click"),
                          QString("pick the pixel: its light path in every view, its ray's figures in Accuracy")));
    rows.append(qMakePair(QString("Image: drag"), QString("look around (one undoable edit of the camera)")));
    rows.append(qMakePair(QString("Image: wheel"), QString("zoom (field of view 10 % per step)")));
    rows.append(qMakePair(QString("r-phi diagram: click"), QString("select the fan ray nearest the point")));
    rows.append(qMakePair(QString("Spacetime view: click"), QString("select a ray or an object; drag turns the view")));
    auto* table = new QTableWidget(rows.size(), 2);
    table->setObjectName("shortcutsTable");
    table->setHorizontalHeaderLabels({"action", "keys or mouse"});
    for (int r = 0; r < rows.size(); ++r) {
        table->setItem(r, 0, new QTableWidgetItem(rows[r].first));
        table->setItem(r, 1, new QTableWidgetItem(rows[r].second));
    }
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    helpWindow(parent, "shortcutsDialog", "Keyboard shortcuts and mouse", table, {640, 480});
}

}  // namespace lc::gui
