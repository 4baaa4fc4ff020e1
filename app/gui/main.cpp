// SPDX-License-Identifier: BSD-3-Clause
// lightcone-gui [SCENE.json | SESSION.lcsession]: the Lightcone workbench (docs/GUI.md).
#include "main_window.hpp"
#include "session_reactions.hpp"
#include "status_reporter.hpp"

#include <QApplication>
#include <QScreen>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

#include <iostream>

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName("Lightcone");
    QCoreApplication::setApplicationName("lightcone-gui");
    const QStringList args = app.arguments();
    if (args.size() > 2 || (args.size() == 2 && (args[1] == "--help" || args[1] == "-h"))) {
        std::cerr << "usage: lightcone-gui [SCENE.json | SESSION.lcsession]   (docs/GUI.md)\n";
        return args.size() == 2 ? 0 : 2;
    }
    lc::gui::MainWindow window;
    window.fitInto(window.screen()->availableGeometry());
    window.show();
    if (args.size() == 2 && !window.sessions()->openFile(args[1]))
        std::cerr << "lightcone-gui: " << window.report()->lastError().toStdString() << "\n";
    return app.exec();
}
