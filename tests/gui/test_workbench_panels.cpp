// SPDX-License-Identifier: BSD-3-Clause
// The workbench's accuracy dock, help windows, r-phi dock without a diagram and export dialogs,
// through real Qt events under Xvfb. Oracles: Synge's shadow of a Schwarzschild hole seen by a
// static observer at r0 (sin a_c = 3 sqrt(3) M sqrt(1 - 2M/r0) / r0) and the impact parameter
// of a ray leaving that observer with unit direction n in its frame (e1 radial),
// L_z / E = r0 n^2 / sqrt(1 - 2M/r0) (docs/PHYSICS.md section 10); docs/GUI.md itself; the menus.
#include "workbench_test_support.hpp"

#include "accuracy_panel.hpp"
#include "diagram_dock.hpp"
#include "light_path.hpp"
#include "egocentric_image_widget.hpp"
#include "guide_window.hpp"
#include "active_scene.hpp"
#include "status_reporter.hpp"
#include "render_controller.hpp"
#include "render_progress_behavior.hpp"
#include "session_reactions.hpp"
#include "scene_read_job.hpp"
#include "images_table.hpp"
#include "main_window.hpp"
#include "metric_editor.hpp"
#include "metric_reaction.hpp"
#include "post_render_dock.hpp"
#include "properties_panel.hpp"
#include "render_comparison.hpp"
#include "render_job.hpp"
#include "shadow_outline_overlay.hpp"
#include "spacetime_view_dock.hpp"
#include "vtkLightconeSpacetimeView.h"

#include "core/scene/frame_camera.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/scene_edits.hpp"
#include "readers/io/session_file.hpp"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFileSystemModel>
#include <QPointer>
#include <QCheckBox>
#include <QComboBox>
#include <QSlider>
#include <QContextMenuEvent>
#include <QToolButton>
#include <QTreeWidget>
#include <vtkActor.h>
#include <vtkAxis.h>
#include <vtkRenderer.h>
#include <vtkChartXY.h>
#include <vtkDoubleArray.h>
#include <vtkPlot.h>
#include <vtkTable.h>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QListWidget>
#include <QMessageBox>
#include <QAbstractItemView>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTextCursor>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QStackedWidget>
#include <QTabBar>
#include <QTableWidget>
#include <QSignalSpy>
#include <QTest>
#include <QAbstractTextDocumentLayout>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTimer>
#include <QSettings>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using lc::test::kData;

class WorkbenchPanels : public ::testing::Test {
protected:
    void SetUp() override {
        window = std::make_unique<lc::gui::MainWindow>();
        ASSERT_TRUE(lc::test::showWorkbench(*window));
        folder = fs::temp_directory_path() / ("lc-panels-" + std::to_string(::getpid()) + "-" +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(folder);
        fs::create_directories(folder);
    }
    void TearDown() override {
        for (QWidget* w : QApplication::topLevelWidgets())
            if (w != window.get() && w->isVisible()) w->close();
        window->activeScene()->undoStack()->setClean();
        window->close();
        fs::remove_all(folder);
    }
    bool open(const QString& file) {
        return window->sessions()->openFile(file) && lc::test::waitForCpuImage(*window, 60000);
    }
    // A data scene copied into the test's folder with a smaller image (the same scene, faster).
    bool openSmallCopy(const char* name, int width, int height) {
        Json::Value small = lc::io::EditableScene::load((kData + name).toStdString()).document();
        small["camera"]["width"] = width;
        small["camera"]["height"] = height;
        const fs::path file = folder / name;
        std::ofstream(file) << small.toStyledString();
        return open(QString::fromStdString(file.string()));
    }
    // Edits from the properties dock are queued: the render they start begins once events run.
    bool renderedAfterEdit() {
        QApplication::processEvents();
        return lc::test::waitForCpuImage(*window);
    }
    template <class W>
    W* openedWindow(const char* name) {
        for (int round = 0; round < 50; ++round) {
            for (QWidget* w : QApplication::topLevelWidgets())
                if (w->objectName() == name && w->isVisible()) return qobject_cast<W*>(w);
            QTest::qWait(20);
        }
        return nullptr;
    }
    std::unique_ptr<lc::gui::MainWindow> window;
    fs::path folder;
};

// A static observer at r0 = 20 M on the x axis looking at a Schwarzschild hole (M = 1).
constexpr double kR0 = 20;
const char* const kSchwarzschildScene = R"({
  "metric": {"name": "schwarzschild", "M": 1.0},
  "observer": {"position": [0, 20, 0, 0]},
  "camera": {"projection": "pinhole", "width": 160, "height": 80, "fov": [70, 35], "forward": [-1, 0, 0], "up": [0, 0, 1]},
  "sky": {"type": "checker", "cells": [36, 18]},
  "render": {"stepper": "dopri5", "tolerance": 1e-10}
})";

// The angle between pixel (i, j)'s ray and the inward radial direction (the camera's forward).
double angleFromForward(const lc::Scene& scene, int i, int j) {
    const lc::Camera cam = lc::frameCamera(scene);
    return std::acos(std::clamp(cam.direction(i, j).normalized().dot(cam.forward.normalized()), -1.0, 1.0));
}

double numberAfter(const QString& text, const QString& label) {
    const auto m = QRegularExpression(QRegularExpression::escape(label) + " ?([-0-9.e+]+)").match(text);
    return m.hasMatch() ? m.captured(1).toDouble() : NAN;
}

TEST_F(WorkbenchPanels, AccuracyDockShowsTheRenderAndThePickedRayAgainstSyngesFormulas) {
    const fs::path file = folder / "schwarzschild.json";
    std::ofstream(file) << kSchwarzschildScene;
    window->resize(1400, 860);
    window->docks()->resetLayout();
    window->findChild<QDockWidget*>("accuracyDock")->raise();
    ASSERT_TRUE(open(QString::fromStdString(file.string()))) << window->report()->lastError().toStdString();
    const lc::Scene& scene = window->activeScene()->scene().scene();
    const QString figures = window->docks()->accuracyPanel()->renderText();
    EXPECT_TRUE(figures.contains("schwarzschild, dopri5 tol 1.0e-10")) << figures.toStdString();
    EXPECT_LT(numberAfter(figures, "worst null-condition drift |H| ="), 1e-6) << figures.toStdString();
    // The render's error in pixels (sampled rays traced again 100 times tighter): far below a pixel at 1e-10.
    EXPECT_LT(numberAfter(figures, "estimated error: escape directions within"), 1e-3) << figures.toStdString();
    // The shadow: the rays that end on the horizon are those inside Synge's angle (pixels whose
    // centre lies within half a pixel of the edge may go either way).
    const double lapse = std::sqrt(1 - 2 / kR0), critical = std::asin(3 * std::sqrt(3.0) * lapse / kR0);
    const double pixelAngle = 70.0 / 160 * lc::kPi / 180;
    int inside = 0, edge = 0;
    for (int j = 0; j < 80; ++j)
        for (int i = 0; i < 160; ++i) {
            const double a = angleFromForward(scene, i, j);
            if (std::abs(a - critical) < 0.75 * pixelAngle)
                ++edge;
            else
                inside += a < critical;
        }
    const double horizon = numberAfter(figures, "horizon=");
    EXPECT_GE(horizon, inside) << figures.toStdString();
    EXPECT_LE(horizon, inside + edge) << figures.toStdString();
    EXPECT_EQ(horizon + numberAfter(figures, "escaped="), 160 * 80) << figures.toStdString();
    // Each stop that occurred in words (#46: "max_affine=169312" was jargon), only those.
    EXPECT_TRUE(figures.contains("horizon: it fell through a horizon: the shadow")) << figures.toStdString();
    EXPECT_TRUE(figures.contains("escaped: the ray left for the sky")) << figures.toStdString();
    EXPECT_FALSE(figures.contains("max_affine:")) << figures.toStdString();

    // Picks through real clicks: one ray into the hole, one past it.
    struct Pick {
        int i, j;
        const char* end;
    };
    for (const Pick& p : {Pick{84, 42, "horizon"}, Pick{140, 40, "escaped"}}) {
        SCOPED_TRACE(p.end);
        const double a = angleFromForward(scene, p.i, p.j);
        ASSERT_EQ(a < critical, std::string(p.end) == "horizon") << "the pixel is on the wrong side of the edge";
        QTest::mouseClick(window->docks()->imageView(), Qt::LeftButton, Qt::NoModifier,
                          window->docks()->imageView()->widgetPointOfPixel(p.i, p.j));
        QApplication::processEvents();
        const QString pick = window->docks()->accuracyPanel()->pickText();
        ASSERT_TRUE(pick.contains(
            QString("pixel (%1, %2)").arg(window->selection()->pickedI()).arg(window->selection()->pickedJ())))
            << pick.toStdString();
        EXPECT_TRUE(pick.contains(QString("traced to the end: ") + p.end)) << pick.toStdString();
        // L_z / E: the observer's frame has e1 radial, e2 along y, e3 along z there; |L_z| = r0 |p^2|.
        const lc::Vec3 n = lc::frameCamera(scene)
                               .direction(window->selection()->pickedI(), window->selection()->pickedJ())
                               .normalized();
        // Its sign: the light arrives from n, so it moves along -n; at (r0, 0, 0) L_z = x p_y has the
        // sign of -n_y (the literature's convention, L_z = p_phi, E = -p_t).
        EXPECT_NEAR(numberAfter(pick, "L_z/E ="), -kR0 * n(1) / lapse, 1e-6) << pick.toStdString();
        EXPECT_TRUE(pick.contains("steps, |H| drift")) << pick.toStdString();
        if (std::string(p.end) == "escaped") {
            const double deflection = numberAfter(pick, "deflection");
            EXPECT_GT(deflection, 0) << pick.toStdString();
            EXPECT_LT(deflection, lc::kPi) << pick.toStdString();
        }
    }
    // docs/GUI.md's screenshot of the accuracy dock (and the r-phi dock saying why it is empty).
    EXPECT_TRUE(lc::test::saveScreenshot(*window, "gui_accuracy.png"));
}

