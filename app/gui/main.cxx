// lightcone-gui SCENE.json: the egocentric image and the r-phi diagram of a Goedel scene as
// linked views (app/gui/README.md).
#include "lightconeMainWindow.h"

#include "readers/io/scene_reader.hpp"

#include <QApplication>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() != 2 || args[1] == "--help" || args[1] == "-h") {
        std::cerr << "usage: lightcone-gui SCENE.json   (a scene with the 'godel' metric)\n";
        return args.size() == 2 ? 0 : 2;
    }
    try {
        lcgui::MainWindow window(lc::io::readScene(args[1].toStdString()));
        window.resize(1400, 600);
        window.show();
        return app.exec();
    } catch (const std::exception& e) {
        std::cerr << "lightcone-gui: " << e.what() << "\n";
        return 1;
    }
}
