// SPDX-License-Identifier: BSD-3-Clause
// The workbench's live preview while dragging the egocentric image (#26 item 4): how many
// updates per second the image follows the hand, on each data scene. Real Qt mouse events
// (QTest) on the image widget; each move redraws the shifted image (VTK through GLX: run under
// xvfb-run, which is Mesa llvmpipe on the CPU). Prints a Markdown table.
#include "egocentric_image_widget.hpp"
#include "main_window.hpp"
#include "active_scene.hpp"
#include "render_controller.hpp"
#include "session_reactions.hpp"
#include "workbench_docks.hpp"

#include <QApplication>
#include <QElapsedTimer>
#include <QTest>

#include <cstdio>

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    lc::gui::MainWindow window;
    window.resize(1280, 800);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return 1;
    std::printf("| scene | image | moves | ms per update | updates/s |\n|---|---|---|---|---|\n");
    for (const char* name : {"default.json", "godel_many_images.json", "kerr.json", "sr_cube.json"}) {
        if (!window.sessions()->openScene(QString(LIGHTCONE_SOURCE_DIR) + "/data/" + name)) return 1;
        QElapsedTimer wait;
        wait.start();
        while ((window.renderer()->rendering() || !window.renderer()->cpuImage()) && wait.elapsed() < 120000)
            QTest::qWait(20);
        lc::gui::EgocentricImageWidget* image = window.docks()->imageView();
        const int w = image->imageWidth(), h = image->imageHeight();
        const QPoint from = image->widgetPointOfPixel(w / 2, h / 2);
        QTest::mousePress(image, Qt::LeftButton, Qt::NoModifier, from);
        constexpr int kMoves = 200;
        QElapsedTimer t;
        t.start();
        for (int k = 1; k <= kMoves; ++k) {
            QTest::mouseMove(image, from + QPoint(10 + k % 100, (k % 40) - 20));
            QApplication::processEvents();
        }
        const double ms = t.nsecsElapsed() * 1e-6 / kMoves;
        // Released where it started: no turn, nothing traced again.
        QTest::mouseMove(image, from);
        QTest::mouseRelease(image, Qt::LeftButton, Qt::NoModifier, from);
        std::printf("| %s | %d x %d | %d | %.2f | %.0f |\n", name, w, h, kMoves, ms, 1000 / ms);
    }
    window.activeScene()->undoStack()->setClean();
    return 0;
}