// #46 item 1: a crowded scene keeps the workbench near the command line's memory (3000 spheres
// once took it from 0.5 to 10 GB), and a big file is read off the GUI thread with Cancel.
TEST_F(WorkbenchPanels, CrowdedAndBigScenesKeepMemoryBoundedAndTheWindowAnswering) {
    ASSERT_TRUE(openSmallCopy("default.json", 48, 16));
    const double before = lc::test::residentMiB();
    const fs::path crowded = folder / "crowded.json";
    std::ofstream(crowded) << lc::test::crowdedGodelScene(3000, 0);
    ASSERT_TRUE(open(QString::fromStdString(crowded.string())));
    // The views draw 24 objects one by one and the others together; no shader preview (its
    // photo-objects, 3000 x 100 x 200 vertices, would take 21 GB): the CPU's closed form draws.
    EXPECT_EQ(window->docks()->rPhiDiagramDock()->diagram()->numberOfObjectsSummarised(), 3000 - 24);
    EXPECT_EQ(window->docks()->spacetimeView()->view()->GetNumberOfObjectsSummarised(), 3000 - 24);
    EXPECT_EQ(window->renderer()->imageSource(), "cpu");
    const double crowdedMiB = lc::test::residentMiB();
    EXPECT_LT(crowdedMiB - before, 250) << before << " MiB before, " << crowdedMiB << " MiB with 3000 spheres";
    // Picking an object beyond the first 24 draws it in full in the 3D view.
    window->docks()->spacetimeView()->view()->SetSelectedObject(2500);
    EXPECT_EQ(window->docks()->spacetimeView()->view()->GetNumberOfObjectsSummarised(), 3000 - 25);

    // 2048 travellers on world lines (2.3 MB): read in the background, the views say so at once.
    const fs::path big = folder / "travellers.json";
    std::ofstream(big) << lc::test::crowdedGodelScene(2048, 12);
    ASSERT_GT(fs::file_size(big), lc::gui::SessionReactions::kReadInBackgroundBytes);
    ASSERT_TRUE(window->sessions()->openFile(QString::fromStdString(big.string())));
    EXPECT_TRUE(window->sessions()->reading()->running());
    EXPECT_TRUE(window->docks()->imageView()->notice().startsWith("reading travellers.json"))
        << window->docks()->imageView()->notice().toStdString();
    EXPECT_EQ(window->docks()->imagesTable()->rowCount(), 0);  // the old scene's rows go at once
    QApplication::processEvents();
    EXPECT_TRUE(window->progress()->cancelButton()->isVisible());
    QTest::mouseClick(window->progress()->cancelButton(), Qt::LeftButton);
    EXPECT_FALSE(window->sessions()->reading()->running());
    EXPECT_TRUE(window->report()->statusText().contains("cancelled: the scene shown is still crowded.json"))
        << window->report()->statusText().toStdString();
    EXPECT_EQ(window->activeScene()->sceneFile(), QString::fromStdString(crowded.string()));

    // Read again to the end: the window answers meanwhile, the long lists wait to be expanded, and
    // the render is refused before it allocates, with its estimate. The cancelled read finishes
    // first (a new read waits for it) and adopts nothing: one scene arrives.
    QSignalSpy adopted(window->activeScene(), &lc::gui::ActiveScene::replaced);
    ASSERT_TRUE(window->sessions()->openFile(QString::fromStdString(big.string())));
    int ticks = 0;
    QTimer ticker;
    QObject::connect(&ticker, &QTimer::timeout, [&] { ++ticks; });
    ticker.start(20);
    QElapsedTimer t;
    t.start();
    while (window->activeScene()->sceneFile() != QString::fromStdString(big.string()) && t.elapsed() < 60000)
        QTest::qWait(20);
    ASSERT_EQ(window->activeScene()->sceneFile(), QString::fromStdString(big.string()));
    EXPECT_GT(ticks, 5) << "the window did not answer while the scene was read";
    EXPECT_EQ(adopted.count(), 1);
    QTreeWidgetItem* objects = nullptr;
    for (int k = 0; k < window->docks()->properties()->tree()->topLevelItemCount(); ++k)
        if (window->docks()->properties()->tree()->topLevelItem(k)->text(0) == "objects")
            objects = window->docks()->properties()->tree()->topLevelItem(k);
    ASSERT_NE(objects, nullptr);
    EXPECT_EQ(objects->childCount(), 0);
    EXPECT_EQ(objects->text(1), "2048 elements (expand to list them)");
    objects->setExpanded(true);
    EXPECT_EQ(objects->childCount(), 2048);
    ASSERT_NE(window->docks()->properties()->itemOf("objects[2000].radius"), nullptr);
    t.restart();
    while (window->report()->messageText().isEmpty() && t.elapsed() < 60000) QTest::qWait(20);
    EXPECT_TRUE(window->report()->messageText().contains("photo-objects (2048 objects, windings 2) would hold about"))
        << window->report()->messageText().toStdString();
    const double bigMiB = lc::test::residentMiB();
    EXPECT_LT(bigMiB - before, 900) << before << " MiB before, " << bigMiB << " MiB with the 2048 travellers";
    std::printf("resident: %.0f MiB (default scene), %.0f MiB (3000 spheres), %.0f MiB (2048 travellers, %.1f MB)\n",
                before, crowdedMiB, bigMiB, fs::file_size(big) / 1e6);
}

// #46 item 8: View > Compare. Pinned (Ctrl+Shift+P), the ball then grown: side by side shows this
// image on the left pixel for pixel and the pinned one on the right; the difference's largest
// value and differing pixels are those of the two images; blinking alternates; Off restores.
TEST_F(WorkbenchPanels, CompareShowsThePinnedImageBesideAsDifferenceAndBlinking) {
    window->renderer()->setShadersEnabled(false, false);  // CPU images: the same on every machine
    ASSERT_TRUE(openSmallCopy("default.json", 48, 16));
    lc::gui::RenderComparison* compare = window->comparison();
    auto modeAction = [&](int mode) { return window->findChild<QAction*>(QString("compareMode%1").arg(mode)); };
    ASSERT_NE(modeAction(1), nullptr);
    modeAction(1)->trigger();  // nothing pinned yet: refused, the menu back on Off
    EXPECT_EQ(compare->mode(), lc::gui::RenderComparison::Off);
    EXPECT_TRUE(modeAction(0)->isChecked());
    EXPECT_TRUE(window->report()->messageText().contains("pin an image first"));

    lc::gui::EgocentricImageWidget* view = window->docks()->imageView();
    view->setFocus();
    QTest::keyClick(view, Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
    ASSERT_TRUE(compare->hasPinned());
    EXPECT_TRUE(window->report()->messageText().isEmpty()) << "the pin mended the refusal";
    const std::vector<float> pinned = window->renderer()->shownImage();
    std::vector<std::array<unsigned char, 3>> pinnedShown;
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 48; ++i) pinnedShown.push_back(view->shownColour(i, j));
    ASSERT_TRUE(window->activeScene()->edit({{"objects[0].radius", Json::Value(0.4)}}, "radius"));
    ASSERT_TRUE(renderedAfterEdit());
    const std::vector<float> now = window->renderer()->shownImage();
    std::vector<std::array<unsigned char, 3>> nowShown;
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 48; ++i) nowShown.push_back(view->shownColour(i, j));

    modeAction(1)->trigger();  // side by side
    ASSERT_EQ(view->imageWidth(), 48 + 4 + 48);
    int mismatches = 0;
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 48; ++i) {
            mismatches += view->shownColour(i, j) != nowShown[j * 48 + i];
            mismatches += view->shownColour(52 + i, j) != pinnedShown[j * 48 + i];
        }
    EXPECT_EQ(mismatches, 0);
    EXPECT_TRUE(lc::test::saveScreenshot(*window, "gui_compare_side_by_side.png"));  // docs/GUI.md
    // A click on the left half picks this image's pixel.
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->widgetPointOfPixel(10, 8));
    QApplication::processEvents();
    EXPECT_EQ(window->selection()->pickedI(), 10);

    modeAction(2)->trigger();  // difference
    double largest = 0;
    long differing = 0;
    for (std::size_t p = 0; p < now.size() / 3; ++p) {
        bool differs = false;
        for (int c = 0; c < 3; ++c) {
            const double d = std::abs(double(now[3 * p + c]) - double(pinned[3 * p + c]));
            largest = std::max(largest, d);
            differs = differs || d > 1e-6;
        }
        differing += differs;
    }
    EXPECT_GT(differing, 0);
    EXPECT_DOUBLE_EQ(compare->largestDifference(), largest);
    EXPECT_EQ(compare->differingPixels(), differing);
    EXPECT_EQ(view->imageWidth(), 48);

    modeAction(3)->trigger();  // blink: the pinned image, then this one, twice a second
    QElapsedTimer t;
    t.start();
    while (!compare->blinkShowsPinned() && t.elapsed() < 3000) QTest::qWait(20);
    ASSERT_TRUE(compare->blinkShowsPinned());
    EXPECT_EQ(view->shownColour(20, 8), pinnedShown[8 * 48 + 20]);
    while (compare->blinkShowsPinned() && t.elapsed() < 6000) QTest::qWait(20);
    EXPECT_FALSE(compare->blinkShowsPinned());

    modeAction(0)->trigger();
    EXPECT_EQ(view->imageWidth(), 48);
    EXPECT_EQ(view->shownColour(20, 8), nowShown[8 * 48 + 20]);
}

TEST_F(WorkbenchPanels, AccuracyDockSaysWhenTheRenderWasCancelled) {
    ASSERT_TRUE(window->sessions()->openFile(kData + "kerr.json"));
    EXPECT_TRUE(window->docks()->accuracyPanel()->renderText().contains("rendering"));
    QTest::qWait(100);
    ASSERT_TRUE(window->renderer()->rendering());
    QTest::mouseClick(window->progress()->cancelButton(), Qt::LeftButton);
    QElapsedTimer t;
    t.start();
    while (!window->docks()->accuracyPanel()->renderText().contains("cancelled") && t.elapsed() < 10000)
        QTest::qWait(20);
    EXPECT_FALSE(window->renderer()->rendering());
    EXPECT_TRUE(window->docks()->accuracyPanel()->renderText().contains("cancelled"))
        << window->docks()->accuracyPanel()->renderText().toStdString();
}

TEST_F(WorkbenchPanels, NonGodelSceneShowsWhyThereIsNoRPhiDiagram) {
    ASSERT_TRUE(open(kData + "kerr.json"));
    EXPECT_TRUE(window->docks()->diagramNote().contains("'kerr'")) << window->docks()->diagramNote().toStdString();
    auto* note = window->findChild<QLabel*>("diagramNote");
    ASSERT_NE(note, nullptr);
    EXPECT_TRUE(note->isVisible());
    EXPECT_EQ(note->text(), window->docks()->diagramNote());
    EXPECT_TRUE(window->docks()->trDiagramDock()->note().contains("'kerr'"))
        << window->docks()->trDiagramDock()->note().toStdString();
    EXPECT_TRUE(window->docks()->trDiagramDock()->windowTitle().contains("Goedel only"));
    ASSERT_TRUE(open(kData + "default.json"));
    EXPECT_TRUE(window->docks()->diagramNote().isEmpty());
    EXPECT_FALSE(note->isVisible());
    EXPECT_TRUE(window->docks()->trDiagramDock()->note().isEmpty());
}

