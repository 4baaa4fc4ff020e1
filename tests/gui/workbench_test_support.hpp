// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the workbench's GUI tests share: a window shown and active as a user has it, waiting for
// the CPU render, and where screenshots for docs/GUI.md go (scripts/screenshots sets the folder).
#include "active_scene.hpp"
#include "camera_reaction.hpp"
#include "export_reaction.hpp"
#include "main_window.hpp"
#include "render_controller.hpp"
#include "render_progress_behavior.hpp"
#include "selection_link.hpp"
#include "session_reactions.hpp"
#include "status_reporter.hpp"
#include "workbench_docks.hpp"
#include "workbench_menus.hpp"

#include <QApplication>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QTest>

#include "core/numerics/types.hpp"

#include <json/json.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <filesystem>
#include <memory>

namespace lc::test {

// The project's data/ folder (the scenes a user opens first), with its trailing slash.
inline const QString kData = QString(LIGHTCONE_SOURCE_DIR) + "/data/";

// Time limits are for the normal build; scripts/sanitize sets LIGHTCONE_TEST_TIME_SCALE (ASan and
// UBSan make the tracer several times slower), so that run checks for reports, not for speed.
inline double timeScale() {
    const char* s = std::getenv("LIGHTCONE_TEST_TIME_SCALE");
    const double v = s ? std::atof(s) : 1.0;
    return v >= 1 ? v : 1.0;
}

// Waits (processing events) until the CPU render of the current scene is there.
inline bool waitForCpuImage(lc::gui::MainWindow& w, int timeoutMs = 30000) {
    timeoutMs = static_cast<int>(timeoutMs * timeScale());
    QElapsedTimer t;
    t.start();
    while ((w.renderer()->rendering() || !w.renderer()->cpuImage()) && t.elapsed() < timeoutMs) QTest::qWait(20);
    return w.renderer()->cpuImage() != nullptr && !w.renderer()->rendering();
}

// A mouse move with the left button held, delivered to the widget at once. Qt 5's QTest::mouseMove
// warps the X pointer instead, and the motion comes back when the X server sends it: on a loaded
// machine, after the test has read what the move did.
inline void dragMoveTo(QWidget* widget, QPoint pos) {
    QMouseEvent move(QEvent::MouseMove, pos, widget->mapToGlobal(pos), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(widget, &move);
}

// A 1280 x 800 workbench, shown, exposed and active (shortcuts need the active window). Returns
// false when the window never got exposed.
inline bool showWorkbench(lc::gui::MainWindow& w) {
    w.resize(1280, 800);
    w.show();
    if (!QTest::qWaitForWindowExposed(&w)) return false;
    w.activateWindow();
    (void)QTest::qWaitForWindowActive(&w, 2000);
    return true;
}

// The folder for docs/GUI.md's screenshots: $LIGHTCONE_SCREENSHOT_DIR, else build/screenshots.
inline std::filesystem::path screenshotFolder() {
    const char* env = std::getenv("LIGHTCONE_SCREENSHOT_DIR");
    const std::filesystem::path dir =
        env && *env ? std::filesystem::path(env) : std::filesystem::path(LIGHTCONE_BINARY_DIR) / "screenshots";
    std::filesystem::create_directories(dir);
    return dir;
}

// A widget as it is drawn now (a popup, a dialog), saved under screenshotFolder().
inline bool saveWidgetScreenshot(QWidget* w, const char* name) {
    QApplication::processEvents();
    return w->grab().toImage().save(QString::fromStdString((screenshotFolder() / name).string()));
}

// The window as it is drawn now, saved under screenshotFolder().
inline bool saveScreenshot(lc::gui::MainWindow& w, const char* name) {
    QApplication::processEvents();
    return w.grab().toImage().save(QString::fromStdString((screenshotFolder() / name).string()));
}

// Resident memory of this process (MiB), from /proc/self/statm.
inline double residentMiB() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// A Goedel scene of `count` small spheres inside the horizon (fixed seed), each at rest or, with
// `worldLinePoints` > 0, on a world line of that many events; a small panorama (24 x 8: the closed
// form tests every sphere at every pixel).
inline std::string crowdedGodelScene(int count, int worldLinePoints) {
    Json::Value scene;
    scene["metric"]["name"] = "godel";
    scene["camera"]["projection"] = "panorama";
    scene["camera"]["width"] = 24;
    scene["camera"]["height"] = 8;
    std::uint32_t state = 20261207;
    auto uniform = [&](double lo, double hi) {
        state = state * 1664525u + 1013904223u;
        return lo + (hi - lo) * (state >> 8) / double(1u << 24);
    };
    for (int k = 0; k < count; ++k) {
        const double r = uniform(0.3, 1.5), phi = uniform(0, 2 * lc::kPi), z = uniform(-0.5, 0.5);
        Json::Value o;
        o["type"] = "sphere";
        o["name"] = "b" + std::to_string(k);
        o["radius"] = 0.02;
        Json::Value centre(Json::arrayValue);
        for (double c : {0.0, r * std::cos(phi), r * std::sin(phi), z}) centre.append(c);
        o["centre"] = centre;
        if (worldLinePoints > 0) {
            o["motion"]["type"] = "world_line";
            Json::Value points(Json::arrayValue);
            for (int i = 0; i < worldLinePoints; ++i) {
                Json::Value e(Json::arrayValue);
                for (double c : {-3 + 0.05 * i, r * std::cos(phi) + 0.001 * i, r * std::sin(phi), z}) e.append(c);
                points.append(e);
            }
            o["motion"]["points"] = points;
            o["centre"] = points[0];
        }
        scene["objects"].append(o);
    }
    Json::StreamWriterBuilder w;
    w["indentation"] = "";
    return Json::writeString(w, scene);
}

}  // namespace lc::test