// The r-phi diagram keeps equal scales (the horizon r = 2a a circle) at every size of its dock,
// and the plot fills the dock (the legend is on demand).
TEST_F(WorkbenchPanels, RPhiDockKeepsEqualScalesAtEverySize) {
    ASSERT_TRUE(open(kData + "default.json"));
    lc::gui::DiagramWidget* diagram = window->docks()->diagramView();
    for (const QSize size : {QSize(1280, 800), QSize(1600, 700), QSize(1000, 900)}) {
        SCOPED_TRACE(size.width());
        window->resize(size);
        QTest::qWait(100);  // the resize events, then the chart's own layout
        vtkAxis* x = diagram->chart()->GetAxis(vtkAxis::BOTTOM);
        vtkAxis* y = diagram->chart()->GetAxis(vtkAxis::LEFT);
        const double perPixelX = (x->GetMaximum() - x->GetMinimum()) / (x->GetPoint2()[0] - x->GetPoint1()[0]);
        const double perPixelY = (y->GetMaximum() - y->GetMinimum()) / (y->GetPoint2()[1] - y->GetPoint1()[1]);
        EXPECT_NEAR(perPixelX / perPixelY, 1.0, 0.02);
        for (vtkAxis* axis : {x, y}) {  // the horizon, r = 2a, inside the plot
            EXPECT_LE(axis->GetMinimum(), -2.0);
            EXPECT_GE(axis->GetMaximum(), 2.0);
        }
        // All but the dock's title bar and margins (no legend below the plot).
        EXPECT_GE(diagram->height(), window->findChild<QDockWidget*>("diagramDock")->height() - 48);
    }
}

// A pick on an image of the ball highlights its light path in the t-r dock, ending at the emission
// event: at the emission time the CPU renderer found for that pixel (closed form), on the ball.
TEST_F(WorkbenchPanels, TrDockShowsThePickedLightPathAndItsEmissionEvent) {
    window->resize(1400, 860);
    window->docks()->resetLayout();
    ASSERT_TRUE(open(kData + "default.json"));
    window->docks()->trDiagramDock()->raise();
    QApplication::processEvents();
    const lc::RenderResult& r = window->renderer()->cpuImage()->records;
    auto objectAt = [&](int i, int j) {
        return r.pixels[static_cast<std::size_t>(j) * r.width + i].kind == lc::PixelRecord::Object;
    };
    int pi = -1, pj = -1;
    for (int j = 2; j + 2 < r.height && pi < 0; ++j)
        for (int i = 2; i + 2 < r.width && pi < 0; ++i)
            if (objectAt(i, j) && objectAt(i - 2, j) && objectAt(i + 2, j) && objectAt(i, j - 2) && objectAt(i, j + 2))
                pi = i, pj = j;
    ASSERT_GE(pi, 0) << "no image of the ball in the default scene";
    QTest::mouseClick(window->docks()->imageView(), Qt::LeftButton, Qt::NoModifier,
                      window->docks()->imageView()->widgetPointOfPixel(pi, pj));
    QApplication::processEvents();
    ASSERT_GE(window->selection()->pickedI(), 0);
    const lc::PixelRecord& picked =
        r.pixels[static_cast<std::size_t>(window->selection()->pickedJ()) * r.width + window->selection()->pickedI()];
    ASSERT_EQ(picked.kind, lc::PixelRecord::Object);
    lc::gui::DiagramWidget* tr = window->docks()->trDiagramDock()->diagram();
    ASSERT_NE(tr->highlightPlot(), nullptr);
    ASSERT_NE(tr->emissionPlot(), nullptr);
    vtkTable* path = tr->highlightPlot()->GetInput();
    const vtkIdType last = path->GetNumberOfRows() - 1;
    auto at = [&](const char* column, vtkIdType row) {
        return vtkDoubleArray::SafeDownCast(path->GetColumnByName(column))->GetValue(row);
    };
    const lc::Scene& scene = window->activeScene()->scene().scene();
    const lc::Vec4 emission(at("t", last), at("x", last), at("y", last), at("z", last));
    // Drawn where the t-r diagram draws events: r = sqrt(X^2 + Y^2) across, the scene's t up.
    EXPECT_NEAR(at("plot_x", last), std::hypot(emission(1), emission(2)), 1e-12);
    EXPECT_NEAR(at("plot_y", last), emission(0) + scene.observer(0), 1e-12);
    EXPECT_NEAR(at("plot_y", 0), scene.observer(0), 1e-9);  // it starts at the observation event
    // The emission event is the one the CPU renderer found, on the ball's surface.
    EXPECT_NEAR(at("plot_y", last), picked.emissionTime, 1e-5);  // the record holds floats
    const lc::Vec4 world = lc::gui::observerChartToWorld(scene, emission);
    const lc::SphereObject& ball = scene.spheres.at(static_cast<std::size_t>(picked.object));
    EXPECT_NEAR(ball.placement->toLocal(world).norm(), ball.radius, 1e-3);  // the ball's own (rest) coordinates
    vtkTable* marker = tr->emissionPlot()->GetInput();
    EXPECT_EQ(marker->GetNumberOfRows(), 1);
    EXPECT_EQ(marker->GetValue(0, 1).ToDouble(), at("plot_y", last));
    // docs/GUI.md's screenshot of the t-r dock.
    EXPECT_TRUE(lc::test::saveScreenshot(*window, "gui_tr_dock.png"));
    // The legend: off in the dock (the plot fills it), on with a click on its check box: a list
    // beside the plot with every labelled curve (the picked path's too), the plot keeping most of
    // the dock's width (#46: the chart's own legend once took all of it).
    EXPECT_FALSE(tr->chart()->GetShowLegend());
    lc::gui::DiagramDock* trDock = window->docks()->trDiagramDock();
    QCheckBox* legend = trDock->legendToggle();
    const int plotWidth = tr->width();
    QTest::mouseClick(legend, Qt::LeftButton, Qt::NoModifier, QPoint(8, legend->height() / 2));
    QApplication::processEvents();
    ASSERT_TRUE(trDock->legendList()->isVisible());
    EXPECT_FALSE(tr->chart()->GetShowLegend());
    const auto entries = tr->legendEntries();
    ASSERT_GE(entries.size(), 4u);
    ASSERT_EQ(trDock->legendList()->count(), static_cast<int>(entries.size()));
    bool pathListed = false;
    for (int k = 0; k < trDock->legendList()->count(); ++k)
        pathListed = pathListed || trDock->legendList()->item(k)->text() == entries.back().label;
    EXPECT_TRUE(pathListed);
    EXPECT_GE(tr->width(), plotWidth / 2) << "the legend took the plot's room";
    EXPECT_GT(trDock->legendList()->width(), 80);
    EXPECT_TRUE(lc::test::saveWidgetScreenshot(trDock, "gui_tr_dock_legend.png"));  // docs/GUI.md
    QTest::mouseClick(legend, Qt::LeftButton, Qt::NoModifier, QPoint(8, legend->height() / 2));
    EXPECT_FALSE(trDock->legendList()->isVisible());
}

// View > Shadow outline, clicked in the menu bar: the outline of the Schwarzschild scene's shadow
// drawn over the image lies on Synge's circle (every point's direction at Synge's angle from
// forward, to the overlay's tolerance), the status bar gives its solid angle 2 pi (1 - cos a_c);
// a scene that casts no shadow says so; unchecking removes the curve. The Kerr infall scene gives
// docs/GUI.md's screenshot.
TEST_F(WorkbenchPanels, ShadowOutlineOverTheImageLiesOnSyngesCircle) {
    const fs::path file = folder / "schwarzschild.json";
    std::ofstream(file) << kSchwarzschildScene;
    window->resize(1400, 860);
    ASSERT_TRUE(open(QString::fromStdString(file.string()))) << window->report()->lastError().toStdString();
    QMenuBar* bar = window->menuBar();
    QAction* viewMenu = nullptr;
    for (QAction* a : bar->actions())
        if (a->text() == "&View") viewMenu = a;
    ASSERT_NE(viewMenu, nullptr);
    QTest::mouseClick(bar, Qt::LeftButton, Qt::NoModifier, bar->actionGeometry(viewMenu).center());
    QMenu* menu = viewMenu->menu();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(menu));
    QAction* outlineAction = window->findChild<QAction*>("shadowOutlineAction");
    ASSERT_NE(outlineAction, nullptr);
    QTest::mouseClick(menu, Qt::LeftButton, Qt::NoModifier, menu->actionGeometry(outlineAction).center());
    lc::gui::ShadowOutlineOverlay* overlay = window->shadowOutline();
    ASSERT_TRUE(overlay->shown());
    QElapsedTimer clock;
    clock.start();
    while ((overlay->tracing() || !overlay->outline()) && clock.elapsed() < 30000) QTest::qWait(20);
    ASSERT_NE(overlay->outline(), nullptr) << overlay->message().toStdString();
    const auto& curves = window->docks()->imageView()->curves();
    ASSERT_FALSE(curves.empty());
    const lc::Scene& scene = window->activeScene()->scene().scene();
    const lc::Camera cam = lc::frameCamera(scene);
    const double critical = std::asin(3 * std::sqrt(3.0) * std::sqrt(1 - 2 / kR0) / kR0);
    std::size_t points = 0;
    for (const auto& curve : curves)
        for (const auto& p : curve) {
            // Continuous image coordinates back to a direction: pixel (i, j)'s centre is (i + 0.5, j + 0.5).
            const lc::Vec3 d = cam.direction(p[0] - 0.5, p[1] - 0.5).normalized();
            EXPECT_NEAR(std::acos(std::clamp(d.dot(cam.forward.normalized()), -1.0, 1.0)), critical, 1e-5 * critical);
            ++points;
        }
    EXPECT_EQ(points, std::size_t(lc::gui::ShadowOutlineOverlay::kPoints) + 1);  // closed: the first point again
    const double omega = 2 * lc::kPi * (1 - std::cos(critical));
    EXPECT_NEAR(overlay->outline()->solidAngle, omega, 1e-5 * omega);
    EXPECT_TRUE(overlay->message().contains(QString::number(overlay->outline()->solidAngle, 'g', 6)))
        << overlay->message().toStdString();

    // The Kerr infall scene: the outline over its image, for docs/GUI.md.
    ASSERT_TRUE(open(kData + "kerr_infall.json")) << window->report()->lastError().toStdString();
    clock.restart();
    while ((overlay->tracing() || !overlay->outline()) && clock.elapsed() < 30000) QTest::qWait(20);
    ASSERT_NE(overlay->outline(), nullptr) << overlay->message().toStdString();
    EXPECT_FALSE(window->docks()->imageView()->curves().empty());
    EXPECT_TRUE(lc::test::saveScreenshot(*window, "gui_shadow_outline.png"));

    // Goedel casts no shadow: said, nothing drawn.
    ASSERT_TRUE(open(kData + "default.json"));
    clock.restart();
    while (!overlay->message().contains("casts no shadow") && clock.elapsed() < 10000) QTest::qWait(20);
    EXPECT_TRUE(overlay->message().contains("godel casts no shadow")) << overlay->message().toStdString();
    EXPECT_TRUE(window->docks()->imageView()->curves().empty());
    outlineAction->trigger();  // unchecked
    EXPECT_FALSE(overlay->shown());
    EXPECT_TRUE(window->docks()->imageView()->curves().empty());
}

// The heading block of `section` on the guide's page, and whether the view shows it at its top.
bool sectionAtTop(QTextBrowser* browser, const QString& section) {
    for (QTextBlock block = browser->document()->begin(); block.isValid(); block = block.next())
        if (block.blockFormat().headingLevel() > 0 && block.text() == section) {
            const double top = browser->document()->documentLayout()->blockBoundingRect(block).top() -
                               browser->verticalScrollBar()->value();
            return top >= -1 && top < browser->viewport()->height() / 3.0;
        }
    return false;
}

QString tooltipOf(lc::gui::PropertiesPanel* panel, const QString& field) {
    QTreeWidgetItem* item = panel->itemOf(field);
    return item ? item->toolTip(1) : QString("no field " + field);
}

TEST_F(WorkbenchPanels, GuideOpensAtTheScenesKindOrTheFieldsSectionSearchesAndShortcutsListTheMenus) {
    ASSERT_TRUE(openSmallCopy("kerr_disk.json", 48, 24));
    lc::gui::PropertiesPanel* panel = window->docks()->properties();
    // Tooltips: the unit and chart of every event, the disk's temperature as its hottest ring.
    const QString position = tooltipOf(panel, "observer.position");
    for (const char* words : {"(t, x, y, z)", "Kerr-Schild", "units of M", "accepted: ", "F1: the guide"})
        EXPECT_TRUE(position.contains(words)) << words << " not in " << position.toStdString();
    const QString temperature = tooltipOf(panel, "objects[0].temperature");
    EXPECT_TRUE(temperature.contains("maximum") && temperature.contains("kelvin")) << temperature.toStdString();
    // A grey default lists its choices, the default first.
    const QString stepper = tooltipOf(panel, "render.stepper");
    EXPECT_TRUE(stepper.contains("choices: auto (default")) << stepper.toStdString();
    for (const char* name : {"rk4", "dopri5", "dopri87", "bulirsch_stoer"}) EXPECT_TRUE(stepper.contains(name));
    EXPECT_TRUE(tooltipOf(panel, "objects[0].sense").contains("prograde (default), retrograde"));

    // F1 away from the properties: the page of the scene's kind.
    window->docks()->imageView()->setFocus();
    QTest::keyClick(window.get(), Qt::Key_F1);
    auto* guide = openedWindow<lc::gui::GuideWindow>("guideDialog");
    ASSERT_NE(guide, nullptr) << "F1 opened no guide";
    EXPECT_EQ(guide->currentPage(), "black_holes.md");
    QTextBrowser* browser = guide->browser();
    EXPECT_TRUE(browser->toPlainText().startsWith("Black holes and accretion disks"))
        << browser->toPlainText().left(80).toStdString();
    EXPECT_EQ(guide->pageList()->count(), 5);
    // Written for users: no test names or source files; every image loads and fits the window.
    int images = 0;
    for (int k = 0; k < guide->pageList()->count(); ++k) {
        guide->pageList()->setCurrentRow(k);
        QApplication::processEvents();
        const QString text = browser->toPlainText();
        EXPECT_FALSE(text.contains(QRegularExpression(R"(\.cpp|\.hpp|tests/|[A-Z][a-z]+\.[A-Z][A-Za-z]+[A-Z])")))
            << guide->currentPage().toStdString();
        for (QTextBlock block = browser->document()->begin(); block.isValid(); block = block.next())
            for (auto it = block.begin(); !it.atEnd(); ++it) {
                if (!it.fragment().charFormat().isImageFormat()) continue;
                const QTextImageFormat image = it.fragment().charFormat().toImageFormat();
                EXPECT_FALSE(browser->loadResource(QTextDocument::ImageResource, QUrl(image.name())).isNull())
                    << image.name().toStdString();
                EXPECT_GT(image.width(), 0) << image.name().toStdString();
                EXPECT_LE(image.width(), browser->viewport()->width()) << image.name().toStdString();
                ++images;
            }
    }
    EXPECT_GE(images, 4);
    guide->close();
    QApplication::setActiveWindow(window.get());  // the guide had the focus: shortcuts need the window active

    // F1 on a property: its section, at the top of the view.
    QTreeWidget* tree = panel->tree();
    const auto f1On = [&](const char* field) {
        QApplication::setActiveWindow(window.get());
        tree->setCurrentItem(panel->itemOf(field), 1);
        tree->setFocus();
        QTest::keyClick(tree, Qt::Key_F1);
        return openedWindow<lc::gui::GuideWindow>("guideDialog");
    };
    guide = f1On("objects[0].temperature");
    ASSERT_NE(guide, nullptr);
    EXPECT_EQ(guide->currentPage(), "black_holes.md");
    EXPECT_TRUE(sectionAtTop(browser, "The accretion disk"));
    guide->close();
    guide = f1On("render.tolerance");
    ASSERT_NE(guide, nullptr);
    EXPECT_EQ(guide->currentPage(), "index.md");
    EXPECT_TRUE(sectionAtTop(browser, "Render settings"));

    // Search: typed in the field, the pages that hold it with their counts, marked in the page.
    QLineEdit* search = guide->searchField();
    search->setFocus();
    QTest::keyClicks(search, "ergoregion");
    EXPECT_GE(guide->pageList()->count(), 1);
    EXPECT_LT(guide->pageList()->count(), 5);
    for (int k = 0; k < guide->pageList()->count(); ++k)
        EXPECT_TRUE(guide->pageList()->item(k)->text().contains(QRegularExpression(R"(\([1-9][0-9]*\)$)")));
    EXPECT_EQ(browser->textCursor().selectedText().toLower(), "ergoregion");
    EXPECT_GE(browser->extraSelections().size(), 1);
    EXPECT_TRUE(lc::test::saveWidgetScreenshot(guide, "gui_guide_search.png"));
    const int first = browser->textCursor().position();
    if (browser->extraSelections().size() > 1) {
        QTest::keyClick(search, Qt::Key_Return);
        EXPECT_GT(browser->textCursor().position(), first);
        QTest::keyClick(search, Qt::Key_Return, Qt::ShiftModifier);
        EXPECT_EQ(browser->textCursor().position(), first);
    }
    search->clear();
    QTest::keyClicks(search, "xyzzy-nowhere");
    EXPECT_EQ(guide->pageList()->count(), 0);
    EXPECT_TRUE(guide->searchSummary()->text().contains("in no page")) << guide->searchSummary()->text().toStdString();
    search->clear();
    EXPECT_EQ(guide->pageList()->count(), 5);
    guide->close();
    QApplication::setActiveWindow(window.get());

    // A field with choices is edited by picking one (the list is editable: typed text still works).
    tree->setCurrentItem(panel->itemOf("render.stepper"), 1);
    tree->setFocus();
    QTest::keyClick(tree, Qt::Key_F2);
    QComboBox* choice = nullptr;
    for (auto* c : tree->viewport()->findChildren<QComboBox*>("choiceEditor"))
        if (c->isVisible()) choice = c;
    ASSERT_NE(choice, nullptr) << "F2 on render.stepper opened no list of choices";
    EXPECT_GE(choice->findText("dopri87"), 0);
    choice->setCurrentIndex(choice->findText("dopri87"));
    QTest::keyClick(choice, Qt::Key_Return);
    for (int round = 0; round < 3; ++round) QApplication::processEvents();
    EXPECT_EQ(window->activeScene()->scene().document()["render"]["stepper"].asString(), "dopri87");
    // A word where the field holds numbers is the word (an observer's name for its 4-velocity).
    Json::Value fourVelocity(Json::arrayValue), typed;
    for (double u : {1.0, 0.0, 0.0, 0.0}) fourVelocity.append(u);
    ASSERT_TRUE(lc::gui::PropertiesPanel::parse("zamo", fourVelocity, typed));
    EXPECT_EQ(typed, Json::Value("zamo"));

    // F1 with a value's editor open: that field's section.
    QApplication::setActiveWindow(window.get());
    tree->setCurrentItem(panel->itemOf("camera.fov"), 1);
    tree->setFocus();
    QTest::keyClick(tree, Qt::Key_F2);
    QWidget* editor = QApplication::focusWidget();
    ASSERT_TRUE(editor && tree->isAncestorOf(editor)) << "F2 opened no editor in the tree";
    QTest::keyClick(editor, Qt::Key_F1);
    guide = openedWindow<lc::gui::GuideWindow>("guideDialog");
    ASSERT_NE(guide, nullptr);
    EXPECT_EQ(guide->currentPage(), "black_holes.md");
    EXPECT_TRUE(sectionAtTop(browser, "The observer and the camera"));
    guide->close();

    // Help > Keyboard shortcuts, clicked in the menu bar.
    QMenuBar* bar = window->menuBar();
    QAction* helpMenu = nullptr;
    for (QAction* a : bar->actions())
        if (a->text() == "&Help") helpMenu = a;
    ASSERT_NE(helpMenu, nullptr);
    QTest::mouseClick(bar, Qt::LeftButton, Qt::NoModifier, bar->actionGeometry(helpMenu).center());
    QMenu* menu = helpMenu->menu();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(menu));
    QAction* shortcuts = nullptr;
    for (QAction* a : menu->actions())
        if (a->text().contains("shortcuts")) shortcuts = a;
    ASSERT_NE(shortcuts, nullptr);
    QTest::mouseClick(menu, Qt::LeftButton, Qt::NoModifier, menu->actionGeometry(shortcuts).center());
    auto* dialog = openedWindow<QDialog>("shortcutsDialog");
    ASSERT_NE(dialog, nullptr) << "the menu opened no shortcuts window";
    auto* table = dialog->findChild<QTableWidget*>("shortcutsTable");
    ASSERT_NE(table, nullptr);
    QStringList rows;
    for (int r = 0; r < table->rowCount(); ++r) rows << table->item(r, 0)->text() + " = " + table->item(r, 1)->text();
    const QString all = rows.join("\n");
    EXPECT_TRUE(
        all.contains("File > Open scene... = " + QKeySequence(QKeySequence::Open).toString(QKeySequence::NativeText)))
        << all.toStdString();
    EXPECT_TRUE(all.contains("View > Reset view = Ctrl+R")) << all.toStdString();
    EXPECT_TRUE(all.contains("Image: drag")) << all.toStdString();
}

// #46 item 4: at 1280 x 800 every dock tab shows its whole title (the four left of the image on the
// dock's edge) and the images table shows four images whole (the default scene's two windings),
// each column its whole text, in the fifth of the window's height it had.
TEST_F(WorkbenchPanels, DockTabsAndTheImagesTableShowTheirWholeText) {
    ASSERT_TRUE(openSmallCopy("default.json", 96, 32));
    window->docks()->resetLayout();
    QApplication::processEvents();
    window->selection()->selectionModel()->selectObject(0);
    QApplication::processEvents();
    lc::gui::ImagesTable* table = window->docks()->imagesTable();
    ASSERT_GE(table->rowCount(), 4);
    const int last = std::min(table->rowCount(), 4) - 1;
    EXPECT_LE(table->rowViewportPosition(last) + table->rowHeight(last), table->viewport()->height())
        << "row " << last + 1 << " of " << table->rowCount() << " is cut; viewport " << table->viewport()->height();
    for (int c = 0; c < table->columnCount(); ++c) {
        EXPECT_GE(table->columnWidth(c), table->horizontalHeader()->sectionSizeHint(c)) << "column " << c;
        for (int r = 0; r < table->rowCount(); ++r)
            if (const QTableWidgetItem* item = table->item(r, c)) {
                EXPECT_GE(table->columnWidth(c), table->fontMetrics().horizontalAdvance(item->text()))
                    << "column " << c << " row " << r;
            }
    }
    // The diagrams' titles are longest for a scene that has none.
    ASSERT_TRUE(openSmallCopy("kerr.json", 48, 24));
    QApplication::processEvents();
    int tabs = 0;
    for (QTabBar* bar : window->findChildren<QTabBar*>()) {
        if (!bar->isVisible()) continue;
        for (int k = 0; k < bar->count(); ++k) {
            // Along the text: across a tab on top, down one on the dock's edge.
            const QRect room = bar->tabRect(k);
            const int along = bar->shape() == QTabBar::RoundedWest ? room.height() : room.width();
            EXPECT_GE(along, bar->fontMetrics().horizontalAdvance(bar->tabText(k)) + 8)
                << bar->tabText(k).toStdString();
            // ... and the whole tab in sight (not scrolled away behind the bar's arrows).
            EXPECT_EQ(bar->visibleRegion().intersected(room), QRegion(room)) << bar->tabText(k).toStdString();
            ++tabs;
        }
    }
    EXPECT_GE(tabs, 6);  // Properties, Post-rendering, Accuracy, Metric editor; r-phi and t-r
    // A long text value is whole in its tooltip.
    const QString description = tooltipOf(window->docks()->properties(), "description");
    EXPECT_TRUE(description.contains(
        QString::fromStdString(window->activeScene()->scene().document()["description"].asString())))
        << description.toStdString();
}

TEST_F(WorkbenchPanels, ExportAndSaveDialogsStartBesideTheScene) {
    const fs::path file = folder / "schwarzschild.json";
    std::ofstream(file) << kSchwarzschildScene;
    ASSERT_TRUE(open(QString::fromStdString(file.string())));
    // Ctrl+E: the export dialog, inspected and closed from inside its own event loop.
    QString selected;
    QTimer::singleShot(300, [&] {
        for (int round = 0; round < 100 && !qobject_cast<QFileDialog*>(QApplication::activeModalWidget()); ++round)
            QTest::qWait(20);
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog) return;
        selected = dialog->selectedFiles().value(0);
        dialog->reject();
    });
    QTest::keyClick(window.get(), Qt::Key_E, Qt::ControlModifier);
    EXPECT_EQ(fs::path(selected.toStdString()), folder / "schwarzschild.png") << selected.toStdString();
    EXPECT_EQ(fs::path(window->activeScene()->besideScene("diagram.svg").toStdString()), folder / "schwarzschild.svg");
    EXPECT_EQ(fs::path(window->activeScene()->besideScene("lightcone-export").toStdString()),
              folder / "schwarzschild-lightcone-export");
}

}  // namespace

// ---- edits that change what the scene holds (#26 item 2) ----------------------------------------

namespace {

// The Schwarzschild scene above with another metric line.
std::string withMetric(const std::string& metric) {
    std::string text = kSchwarzschildScene;
    const std::string from = R"("metric": {"name": "schwarzschild", "M": 1.0})";
    text.replace(text.find(from), from.size(), metric);
    return text;
}

// Pixels the CPU render ends on the horizon, and Synge's bounds for them (as in the accuracy test).
struct ShadowCount {
    int horizon = 0, inside = 0, edge = 0;
};
ShadowCount shadowOf(const lc::Scene& scene, const lc::ColouredImage& image) {
    const double critical = std::asin(3 * std::sqrt(3.0) * std::sqrt(1 - 2 / kR0) / kR0);
    const double pixelAngle = 70.0 / 160 * lc::kPi / 180;
    ShadowCount c;
    for (int j = 0; j < 80; ++j)
        for (int i = 0; i < 160; ++i) {
            const double a = angleFromForward(scene, i, j);
            if (std::abs(a - critical) < 0.75 * pixelAngle)
                ++c.edge;
            else
                c.inside += a < critical;
            c.horizon += image.records.pixels[static_cast<std::size_t>(j) * 160 + i].kind == lc::PixelRecord::Horizon;
        }
    return c;
}

}  // namespace

TEST_F(WorkbenchPanels, MetricChooserChangesTheMetricInOneUndoableEdit) {
    const fs::path file = folder / "kerr.json";
    std::ofstream(file) << withMetric(R"("metric": {"name": "kerr", "M": 1.0, "a": 0.9})");
    ASSERT_TRUE(open(QString::fromStdString(file.string()))) << window->report()->lastError().toStdString();
    QComboBox* chooser = window->docks()->properties()->metricChooser();
    ASSERT_EQ(chooser->currentText(), "kerr");
    const int undoBefore = window->activeScene()->undoStack()->count();
    // The key a user presses on the chooser: the metric listed above Kerr.
    chooser->setFocus();
    QTest::keyClick(chooser, Qt::Key_Up);
    ASSERT_TRUE(renderedAfterEdit());
    const lc::Scene& scene = window->activeScene()->scene().scene();
    EXPECT_EQ(scene.spacetime->name(), "schwarzschild");
    EXPECT_EQ(scene.spacetime->parameters().at("a"), 0.0) << "the new metric's defaults, not Kerr's spin";
    EXPECT_EQ(window->activeScene()->undoStack()->count(), undoBefore + 1);
    EXPECT_EQ(window->activeScene()->undoStack()->undoText(), "metric schwarzschild");
    ASSERT_NE(window->docks()->properties()->itemOf("metric.M"), nullptr);
    EXPECT_EQ(window->docks()->properties()->itemOf("metric.a"), nullptr) << "Kerr's spin is gone from the tree";
    // What is drawn is Schwarzschild's: the shadow within Synge's angle.
    const ShadowCount shadow = shadowOf(scene, *window->renderer()->cpuImage());
    EXPECT_GE(shadow.horizon, shadow.inside);
    EXPECT_LE(shadow.horizon, shadow.inside + shadow.edge);

    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    ASSERT_TRUE(renderedAfterEdit());
    EXPECT_EQ(window->activeScene()->scene().scene().spacetime->name(), "kerr");
    EXPECT_EQ(window->activeScene()->scene().scene().spacetime->parameters().at("a"), 0.9);
    EXPECT_EQ(chooser->currentText(), "kerr");
    EXPECT_EQ(window->activeScene()->scene().document(), window->activeScene()->scene().original());
}

// The chooser lists the catalogue (#43): every file of data/metrics with the gallery's thumbnail
// and its summary as tooltip. Opened with a click and an item clicked in its list, a catalogue
// file becomes the scene's metric in one undoable edit, and the chooser shows it as that item.
TEST_F(WorkbenchPanels, MetricChooserListsTheCatalogueWithThumbnailsAndTakesOne) {
    const fs::path file = folder / "kerr.json";
    std::ofstream(file) << withMetric(R"("metric": {"name": "kerr", "M": 1.0, "a": 0.9})");
    ASSERT_TRUE(open(QString::fromStdString(file.string()))) << window->report()->lastError().toStdString();
    QComboBox* chooser = window->docks()->properties()->metricChooser();
    std::set<QString> onDisk, listed;
    for (const auto& e : fs::directory_iterator(fs::path(LIGHTCONE_SOURCE_DIR) / "data" / "metrics"))
        if (e.path().extension() == ".json") onDisk.insert(QString::fromStdString(e.path().filename().string()));
    int ellis = -1;
    for (int k = 0; k < chooser->count(); ++k) {
        if (!chooser->itemText(k).endsWith(".json")) continue;
        listed.insert(chooser->itemText(k));
        EXPECT_FALSE(chooser->itemIcon(k).isNull()) << chooser->itemText(k).toStdString() << " has no thumbnail";
        if (chooser->itemText(k) == "ellis_wormhole.json") ellis = k;
    }
    EXPECT_EQ(listed, onDisk) << "the chooser lists every metric file of data/metrics";
    ASSERT_GE(ellis, 0);
    EXPECT_TRUE(chooser->itemData(ellis, Qt::ToolTipRole).toString().contains("Ellis-Bronnikov wormhole"));

    const int undoBefore = window->activeScene()->undoStack()->count();
    QTest::mouseClick(chooser, Qt::LeftButton);  // opens the list
    QAbstractItemView* list = chooser->view();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(list->window()));
    list->scrollTo(chooser->model()->index(ellis, 0));
    QApplication::processEvents();
    EXPECT_TRUE(lc::test::saveWidgetScreenshot(list->window(), "gui_metric_catalogue.png"));
    const QRect row = list->visualRect(chooser->model()->index(ellis, 0));
    // The list ignores a release that comes sooner than a double click after it opened (the
    // release of the click that opened it); a user's next click comes later.
    QTest::qWait(QApplication::doubleClickInterval() + 50);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier, row.center());
    ASSERT_TRUE(renderedAfterEdit());
    const lc::Scene& scene = window->activeScene()->scene().scene();
    EXPECT_EQ(scene.spacetime->name(), "ellis-wormhole");
    EXPECT_TRUE(scene.spacetime->hasOtherEnd()) << "the file's other_end came with it";
    EXPECT_EQ(chooser->currentText(), "ellis_wormhole.json");
    EXPECT_EQ(window->activeScene()->undoStack()->count(), undoBefore + 1);
    EXPECT_EQ(window->activeScene()->undoStack()->undoText(), "metric ellis_wormhole.json");

    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    ASSERT_TRUE(renderedAfterEdit());
    EXPECT_EQ(window->activeScene()->scene().scene().spacetime->name(), "kerr");
    EXPECT_EQ(chooser->currentText(), "kerr");
}

// The chooser's "formula file..." (the key End on the chooser): a file dialog, a file name typed
// and Return, and the metric written as text (data/metrics/kerr.json, a = 0.9 by default) becomes
// the scene's in one undoable edit. The image is the built-in Kerr's: the same pixel kinds.
TEST_F(WorkbenchPanels, MetricChooserTakesAFormulaFile) {
    const fs::path file = folder / "kerr.json";
    std::ofstream(file) << withMetric(R"("metric": {"name": "kerr", "M": 1.0, "a": 0.9})");
    ASSERT_TRUE(open(QString::fromStdString(file.string()))) << window->report()->lastError().toStdString();
    const std::vector<lc::PixelRecord> builtin = window->renderer()->cpuImage()->records.pixels;
    QComboBox* chooser = window->docks()->properties()->metricChooser();
    const int undoBefore = window->activeScene()->undoStack()->count();
    chooser->setFocus();
    QTest::keyClick(chooser, Qt::Key_End);
    for (int round = 0; round < 50 && !window->metrics()->fileDialog(); ++round) QTest::qWait(20);
    QFileDialog* dialog = window->metrics()->fileDialog();
    ASSERT_NE(dialog, nullptr) << "the chooser's last item asks for a metric file";
    const QPointer<QFileDialog> openDialog(dialog);  // deleted when it closes
    EXPECT_EQ(fs::path(dialog->directory().absolutePath().toStdString()), folder) << "beside the scene";
    EXPECT_EQ(chooser->currentText(), "kerr") << "the scene's metric until a file is chosen";
    auto* name = dialog->findChild<QLineEdit*>("fileNameEdit");
    ASSERT_NE(name, nullptr);
    // The dialog's file-name completion pops up while typing, sometimes only after the last key
    // (it lists the folder asynchronously), and then takes the Return (a user dismisses it first).
    // It is not what this test checks: off, so the typed name and the Return reach the dialog.
    name->setCompleter(nullptr);
    // A user goes to the folder first, then types the file's name: a whole path typed at once makes
    // the dialog move into its folder when the listing arrives, and that clears the typed name (a
    // loaded run saw the name field empty after Return). The folder is listed before typing.
    auto* listing = dialog->findChild<QFileSystemModel*>();
    ASSERT_NE(listing, nullptr);
    const QString metricsFolder = QDir(kData + "metrics").absolutePath();
    bool listed = false;
    QObject::connect(listing, &QFileSystemModel::directoryLoaded, dialog,
                     [&](const QString& path) { listed = listed || QDir(path).absolutePath() == metricsFolder; });
    dialog->setDirectory(metricsFolder);
    QElapsedTimer loading;
    loading.start();
    while (!listed && loading.elapsed() < 10000) QTest::qWait(20);
    EXPECT_TRUE(listed) << "the dialog never listed " << metricsFolder.toStdString();
    QTest::keyClicks(name, "kerr.json");
    // The dialog enables Open only once its file-system model has listed the typed file's folder
    // (asynchronously; seconds on a loaded machine); a Return before that does nothing. A user
    // presses it when the button is enabled: so does the test.
    auto* buttons = dialog->findChild<QDialogButtonBox*>("buttonBox");
    ASSERT_NE(buttons, nullptr);
    QPushButton* openButton = buttons->button(QDialogButtonBox::Open);
    ASSERT_NE(openButton, nullptr);
    QElapsedTimer enabling;
    enabling.start();
    while (!openButton->isEnabled() && enabling.elapsed() < 10000) QTest::qWait(20);
    EXPECT_TRUE(openButton->isEnabled()) << "the dialog never took the typed file name";
    // A completion list the dialog may still pop up takes the Return (a run on a loaded machine
    // pressed it and nothing happened): a user closes it first.
    if (QWidget* popup = QApplication::activePopupWidget()) QTest::keyClick(popup, Qt::Key_Escape);
    QTest::keyClick(name, Qt::Key_Return);
    // The dialog's accept reaches the metric reaction through the event loop: on a loaded machine
    // the edit may come after the first events run, so wait for it (not a fixed time) first.
    QElapsedTimer accepted;
    accepted.start();
    while (window->activeScene()->undoStack()->count() == undoBefore && accepted.elapsed() < 10000) QTest::qWait(20);
    ASSERT_NE(window->activeScene()->undoStack()->count(), undoBefore)
        << "no edit 10 s after Return; the dialog is " << (openDialog ? "still open" : "closed")
        << ", its name field says '" << (openDialog ? name->text().toStdString() : std::string("-")) << "'";
    ASSERT_TRUE(renderedAfterEdit());
    const lc::Scene& scene = window->activeScene()->scene().scene();
    EXPECT_EQ(scene.spacetime->name(), "kerr-formula");
    EXPECT_EQ(scene.spacetime->parameters().at("a"), 0.9);
    EXPECT_EQ(window->activeScene()->undoStack()->count(), undoBefore + 1);
    EXPECT_EQ(window->activeScene()->undoStack()->undoText(), "metric kerr.json");
    EXPECT_EQ(chooser->currentText(), "kerr.json") << "a file of the catalogue is shown as its item";
    const std::vector<lc::PixelRecord>& formula = window->renderer()->cpuImage()->records.pixels;
    ASSERT_EQ(formula.size(), builtin.size());
    std::size_t differ = 0;
    for (std::size_t k = 0; k < formula.size(); ++k) differ += formula[k].kind != builtin[k].kind;
    EXPECT_LE(differ, builtin.size() / 200) << "pixel kinds of the formula Kerr against the built-in's";

    window->activateWindow();  // the dialog had it: shortcuts need the active window
    (void)QTest::qWaitForWindowActive(window.get(), 2000);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    ASSERT_TRUE(renderedAfterEdit());
    EXPECT_EQ(window->activeScene()->scene().scene().spacetime->name(), "kerr");
    EXPECT_EQ(chooser->currentText(), "kerr");
}

// The metric editor: a formula typed with a mistake is refused by the scene reader and the mistake
// is underlined where it is (the reader's field and column mapped into the text), a JSON syntax
// error at its line and column; the text's own undo takes the mistake back, Apply renders the
// formula in one undoable edit (the text stays as typed), and Edit > Undo brings the built-in
// back. The screenshot for docs/GUI.md shows a refusal.
TEST_F(WorkbenchPanels, MetricEditorMarksErrorsWhereTheyAreAndAppliesUndoably) {
    const fs::path file = folder / "kerr.json";
    std::ofstream(file) << withMetric(R"("metric": {"name": "kerr", "M": 1.0, "a": 0.9})");
    ASSERT_TRUE(open(QString::fromStdString(file.string()))) << window->report()->lastError().toStdString();
    lc::gui::MetricEditor* editor = window->docks()->metricEditor();
    window->docks()->metricEditorDock()->raise();
    EXPECT_TRUE(editor->captionText().contains("built-in 'kerr'")) << editor->captionText().toStdString();
    const int undoBefore = window->activeScene()->undoStack()->count();

    std::ifstream in(kData.toStdString() + "metrics/kerr.json");
    const QString kerr = QString::fromStdString(std::string(std::istreambuf_iterator<char>(in), {}));
    editor->text()->setFocus();
    editor->text()->selectAll();
    QTest::keyClick(editor->text(), Qt::Key_Delete);
    editor->text()->insertPlainText(kerr);
    // A typo typed where f is used in the line element: "ff*(dt".
    const int typo = kerr.indexOf("f*(dt");
    ASSERT_GT(typo, 0);
    QTextCursor cursor = editor->text()->textCursor();
    cursor.setPosition(typo);
    editor->text()->setTextCursor(cursor);
    QTest::keyClick(editor->text(), Qt::Key_F);
    QTest::mouseClick(editor->applyButton(), Qt::LeftButton);
    QApplication::processEvents();
    EXPECT_TRUE(editor->problemText().contains("metric.formula.ds2")) << editor->problemText().toStdString();
    EXPECT_TRUE(editor->problemText().contains("unknown name 'ff'")) << editor->problemText().toStdString();
    EXPECT_EQ(editor->problemOffset(), typo) << "the mistake is underlined where it was typed";
    EXPECT_EQ(window->activeScene()->undoStack()->count(), undoBefore);
    EXPECT_EQ(window->activeScene()->scene().scene().spacetime->name(), "kerr");
    EXPECT_TRUE(lc::test::saveScreenshot(*window, "gui_metric_editor.png"));

    // The text's own undo takes the typed letter back; Apply renders the formula.
    QTest::keyClick(editor->text(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(editor->text()->toPlainText(), kerr);
    QTest::mouseClick(editor->applyButton(), Qt::LeftButton);
    ASSERT_TRUE(renderedAfterEdit());
    EXPECT_EQ(editor->problemText(), "");
    EXPECT_EQ(window->activeScene()->scene().scene().spacetime->name(), "kerr-formula");
    EXPECT_EQ(window->activeScene()->scene().scene().spacetime->parameters().at("a"), 0.9)
        << "the scene's value of a parameter the formula also declares";
    EXPECT_EQ(window->activeScene()->undoStack()->count(), undoBefore + 1);
    EXPECT_EQ(window->activeScene()->undoStack()->undoText(), "metric formula");
    EXPECT_EQ(editor->text()->toPlainText(), kerr) << "the text stays as typed";
    EXPECT_EQ(window->docks()->properties()->metricChooser()->currentText(), "formula: kerr-formula");

    // A JSON mistake: the last closing brace deleted.
    QTextCursor end = editor->text()->textCursor();
    end.movePosition(QTextCursor::End);
    editor->text()->setTextCursor(end);
    QTest::keyClick(editor->text(), Qt::Key_Backspace);  // the final newline
    QTest::keyClick(editor->text(), Qt::Key_Backspace);  // the brace
    QTest::mouseClick(editor->applyButton(), Qt::LeftButton);
    QApplication::processEvents();
    EXPECT_TRUE(editor->problemText().startsWith("not JSON: line ")) << editor->problemText().toStdString();
    EXPECT_GE(editor->problemOffset(), editor->text()->toPlainText().size() - 3);
    EXPECT_EQ(window->activeScene()->undoStack()->count(), undoBefore + 1);

    // Edit > Undo: the built-in again, and the editor shows it.
    window->activateWindow();
    window->setFocus();
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    ASSERT_TRUE(renderedAfterEdit());
    EXPECT_EQ(window->activeScene()->scene().scene().spacetime->name(), "kerr");
    EXPECT_TRUE(editor->captionText().contains("built-in 'kerr'")) << editor->captionText().toStdString();
}

// #46 item 3: from the default scene (Goedel, observer at the chart origin) every built-in metric
// chosen in the chooser's list with the keyboard is taken, with an observer it serves (the plan of
// StructuralEdits.MetricChangePlanMovesTheObserverWhereTheNewMetricServesAndSaysWhy), and renders:
// no error, no dialog; what moved is said in the message bar. Undo and redo go through the same
// states without a dialog.
TEST_F(WorkbenchPanels, EveryBuiltInMetricChosenFromTheDefaultSceneRendersWithAnObserverItServes) {
    ASSERT_TRUE(openSmallCopy("default.json", 72, 24)) << window->report()->lastError().toStdString();
    QComboBox* chooser = window->docks()->properties()->metricChooser();
    auto choose = [&](const QString& name) {
        // As a user at the keyboard: Alt+Down opens the list, Home and Down walk to the item (the
        // list takes nothing before Return), Return takes it.
        chooser->setFocus();
        QTest::keyClick(chooser, Qt::Key_Down, Qt::AltModifier);
        QAbstractItemView* list = chooser->view();
        if (!QTest::qWaitForWindowExposed(list->window())) return false;
        QTest::keyClick(list, Qt::Key_Home);
        for (int k = 0; k < chooser->findText(name); ++k) QTest::keyClick(list, Qt::Key_Down);
        if (list->currentIndex().data().toString() != name) return false;
        QTest::keyClick(list, Qt::Key_Return);
        return renderedAfterEdit();
    };
    auto noDialog = [&] {
        for (QWidget* w : QApplication::topLevelWidgets())
            if (w->isVisible() && (w->isModal() || qobject_cast<QMessageBox*>(w))) return false;
        return QApplication::activeModalWidget() == nullptr;
    };
    const lc::gui::StatusReporter* report = window->report();
    for (const char* metric :
         {"minkowski", "schwarzschild", "kerr", "kerr-newman", "alcubierre", "godel-cylindrical"}) {
        SCOPED_TRACE(metric);
        const int undoBefore = window->activeScene()->undoStack()->index();
        ASSERT_TRUE(choose(metric));
        const lc::Scene& scene = window->activeScene()->scene().scene();
        EXPECT_EQ(scene.spacetime->name(), metric);
        EXPECT_EQ(window->activeScene()->undoStack()->index(), undoBefore + 1) << "one undoable edit";
        EXPECT_TRUE(report->lastError().isEmpty()) << report->lastError().toStdString();
        EXPECT_TRUE(noDialog());
        EXPECT_EQ(window->renderer()->cpuImage()->records.width, 72);
        const std::string said = report->messageText().toStdString();
        if (std::string(metric) == "minkowski") {
            EXPECT_TRUE(said.empty()) << said;
        } else {
            EXPECT_NE(said.find("metric " + std::string(metric) + ": the observer"), std::string::npos) << said;
        }
        if (std::string(metric) == "schwarzschild") {
            EXPECT_NE(said.find("moved to (0, -"), std::string::npos) << said;
            // The default scene's ball (r = 1 M) is inside the horizon: the image says so.
            EXPECT_TRUE(window->docks()->imageView()->notice().contains("inside the metric's horizon"))
                << window->docks()->imageView()->notice().toStdString();
            EXPECT_TRUE(lc::test::saveScreenshot(*window, "gui_metric_moved_observer.png"));  // docs/GUI.md's
            // Redo through the moved state: no dialog either.
            QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
            ASSERT_TRUE(renderedAfterEdit());
            QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
            ASSERT_TRUE(renderedAfterEdit());
            EXPECT_EQ(window->activeScene()->scene().scene().spacetime->name(), metric);
            EXPECT_TRUE(noDialog());
        }
        QTest::mouseClick(report->messageCloseButton(), Qt::LeftButton);
        EXPECT_TRUE(report->messageText().isEmpty());
        QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
        ASSERT_TRUE(renderedAfterEdit());
        EXPECT_EQ(window->activeScene()->scene().scene().spacetime->name(), "godel");
        EXPECT_TRUE(noDialog());
        EXPECT_TRUE(report->lastError().isEmpty()) << report->lastError().toStdString();
    }
}

TEST_F(WorkbenchPanels, RefusedMetricRestoresTheTreeAtOnce) {
    ASSERT_TRUE(openSmallCopy("godel_free_fall_earth.json", 220, 25)) << window->report()->lastError().toStdString();
    QComboBox* chooser = window->docks()->properties()->metricChooser();
    const int undoBefore = window->activeScene()->undoStack()->count();
    chooser->setFocus();
    QTest::keyClicks(chooser, "s");  // keyboard search: schwarzschild, where Goedel's free fall is not
    QApplication::processEvents();   // the queued edit
    EXPECT_EQ(chooser->currentText(), "godel") << "the chooser shows the scene's metric again";
    EXPECT_EQ(window->activeScene()->scene().scene().spacetime->name(), "godel");
    EXPECT_EQ(window->activeScene()->undoStack()->count(), undoBefore);
    ASSERT_NE(window->docks()->properties()->itemOf("metric.a"), nullptr);
    EXPECT_EQ(window->docks()->properties()->itemOf("metric.a")->text(1), "1");
    EXPECT_FALSE(window->docks()->properties()->refusalText().isEmpty());
    EXPECT_TRUE(window->report()->statusText().startsWith("refused")) << window->report()->statusText().toStdString();
}

TEST_F(WorkbenchPanels, ObjectsAndLightsAreAddedDuplicatedAndRemovedUndoably) {
    const fs::path file = folder / "schwarzschild.json";
    std::ofstream(file) << kSchwarzschildScene;
    ASSERT_TRUE(open(QString::fromStdString(file.string()))) << window->report()->lastError().toStdString();
    lc::gui::PropertiesPanel* panel = window->docks()->properties();

    QTest::mouseClick(panel->addSphereButton(), Qt::LeftButton);
    ASSERT_TRUE(renderedAfterEdit());
    ASSERT_EQ(window->activeScene()->scene().scene().spheres.size(), 1u);
    EXPECT_EQ(window->activeScene()->scene().scene().spheres[0].name, "sphere-1");
    // 6 M ahead with radius 0.6 M: it covers the centre of the image (angular radius
    // asin(0.6 / 6) = 5.7 degrees as in flat space; the ray to it passes 14 M and more from the
    // hole) and not a pixel 8 degrees off, inside Synge's shadow of 14.3 degrees.
    const lc::Scene& scene = window->activeScene()->scene().scene();
    auto recordAt = [&](double degreesRight) {  // on the middle row, right of the centre
        auto off = [&](int i) { return std::abs(angleFromForward(scene, i, 40) - degreesRight * lc::kPi / 180); };
        int best = 80;
        for (int i = 80; i < 160; ++i)
            if (off(i) < off(best)) best = i;
        return window->renderer()->cpuImage()->records.pixels[40 * 160 + static_cast<std::size_t>(best)];
    };
    EXPECT_EQ(recordAt(0).kind, lc::PixelRecord::Object);
    EXPECT_EQ(recordAt(4).kind, lc::PixelRecord::Object);
    EXPECT_EQ(recordAt(8).kind, lc::PixelRecord::Horizon);

    QTest::mouseClick(panel->addLightButton(), Qt::LeftButton);
    ASSERT_TRUE(renderedAfterEdit());
    ASSERT_EQ(window->activeScene()->scene().scene().lights.size(), 1u);

    // The object's context menu (a real context-menu event on its row): Duplicate.
    auto contextMenuOn = [&](const QString& field, int downs) {
        QTreeWidgetItem* element = panel->itemOf(field)->parent();
        panel->tree()->scrollToItem(element);
        const QPoint at = panel->tree()->visualItemRect(element).center();
        QTimer::singleShot(100, [downs] {
            QWidget* menu = QApplication::activePopupWidget();
            ASSERT_NE(menu, nullptr);
            for (int k = 0; k < downs; ++k) QTest::keyClick(menu, Qt::Key_Down);
            QTest::keyClick(menu, Qt::Key_Return);
        });
        QContextMenuEvent event(QContextMenuEvent::Mouse, at, panel->tree()->viewport()->mapToGlobal(at));
        QApplication::sendEvent(panel->tree()->viewport(), &event);
        QApplication::processEvents();
    };
    contextMenuOn("objects[0].radius", 1);
    ASSERT_TRUE(renderedAfterEdit());
    ASSERT_EQ(window->activeScene()->scene().scene().spheres.size(), 2u);
    EXPECT_EQ(window->activeScene()->scene().scene().spheres[1].name, "sphere-1-copy");
    // Beside the original, not on it: both are seen
    // (StructuralEdits.DuplicateCopiesRightAfterWithAFreeNameBesideTheOriginal).
    std::array<int, 2> seen{};
    for (const lc::PixelRecord& p : window->renderer()->cpuImage()->records.pixels)
        if (p.kind == lc::PixelRecord::Object && p.object >= 0 && p.object < 2)
            ++seen[static_cast<std::size_t>(p.object)];
    EXPECT_GT(seen[0], 20);
    EXPECT_GT(seen[1], 20) << "the copy is hidden behind the original";

    // The light's row clicked, then Ctrl+D.
    QTreeWidgetItem* light = panel->itemOf("lights[0].position")->parent();
    panel->tree()->scrollToItem(light);  // as a user scrolls to it in a 1280 x 800 window
    QTest::mouseClick(panel->tree()->viewport(), Qt::LeftButton, Qt::NoModifier,
                      panel->tree()->visualItemRect(light).center());
    QTest::keyClick(window.get(), Qt::Key_D, Qt::ControlModifier);
    ASSERT_TRUE(renderedAfterEdit());
    ASSERT_EQ(window->activeScene()->scene().scene().lights.size(), 2u);
    EXPECT_EQ(window->activeScene()->scene().scene().lights[1].name, "light-1-copy");

    contextMenuOn("objects[0].radius", 2);  // Remove
    ASSERT_TRUE(renderedAfterEdit());
    ASSERT_EQ(window->activeScene()->scene().scene().spheres.size(), 1u);
    EXPECT_EQ(window->activeScene()->scene().scene().spheres[0].name, "sphere-1-copy");

    EXPECT_EQ(window->activeScene()->undoStack()->undoText(), "remove objects[0]");
    for (int k = 0; k < 5; ++k) QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    ASSERT_TRUE(renderedAfterEdit());
    EXPECT_EQ(window->activeScene()->scene().document(), window->activeScene()->scene().original());
    EXPECT_TRUE(window->activeScene()->scene().scene().spheres.empty());
}

// ---- post-render settings in sessions and exports (#26 item 6) ----------------------------------

TEST_F(WorkbenchPanels, PostRenderSettingsTravelInSessionsAndExports) {
    ASSERT_TRUE(open(kData + "default.json"));
    lc::gui::PostRenderDock* dock = window->docks()->postRenderView();
    window->findChild<QDockWidget*>("postRenderDock")->raise();
    auto click = [](QCheckBox* box) { QTest::mouseClick(box, Qt::LeftButton, {}, QPoint(8, box->height() / 2)); };
    click(dock->enableBox());
    dock->textureChoice()->setFocus();
    QTest::keyClick(dock->textureChoice(), Qt::Key_Down);  // checker
    dock->uOffsetSlider()->setFocus();
    QTest::keyClick(dock->uOffsetSlider(), Qt::Key_PageUp);
    click(dock->temperatureBox());
    ASSERT_TRUE(dock->active());
    ASSERT_EQ(window->renderer()->imageSource(), "post-render");
    const std::vector<unsigned char> gpu = dock->lastSrgb();

    // Export: the post-rendered image, to one 8-bit level of the dock's GPU image (an independent
    // path: vtkLightconePostRenderer against lc::shadePixels), and not the render itself.
    const std::string shaded = (folder / "shaded.png").string(), plain = (folder / "plain.png").string();
    ASSERT_TRUE(window->exports()->exportImage(QString::fromStdString(shaded)))
        << window->report()->lastError().toStdString();
    const lc::io::ImageChannels exported = lc::io::readImageRgb(shaded);
    ASSERT_EQ(exported.data.size(), gpu.size());
    std::size_t far = 0, differsFromRender = 0;
    for (std::size_t k = 0; k < gpu.size(); ++k) {
        far += std::abs(int(gpu[k]) - int(std::lround(255.0f * lc::io::srgbEncode(exported.data[k])))) > 1;
        differsFromRender += std::abs(exported.data[k] - window->renderer()->cpuImage()->rgb[k]) > 0.05f;
    }
    EXPECT_EQ(far, 0u);
    EXPECT_GT(differsFromRender, 1000u) << "the export is the post-rendered image, not the render";

    // The session keeps the controls; opened again it shows and exports the same image.
    const QString session = QString::fromStdString((folder / "shaded.lcsession").string());
    ASSERT_TRUE(window->sessions()->saveSession(session)) << window->report()->lastError().toStdString();
    const lc::io::PostRenderControls saved = dock->controls();
    EXPECT_EQ(lc::io::readSession(session.toStdString()).postRender.texture, "checker");
    click(dock->enableBox());  // off, then the session puts it back
    ASSERT_FALSE(dock->active());
    ASSERT_TRUE(window->exports()->exportImage(QString::fromStdString(plain)));
    ASSERT_TRUE(window->sessions()->openSession(session)) << window->report()->lastError().toStdString();
    ASSERT_TRUE(lc::test::waitForCpuImage(*window, 60000));
    QApplication::processEvents();
    EXPECT_TRUE(dock->controls() == saved);
    EXPECT_EQ(window->renderer()->imageSource(), "post-render");
    EXPECT_EQ(dock->lastSrgb(), gpu);
    const std::string again = (folder / "again.png").string();
    ASSERT_TRUE(window->exports()->exportImage(QString::fromStdString(again)));
    auto bytes = [](const std::string& f) {
        std::ifstream in(f, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_EQ(bytes(again), bytes(shaded));
    EXPECT_NE(bytes(plain), bytes(shaded));
}
// ---- the spacetime view's camera (#26 item 3) ----------------------------------------------------

// Opened on a scene of flat or black-hole spacetime, the 3D view shows all it draws and fills the
// dock: every visible actor's bounds project inside the viewport, spanning at least half of it;
// the fan rays are drawn to their affine length, not stopped at the observer.
TEST_F(WorkbenchPanels, SpacetimeViewFitsItsCameraToWhatItDraws) {
    using View = vtkLightconeSpacetimeView;
    for (const char* file : {"sr_cube.json", "kerr.json"}) {
        SCOPED_TRACE(file);
        ASSERT_TRUE(open(kData + file));
        QApplication::processEvents();
        View* view = window->docks()->spacetimeView()->view();
        vtkRenderer* renderer = view->GetRenderer();
        const int* size = renderer->GetSize();
        ASSERT_GT(size[0], 100);
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        for (int layer = 0; layer < View::NUMBER_OF_LAYERS; ++layer)
            for (vtkActor* actor : view->GetLayerActors(layer)) {
                if (!actor->GetVisibility()) continue;
                const double* b = actor->GetBounds();
                for (int corner = 0; corner < 8; ++corner) {
                    renderer->SetWorldPoint(b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)], 1);
                    renderer->WorldToDisplay();
                    const double* d = renderer->GetDisplayPoint();
                    for (int k = 0; k < 2; ++k) {
                        lo[k] = std::min(lo[k], d[k]);
                        hi[k] = std::max(hi[k], d[k]);
                    }
                }
            }
        EXPECT_GE(lo[0], 0);
        EXPECT_GE(lo[1], 0);
        EXPECT_LE(hi[0], size[0]);
        EXPECT_LE(hi[1], size[1]);
        EXPECT_TRUE(hi[0] - lo[0] > 0.5 * size[0] || hi[1] - lo[1] > 0.5 * size[1])
            << "drawn within x " << lo[0] << ".." << hi[0] << ", y " << lo[1] << ".." << hi[1] << " of " << size[0]
            << " x " << size[1];
        const double* rays = view->GetLayerActors(View::GEODESICS)[0]->GetBounds();
        EXPECT_GT(rays[1] - rays[0], 40) << "the fan rays reach their affine length 60";
    }
}

// ---- the live preview while dragging (#26 item 4) ------------------------------------------------

// A drag moves the image with the hand at once, and the render of the turned camera confirms it:
// a panorama's yaw about its up axis is a circular shift of its columns (equirectangular), so the
// new CPU image is the old one shifted by exactly the preview's shift.
TEST_F(WorkbenchPanels, DragShowsALivePreviewThatTheRenderConfirms) {
    ASSERT_TRUE(open(kData + "default.json"));
    ASSERT_TRUE(
        window->activeScene()->edit({{"camera.width", Json::Value(480)}, {"camera.height", Json::Value(160)}}, "size"));
    ASSERT_TRUE(lc::test::waitForCpuImage(*window));
    const std::vector<lc::PixelRecord> before = window->renderer()->cpuImage()->records.pixels;
    auto* image = window->docks()->imageView();
    const QPoint from = image->widgetPointOfPixel(240, 80), to = image->widgetPointOfPixel(300, 80);
    QTest::mousePress(image, Qt::LeftButton, Qt::NoModifier, from);
    lc::test::dragMoveTo(image, (from + to) / 2);
    EXPECT_NEAR(image->dragPreviewShift().x(), 30, 1.5) << "the image follows the hand before the release";
    lc::test::dragMoveTo(image, to);
    const QPointF shift = image->dragPreviewShift();
    EXPECT_NEAR(shift.x(), 60, 1.5);
    EXPECT_NEAR(shift.y(), 0, 1.5);
    QTest::mouseRelease(image, Qt::LeftButton, Qt::NoModifier, to);
    ASSERT_TRUE(renderedAfterEdit());
    EXPECT_EQ(image->dragPreviewShift(), QPointF(0, 0)) << "the render replaced the preview";
    // The ball's pixels (a few per cent of the panorama) land where the preview put them.
    const std::vector<lc::PixelRecord>& after = window->renderer()->cpuImage()->records.pixels;
    const int dx = static_cast<int>(std::lround(shift.x()));
    std::size_t ball = 0, moved = 0;
    for (int j = 0; j < 160; ++j)
        for (int i = 0; i < 480; ++i) {
            const lc::PixelRecord& was = before[static_cast<std::size_t>(j) * 480 + i];
            if (was.kind != lc::PixelRecord::Object) continue;
            const lc::PixelRecord& now = after[static_cast<std::size_t>(j) * 480 + (i + dx) % 480];
            ++ball;
            moved += now.kind == lc::PixelRecord::Object && std::abs(now.u - was.u) < 0.02f &&
                     std::abs(now.v - was.v) < 0.02f;
        }
    ASSERT_GT(ball, 100u);
    EXPECT_GT(moved, 0.95 * ball) << "the rendered image is the preview's shift of the old one";
}

// ---- the render job: no state that waits for nothing (#26 item 1, found by the monkey test) ---------

// Cancel while a new job waits for an old worker to stop: the waiting job is cancelled too, and
// the job says so (before, running() stayed true with no worker: every later pick waited forever).
TEST_F(WorkbenchPanels, CancelWhileTheNewJobWaitsForTheOldWorkerEndsBoth) {
    lc::io::EditableScene kerr = lc::io::EditableScene::load((kData + "kerr.json").toStdString());
    lc::gui::RenderJob job;
    int cancelled = 0, finished = 0;
    QObject::connect(&job, &lc::gui::RenderJob::cancelled, [&] { ++cancelled; });
    QObject::connect(&job, &lc::gui::RenderJob::finished, [&] { ++finished; });
    job.start(kerr.scene());
    job.start(kerr.scene());  // waits for the first worker, which is told to stop
    ASSERT_TRUE(job.running());
    job.cancel();
    QElapsedTimer t;
    t.start();
    while ((job.running() || cancelled == 0) && t.elapsed() < 10000) QTest::qWait(10);
    EXPECT_FALSE(job.running());
    EXPECT_EQ(cancelled, 1);
    EXPECT_EQ(finished, 0);
    // And the job takes the next one as always.
    lc::io::EditableScene small = kerr;
    small.apply({{"camera.width", Json::Value(48)}, {"camera.height", Json::Value(24)}});
    job.start(small.scene());
    t.restart();
    while (job.running() && t.elapsed() < 60000) QTest::qWait(10);
    EXPECT_EQ(finished, 1);
}
