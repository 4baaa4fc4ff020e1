// SPDX-License-Identifier: BSD-3-Clause
// The Lightcone workbench (app/gui) through real Qt events under Xvfb: opening every scene of
// data/, editing in the properties dock (accepted and refused), undo, picking with the linked
// r-phi diagram (observer moved, freely falling body), the images table, sessions (round trip,
// malformed, moved scene), exports equal to the CLI's, Cancel, the event loop during a numeric
// Kerr render, and the unsaved-changes prompt. Oracles: the scene reader (refusals), closed-form
// Goedel geodesics and world lines (paths end on the object), the CLI's own files (exports),
// the image before the edit (undo, sessions). Needs an X display (ctest runs under xvfb-run).
#include "workbench_test_support.hpp"

#include "diagram_chart.hpp"
#include "egocentric_image_widget.hpp"
#include "images_table.hpp"
#include "light_path.hpp"
#include "post_render_dock.hpp"
#include "accuracy_panel.hpp"
#include "main_window.hpp"
#include "observer_time_slider.hpp"
#include "properties_panel.hpp"
#include "diagram_widget.hpp"
#include "filters_from_scene.hpp"
#include "selection_model.hpp"
#include "spacetime_view_dock.hpp"
#include "vtkLightconeKillingFieldSource.h"
#include "vtkLightconeSpacetimeView.h"

#include "app/commands/commands.hpp"
#include "core/scene/frame_camera.hpp"
#include "core/godel/geodesic.hpp"
#include "core/godel/images.hpp"
#include "core/godel/isometry.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "tests/common/spacetime_view_checks.hpp"

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QHeaderView>
#include <QLineEdit>
#include <QMouseEvent>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QRegularExpression>
#include <QTest>
#include <QTimer>
#include <QToolTip>
#include <QTreeWidget>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkActor.h>
#include <vtkAxis.h>
#include <vtkCellData.h>
#include <vtkChartXY.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkPlot.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkVolume.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <cstring>
#include <set>
#include <map>
#include <memory>

namespace fs = std::filesystem;

namespace {

using lc::test::kData;

std::string fileBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

struct TempFolder {
    fs::path path;
    TempFolder() {
        path = fs::temp_directory_path() / ("lc-gui-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempFolder() { fs::remove_all(path); }
    QString operator/(const char* name) const { return QString::fromStdString((path / name).string()); }
};

using lc::test::dragMoveTo;
using lc::test::timeScale;
using lc::test::waitForCpuImage;

const lc::PixelRecord& record(const lc::gui::MainWindow& w, int i, int j) {
    const auto& r = w.renderer()->cpuImage()->records;
    return r.pixels[static_cast<std::size_t>(j) * r.width + i];
}

// A pixel deep inside the largest image of `object` (all four neighbours show it too).
bool innerObjectPixel(const lc::RenderResult& r, int object, int& pi, int& pj) {
    std::map<int, std::pair<long, std::pair<double, double>>> byTime;  // images differ in emission time
    auto objectAt = [&](int i, int j) {
        const auto& p = r.pixels[static_cast<std::size_t>(j) * r.width + i];
        return p.kind == lc::PixelRecord::Object && p.object == object;
    };
    for (int j = 1; j + 1 < r.height; ++j)
        for (int i = 1; i + 1 < r.width; ++i)
            if (objectAt(i, j) && objectAt(i + 1, j) && objectAt(i - 1, j) && objectAt(i, j + 1) &&
                objectAt(i, j - 1)) {
                auto& b = byTime[static_cast<int>(
                    std::floor(4 * r.pixels[static_cast<std::size_t>(j) * r.width + i].emissionTime))];
                ++b.first;
                b.second.first += i;
                b.second.second += j;
            }
    if (byTime.empty()) return false;
    auto best = byTime.begin();
    for (auto it = byTime.begin(); it != byTime.end(); ++it)
        if (it->second.first > best->second.first) best = it;
    const double ci = best->second.second.first / best->second.first,
                 cj = best->second.second.second / best->second.first;
    double bestD = 1e300;
    for (int j = 1; j + 1 < r.height; ++j)
        for (int i = 1; i + 1 < r.width; ++i)
            if (objectAt(i, j) && objectAt(i + 1, j) && objectAt(i - 1, j) && objectAt(i, j + 1) &&
                objectAt(i, j - 1) &&
                static_cast<int>(std::floor(4 * r.pixels[static_cast<std::size_t>(j) * r.width + i].emissionTime)) ==
                    best->first) {
                const double d = (i - ci) * (i - ci) + (j - cj) * (j - cj);
                if (d < bestD) bestD = d, pi = i, pj = j;
            }
    return true;
}

// Types `text` into the value cell of `field` in the properties dock: select it, F2 opens the
// editor, the keys replace the text, Return commits.
void typeIntoField(lc::gui::MainWindow& w, const QString& field, const QString& text) {
    QTreeWidget* tree = w.docks()->properties()->tree();
    QTreeWidgetItem* item = w.docks()->properties()->itemOf(field);
    ASSERT_NE(item, nullptr) << "no field " << field.toStdString() << " in the properties dock";
    w.docks()->properties()->parentWidget()->show();
    tree->scrollToItem(item);
    tree->setCurrentItem(item, 1);
    tree->setFocus();
    QTest::keyClick(tree, Qt::Key_F2);
    QLineEdit* editor = nullptr;  // an earlier editor may wait for its deferred deletion
    for (auto* e : tree->viewport()->findChildren<QLineEdit*>())
        if (e->isVisible()) editor = e;
    ASSERT_NE(editor, nullptr) << "F2 opened no editor for " << field.toStdString();
    editor->selectAll();
    QTest::keyClicks(editor, text);
    QTest::keyClick(editor, Qt::Key_Return);
    // The delegate commits on a queued call and the window takes the edit on another (it rebuilds
    // the tree): two rounds of posted events.
    for (int round = 0; round < 3; ++round) QApplication::processEvents();
}

// Clicks the centre of pixel (i, j) and returns the pixel the window picked in (i, j): the same
// one, or a neighbour where the view shows the image smaller than one screen pixel per pixel.
void clickPixel(lc::gui::MainWindow& w, int& i, int& j) {
    auto* image = w.docks()->imageView();
    const QPoint at = image->widgetPointOfPixel(i, j);
    ASSERT_TRUE(image->rect().contains(at)) << "pixel (" << i << ", " << j << ") maps outside the widget";
    QTest::mouseClick(image, Qt::LeftButton, Qt::NoModifier, at);
    QApplication::processEvents();
    ASSERT_GE(w.selection()->pickedI(), 0) << "the click picked nothing";
    EXPECT_LE(std::abs(w.selection()->pickedI() - i) + std::abs(w.selection()->pickedJ() - j),
              image->width() >= w.renderer()->cpuImage()->records.width ? 0 : 2);
    i = w.selection()->pickedI();
    j = w.selection()->pickedJ();
}

// The column and row of an accretion disk's brightest pixel (largest observed intensity).
std::pair<int, int> brightestDiskPixel(const lc::RenderResult& data) {
    std::size_t brightest = 0;
    for (std::size_t k = 0; k < data.pixels.size(); ++k)
        if (data.pixels[k].kind == lc::PixelRecord::Disk && data.pixels[k].intensity > data.pixels[brightest].intensity)
            brightest = k;
    return {static_cast<int>(brightest % data.width), static_cast<int>(brightest / data.width)};
}

// The highlighted path's last sample in the world chart (columns t, x, y, z of the plot's table).
bool highlightEnd(lc::gui::MainWindow& w, lc::Vec4& endWorld, lc::Vec4& startObserverChart) {
    vtkPlot* plot = w.docks()->diagramView()->highlightPlot();
    if (!plot || !plot->GetInput() || plot->GetInput()->GetNumberOfRows() < 10) return false;
    vtkTable* table = plot->GetInput();
    auto col = [&](const char* name, vtkIdType row) {
        return vtkDoubleArray::SafeDownCast(table->GetColumnByName(name))->GetValue(row);
    };
    const vtkIdType last = table->GetNumberOfRows() - 1;
    startObserverChart = lc::Vec4(col("t", 0), col("x", 0), col("y", 0), col("z", 0));
    endWorld = lc::gui::observerChartToWorld(w.activeScene()->scene().scene(),
                                             lc::Vec4(col("t", last), col("x", last), col("y", last), col("z", last)));
    return true;
}

using SpacetimeView = vtkLightconeSpacetimeView;

using lc::test::drawnPoints;
using lc::test::executions;
using lc::test::runsSince;

// Clicks a layer's checkbox in the spacetime dock.
void clickToggle(lc::gui::MainWindow& w, int layer) {
    QCheckBox* box = w.docks()->spacetimeView()->layerToggle(layer);
    QTest::mouseClick(box, Qt::LeftButton, Qt::NoModifier, QPoint(8, box->height() / 2));
    QApplication::processEvents();
}

// The widget position of the r-phi diagram's point (x, y), from the chart's axes: each spans its
// data range between its end points in scene pixels, whose y grows upwards (Qt's downwards).
QPoint widgetPointOfDiagramPoint(lc::gui::DiagramWidget* diagram, double x, double y) {
    auto scene = [](vtkAxis* axis, int c, double v) {
        const double f = (v - axis->GetMinimum()) / (axis->GetMaximum() - axis->GetMinimum());
        return axis->GetPoint1()[c] + f * (axis->GetPoint2()[c] - axis->GetPoint1()[c]);
    };
    const double ratio = diagram->devicePixelRatioF();
    const double sx = scene(diagram->chart()->GetAxis(vtkAxis::BOTTOM), 0, x);
    const double sy = scene(diagram->chart()->GetAxis(vtkAxis::LEFT), 1, y);
    return {static_cast<int>(std::lround(sx / ratio)),
            static_cast<int>(std::lround(diagram->height() - 1 - sy / ratio))};
}

// Data units per widget pixel along the diagram's x axis.
double diagramPixel(lc::gui::DiagramWidget* diagram) {
    vtkAxis* axis = diagram->chart()->GetAxis(vtkAxis::BOTTOM);
    return (axis->GetMaximum() - axis->GetMinimum()) * diagram->devicePixelRatioF() /
           (axis->GetPoint2()[0] - axis->GetPoint1()[0]);
}

// The highlighted ray of the 3D view: its last point (t, x, y, z) in the world chart.
lc::Vec4 highlightedRayEnd(SpacetimeView* view) {
    vtkPolyData* ray = view->GetHighlightedRay();
    const vtkIdType last = ray->GetNumberOfPoints() - 1;
    double xyz[3];
    ray->GetPoint(last, xyz);
    return {ray->GetPointData()->GetArray("t")->GetTuple1(last), xyz[0], xyz[1], xyz[2]};
}

class Workbench : public ::testing::Test {
protected:
    void SetUp() override {
        window = std::make_unique<lc::gui::MainWindow>();
        ASSERT_TRUE(lc::test::showWorkbench(*window));  // active: shortcuts need it (the undo test checks)
    }
    void TearDown() override {
        if (window) {
            window->activeScene()->undoStack()->setClean();  // no prompt when the fixture closes it
            window->close();
        }
    }
    void open(const QString& file) {
        ASSERT_TRUE(window->sessions()->openFile(file)) << window->report()->lastError().toStdString();
        ASSERT_TRUE(waitForCpuImage(*window)) << "no CPU render of " << file.toStdString();
    }
    std::unique_ptr<lc::gui::MainWindow> window;
};

// #46 item 4: the window opens within the screen, centred: 1400 x 860 where there is room, the
// whole of a 1280 x 720 laptop screen's available area otherwise, which its docks' minimum sizes
// fit, with the image at least its minimum size.
TEST(WorkbenchWindow, OpensWithinTheScreenDownTo1280By720) {
    lc::gui::MainWindow big;
    big.fitInto(QRect(0, 0, 1920, 1080));
    EXPECT_EQ(big.size(), QSize(1400, 860));
    EXPECT_EQ(big.pos(), QPoint(260, 110));
    lc::gui::MainWindow small;
    small.fitInto(QRect(0, 24, 1280, 696));  // a 1280 x 720 screen below a 24 px panel
    small.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&small));
    EXPECT_LE(small.minimumSizeHint().width(), 1280);
    EXPECT_LE(small.minimumSizeHint().height(), 696);
    EXPECT_LE(small.width(), 1280);
    EXPECT_LE(small.height(), 696);
    EXPECT_GE(small.y(), 24);
    EXPECT_GE(small.docks()->imageView()->width(), 320);
    EXPECT_GE(small.docks()->imageView()->height(), 160);
    small.close();
}

TEST_F(Workbench, EveryDataSceneOpensWithItsRenderer) {
    struct Case {
        const char* file;
        const char* source;  // what draws the egocentric image
        const char* method;  // render --method auto
    };
    const Case cases[] = {{"default.json", "shaders", "closed_form"},
                          {"godel_many_images.json", "shaders", "closed_form"},
                          {"godel_free_fall_earth.json", "shaders", "per_vertex"},
                          {"godel_lit_sphere.json", "shaders", "closed_form"},
                          {"godel_lit_earth.json", "shaders", "closed_form"},
                          {"godel_time_traveller.json", "shaders", "per_vertex"},
                          {"sr_cube.json", "shaders", ""},
                          {"kerr.json", "shaders", "numeric"},
                          {"kerr_disk.json", "shaders", "numeric"}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.file);
        QElapsedTimer opened;
        opened.start();
        ASSERT_TRUE(window->sessions()->openScene(kData + c.file)) << window->report()->lastError().toStdString();
        while (window->renderer()->imageSource().isEmpty() && opened.elapsed() < 30000) QTest::qWait(5);
        std::printf("[ measured ] %s: first image (%s) %lld ms after Open\n", c.file,
                    window->renderer()->imageSource().toUtf8().data(), static_cast<long long>(opened.elapsed()));
        const lc::Camera& cam = window->activeScene()->scene().scene().camera;
        EXPECT_EQ(window->renderer()->imageSource().toStdString(), c.source);
        EXPECT_EQ(window->renderer()->shownImage().size(), 3u * cam.width * cam.height);
        EXPECT_EQ(window->docks()->imageView()->imageWidth(), cam.width);
        if (std::string(c.method).size()) {
            EXPECT_EQ(lc::renderMethodName(lc::resolveMethod(window->activeScene()->scene().scene())), c.method);
        }
        // The per-pixel data comes from the CPU at a smaller size (an edit: the full-size render
        // of the opened scene is cancelled and replaced).
        std::vector<lc::io::SceneEdit> smaller{{"camera.width", Json::Value(cam.width / 4)},
                                               {"camera.height", Json::Value(cam.height / 4)}};
        if (!window->activeScene()->scene().value("render.mesh_resolution").isNull()) {  // photo-objects of moving
                                                                                         // bodies
            Json::Value coarse(Json::arrayValue);
            coarse.append(16);
            coarse.append(32);
            smaller.push_back({"render.mesh_resolution", coarse});
        }
        ASSERT_TRUE(window->activeScene()->edit(smaller, "smaller"));
        ASSERT_TRUE(waitForCpuImage(*window));
        std::printf("[ measured ] %s: CPU data at 1/4 size %lld ms after Open\n", c.file,
                    static_cast<long long>(opened.elapsed()));
        EXPECT_EQ(window->renderer()->cpuImage()->records.width, cam.width);  // cam is the edited scene's camera now
        EXPECT_GT(
            window->renderer()->cpuImage()->records.stats.rays + window->renderer()->cpuImage()->records.stats.hits,
            0u);
        EXPECT_TRUE(window->report()->lastError().isEmpty()) << window->report()->lastError().toStdString();
        EXPECT_TRUE(window->windowTitle().contains(c.file)) << window->windowTitle().toStdString();
    }
}

TEST_F(Workbench, EditInThePropertiesDockReRendersAndUndoRestoresThePixels) {
    open(kData + "default.json");
    const std::vector<float> before = window->renderer()->shownImage();
    const std::vector<float> cpuBefore = window->renderer()->cpuImage()->rgb;
    EXPECT_FALSE(window->isWindowModified());

    typeIntoField(*window, "objects[0].radius", "0.4");
    ASSERT_TRUE(waitForCpuImage(*window));
    EXPECT_DOUBLE_EQ(window->activeScene()->scene().scene().spheres[0].radius, 0.4);
    EXPECT_NE(window->renderer()->shownImage(), before) << "the image did not change";
    EXPECT_GT(window->renderer()->cpuImage()->records.stats.hits, 0u);
    EXPECT_TRUE(window->isWindowModified());
    EXPECT_TRUE(window->windowTitle().contains("[*]") || window->windowTitle().contains("*"));
    EXPECT_EQ(window->activeScene()->undoStack()->count(), 1);

    ASSERT_TRUE(window->isActiveWindow()) << "shortcuts go to the active window";
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);  // Edit > Undo
    ASSERT_TRUE(waitForCpuImage(*window));
    EXPECT_DOUBLE_EQ(window->activeScene()->scene().scene().spheres[0].radius, 0.25);
    EXPECT_EQ(window->renderer()->shownImage(), before) << "undo did not restore the image pixel for pixel";
    EXPECT_EQ(window->renderer()->cpuImage()->rgb, cpuBefore);
    EXPECT_FALSE(window->isWindowModified());
}

TEST_F(Workbench, InvalidValueIsRefusedAtTheFieldWithTheReadersReason) {
    open(kData + "default.json");
    typeIntoField(*window, "objects[0].radius", "-1");
    const QString refusal = window->docks()->properties()->refusalText();
    EXPECT_TRUE(refusal.contains("objects[0].radius")) << refusal.toStdString();
    EXPECT_TRUE(refusal.contains("expected a number in [1e-06, 1e+06], got -1")) << refusal.toStdString();
    QTreeWidgetItem* item = window->docks()->properties()->itemOf("objects[0].radius");
    ASSERT_NE(item, nullptr);
    EXPECT_EQ(item->text(1), "0.25") << "the refused value is still shown";
    EXPECT_EQ(item->toolTip(1), refusal.mid(refusal.indexOf(": ") + 2));
    EXPECT_EQ(window->activeScene()->undoStack()->count(), 0);
    EXPECT_DOUBLE_EQ(window->activeScene()->scene().scene().spheres[0].radius, 0.25);

    // Text where a number belongs, and a metric parameter the file leaves out (Goedel has only a).
    typeIntoField(*window, "metric.a", "abc");
    EXPECT_TRUE(window->docks()->properties()->refusalText().contains("metric.a"))
        << window->docks()->properties()->refusalText().toStdString();
    EXPECT_EQ(window->activeScene()->undoStack()->count(), 0);

    // A metric name typed in the tree is the metric chooser's edit (the new metric at its
    // defaults, the observer moved where the metric cannot have it: on the axis it would sit on
    // Schwarzschild's singularity), one undoable edit, and the message bar says what moved.
    typeIntoField(*window, "metric.name", "schwarzschild");
    EXPECT_EQ(window->docks()->properties()->itemOf("metric.name")->text(1), "schwarzschild");
    EXPECT_EQ(window->activeScene()->undoStack()->count(), 1);
    EXPECT_GT(window->activeScene()->scene().scene().observer.tail<3>().norm(), 2.0);
    EXPECT_TRUE(window->report()->messageText().contains("the observer moved to"))
        << window->report()->messageText().toStdString();
    // A name no metric has is refused at the field, and the tree shows the document.
    typeIntoField(*window, "metric.name", "goedel");
    EXPECT_TRUE(window->docks()->properties()->refusalText().contains("unknown metric 'goedel'"))
        << window->docks()->properties()->refusalText().toStdString();
    EXPECT_EQ(window->docks()->properties()->itemOf("metric.name")->text(1), "schwarzschild");
    EXPECT_EQ(window->activeScene()->undoStack()->count(), 1);
}

// Magnification per pixel in the workbench: ticked in the properties dock (render.magnification,
// shown as a default), the CPU image carries the ray bundles' channels and a pick reads the
// pixel's magnification, shear and rotation in the info line, the values of its record.
TEST_F(Workbench, MagnificationIsSwitchedOnInThePropertiesDockAndShownByAPick) {
    ASSERT_TRUE(window->sessions()->openScene(kData + "kerr.json")) << window->report()->lastError().toStdString();
    ASSERT_TRUE(window->activeScene()->edit({{"camera.width", Json::Value(64)}, {"camera.height", Json::Value(32)}},
                                            "smaller"));
    ASSERT_TRUE(waitForCpuImage(*window));
    ASSERT_NE(window->docks()->properties()->itemOf("render.magnification"), nullptr) << "a default of the file";
    EXPECT_FALSE(window->renderer()->cpuImage()->records.lensing);
    typeIntoField(*window, "render.magnification", "true");
    ASSERT_TRUE(waitForCpuImage(*window));
    const lc::RenderResult& data = window->renderer()->cpuImage()->records;
    ASSERT_TRUE(data.lensing);
    // The most magnified sky pixel (beside the shadow's edge).
    std::size_t most = 0;
    for (std::size_t k = 0; k < data.pixels.size(); ++k)
        if (data.pixels[k].kind == lc::PixelRecord::Sky &&
            std::abs(data.pixels[k].magnification) > std::abs(data.pixels[most].magnification))
            most = k;
    ASSERT_GT(std::abs(data.pixels[most].magnification), 2.0f);
    int i = static_cast<int>(most % data.width), j = static_cast<int>(most / data.width);
    clickPixel(*window, i, j);
    const lc::PixelRecord& p = data.pixels[static_cast<std::size_t>(j * data.width + i)];
    const QString picked = window->report()->statusText();
    EXPECT_TRUE(
        picked.contains(QString("magnification %1, shear %2").arg(p.magnification, 0, 'g', 4).arg(p.shear, 0, 'g', 3)))
        << picked.toStdString();
    ASSERT_TRUE(lc::test::saveScreenshot(*window, "gui_magnification.png"));
}

// An accretion disk in the workbench: the shader image and the CPU data show it, its settings are
// in the properties dock (those the file leaves out as defaults), an edit re-renders it, and an
// inner edge inside the ISCO is refused with the reader's reason at that field.
TEST_F(Workbench, AccretionDiskParametersAreEditableInThePropertiesDock) {
    ASSERT_TRUE(window->sessions()->openScene(kData + "kerr_disk.json")) << window->report()->lastError().toStdString();
    ASSERT_TRUE(window->activeScene()->edit({{"camera.width", Json::Value(160)}, {"camera.height", Json::Value(90)}},
                                            "smaller"));
    ASSERT_TRUE(waitForCpuImage(*window));
    std::size_t diskPixels = 0;
    for (const auto& p : window->renderer()->cpuImage()->records.pixels) diskPixels += p.kind == lc::PixelRecord::Disk;
    EXPECT_GT(diskPixels, 3000u);
    // The status counts them as the disk's, for people ("12 345 pixels of the disk").
    EXPECT_TRUE(window->report()->statusText().remove(' ').contains(QString::number(diskPixels) + "pixelsofthedisk"))
        << window->report()->statusText().toStdString();
    ASSERT_NE(window->docks()->properties()->itemOf("objects[0].sense"), nullptr) << "defaults of the disk";
    EXPECT_EQ(window->docks()->properties()->itemOf("objects[0].sense")->text(1), "prograde");

    const std::vector<float> before = window->renderer()->shownImage();
    typeIntoField(*window, "objects[0].temperature", "4500");
    ASSERT_TRUE(waitForCpuImage(*window));
    ASSERT_EQ(window->activeScene()->scene().scene().disks.size(), 1u);
    EXPECT_DOUBLE_EQ(window->activeScene()->scene().scene().disks[0].temperature, 4500);
    EXPECT_NE(window->renderer()->shownImage(), before) << "a cooler disk looks redder";

    // A pick on the brightest disk pixel says what its colour is made of.
    auto [i, j] = brightestDiskPixel(window->renderer()->cpuImage()->records);
    clickPixel(*window, i, j);
    const QString picked = window->report()->statusText();
    EXPECT_TRUE(picked.contains("disk 'disk', direct image")) << picked.toStdString();
    EXPECT_TRUE(picked.contains("nu_obs/nu_em = 1.")) << "the approaching side: blueshifted " << picked.toStdString();
    // The accuracy dock names the hit (the disk at the record's radius, the direct image) and
    // follows the ray past it under its own name, not as this pixel's fate.
    const QString figures = window->docks()->accuracyPanel()->pickText();
    const lc::PixelRecord& hit = record(*window, i, j);
    ASSERT_EQ(hit.kind, lc::PixelRecord::Disk);
    EXPECT_TRUE(figures.contains(QString("meets the accretion disk at r = %1 M").arg(hit.diskRadius, 0, 'g', 6)))
        << figures.toStdString();
    EXPECT_TRUE(figures.contains("the direct image")) << figures.toStdString();
    EXPECT_TRUE(figures.contains("followed on past the hit")) << figures.toStdString();
    EXPECT_FALSE(figures.contains("traced to the end")) << figures.toStdString();

    const int undo = window->activeScene()->undoStack()->count();
    typeIntoField(*window, "objects[0].inner_radius", "1.5");
    const QString refusal = window->docks()->properties()->refusalText();
    EXPECT_TRUE(refusal.contains("objects[0].inner_radius")) << refusal.toStdString();
    EXPECT_TRUE(refusal.contains("innermost stable circular orbit r = 2.32088")) << refusal.toStdString();
    EXPECT_EQ(window->activeScene()->undoStack()->count(), undo);
}

TEST_F(Workbench, PickedPixelLightPathEndsOnTheSphereForAMovedObserver) {
    open(kData + "default.json");
    // The observer moved off the axis (an isometry carries the closed forms there).
    typeIntoField(*window, "observer.position", "[0, -0.3, 0.2, 0.1]");
    ASSERT_TRUE(waitForCpuImage(*window));
    ASSERT_EQ(window->activeScene()->scene().scene().observer, lc::Vec4(0, -0.3, 0.2, 0.1));
    int i = -1, j = -1;
    ASSERT_TRUE(innerObjectPixel(window->renderer()->cpuImage()->records, 0, i, j))
        << "the moved observer sees no sphere";
    clickPixel(*window, i, j);
    const lc::PixelRecord& p = record(*window, i, j);
    ASSERT_EQ(p.kind, lc::PixelRecord::Object);
    lc::Vec4 end, start;
    ASSERT_TRUE(highlightEnd(*window, end, start)) << "no highlighted path";
    EXPECT_NEAR(start.tail<3>().norm(), 0, 1e-12) << "the path does not start at the observer";
    const auto& ball = window->activeScene()->scene().scene().spheres[0];
    EXPECT_NEAR(ball.placement->toLocal(end).norm(), ball.radius, 1e-3) << "the path ends off the sphere";
    EXPECT_NEAR(end(0), p.emissionTime, 1e-4);
    EXPECT_TRUE(window->report()->statusText().contains("'ball'")) << window->report()->statusText().toStdString();
    // Its winding and branch: those of the image (images table) emitted closest in time.
    QTableWidget* table = window->docks()->imagesTable();
    ASSERT_GT(table->rowCount(), 0);
    // Every row's psi and phi are the direction of the pixel it names, in the camera's frame (before,
    // the table gave them in the chart the isometry moved the observer into: phi 145.5 degrees off).
    const lc::Camera camera = lc::frameCamera(window->activeScene()->scene().scene());
    int rowsInView = 0;
    for (int row = 0; row < table->rowCount(); ++row) {
        const QStringList pixel = table->item(row, 7)->text().split(", ");
        if (pixel.size() != 2) continue;  // "outside the view"
        const lc::Vec3 d = camera.direction(pixel[0].toInt(), pixel[1].toInt());
        const double pixelDeg = camera.fovXDeg / camera.width;
        EXPECT_NEAR(table->item(row, 3)->text().toDouble(), std::atan2(d.y(), d.x()) * 180 / lc::kPi, 2 * pixelDeg)
            << "row " << row;
        EXPECT_NEAR(table->item(row, 2)->text().toDouble(), std::acos(d.z()) * 180 / lc::kPi, 2 * pixelDeg)
            << "row " << row;
        ++rowsInView;
    }
    EXPECT_GT(rowsInView, 0);
    int nearest = 0;
    for (int row = 0; row < table->rowCount(); ++row)
        if (std::abs(table->item(row, 4)->text().toDouble() - p.emissionTime) <
            std::abs(table->item(nearest, 4)->text().toDouble() - p.emissionTime))
            nearest = row;
    const QString path = "winding " + table->item(nearest, 0)->text() + ", " + table->item(nearest, 1)->text();
    EXPECT_TRUE(window->report()->statusText().contains(path))
        << window->report()->statusText().toStdString() << " vs " << path.toStdString();
    // Background (a pixel whose 5 x 5 neighbourhood shows no object): no path.
    const lc::RenderResult& r = window->renderer()->cpuImage()->records;
    int bi = -1, bj = -1;
    for (int dj = 0; dj < r.height / 2 - 3 && bi < 0; ++dj)
        for (int jj : {r.height / 2 + dj, r.height / 2 - dj})
            for (int ii = 10; ii < r.width - 10 && bi < 0; ii += 5) {
                bool empty = true;
                for (int y = jj - 2; y <= jj + 2; ++y)
                    for (int x = ii - 2; x <= ii + 2; ++x)
                        empty = empty && record(*window, x, y).kind != lc::PixelRecord::Object;
                if (empty) bi = ii, bj = jj;
            }
    ASSERT_GE(bi, 0);
    clickPixel(*window, bi, bj);
    EXPECT_NE(record(*window, bi, bj).kind, lc::PixelRecord::Object);
    EXPECT_EQ(window->docks()->diagramView()->highlightPlot(), nullptr);
    EXPECT_TRUE(window->report()->statusText().contains("background")) << window->report()->statusText().toStdString();
}

// One camera for the image and the pick (issue 51): in data/sr_cube.json (640 x 360 with fields of
// view 101.5 x 75 degrees: non-square pixels), the cube's rightmost and leftmost pixels of the
// middle row, picked with the mouse, give rays whose emission event (the picked direction at the
// pixel's recorded apparent distance), carried into the cube's rest frame by the Lorentz
// transformation, lies on a face of the box of edge 4. Before, the special-relativity renderer drew
// with a camera of its own (square pixels from the vertical field): the pick's direction differed
// by 8 px at the cube's edge, 70 px from the centre, and missed the cube.
TEST_F(Workbench, PickedPixelRayMeetsTheMovingCubeAtItsEdges) {
    open(kData + "sr_cube.json");
    ASSERT_TRUE(waitForCpuImage(*window));
    const lc::RenderResult& r = window->renderer()->cpuImage()->records;
    auto cubeAt = [&](int i, int j) {
        return i >= 0 && i < r.width && j >= 0 && j < r.height &&
               r.pixels[static_cast<std::size_t>(j) * r.width + i].kind == lc::PixelRecord::Object;
    };
    // The rightmost and leftmost cube pixels of the middle row with two cube pixels inside them.
    const int row = r.height / 2;
    int right = -1, left = -1;
    for (int i = 0; i < r.width; ++i)
        if (cubeAt(i, row) && cubeAt(i - 1, row) && cubeAt(i - 2, row)) right = i;
    for (int i = r.width - 1; i >= 0; --i)
        if (cubeAt(i, row) && cubeAt(i + 1, row) && cubeAt(i + 2, row)) left = i;
    ASSERT_GE(left, 0);
    ASSERT_GT(right, r.width / 2 + 50) << "the cube should reach well to the right";
    const auto& cube = window->activeScene()->scene().scene().meshes.at(0);
    const double beta = cube.motion.beta.x(), gamma = 1 / std::sqrt(1 - beta * beta);
    for (int i0 : {right, left}) {
        // Where the view shows the image smaller than its pixels a click lands within 2 px of its
        // pixel: stepped inwards until it picks the cube's outermost pixel under the mouse.
        int i = i0, j = row;
        for (int inward = 0; inward <= 3; ++inward) {
            i = i0 == right ? i0 - inward : i0 + inward;
            j = row;
            clickPixel(*window, i, j);
            if (record(*window, i, j).kind == lc::PixelRecord::Object) break;
        }
        ASSERT_EQ(record(*window, i, j).kind, lc::PixelRecord::Object);
        // The picked ray: its direction and the apparent distance of the emission (light at c = 1).
        ASSERT_TRUE(window->selection()->selectionModel()->ray().has_value()) << "no ray picked at pixel " << i;
        const lc::gui::SelectedRay& ray = *window->selection()->selectionModel()->ray();
        const lc::Vec4 observer = window->activeScene()->scene().scene().observer;
        const lc::Vec4 end =
            observer + ray.affine * lc::Vec4(-1, ray.direction.x(), ray.direction.y(), ray.direction.z());
        const lc::Vec4 d = end - cube.centre;  // from the event the cube's centre passes
        const lc::Vec3 rest(gamma * (d(1) - beta * d(0)), d(2), d(3));
        EXPECT_NEAR(rest.cwiseAbs().maxCoeff(), 2.0, 2e-3)
            << "pixel " << i << ": rest-frame point " << rest.transpose();
    }
}

TEST_F(Workbench, PickedPixelLightPathEndsOnTheFreelyFallingBody) {
    open(kData + "godel_free_fall_earth.json");
    const lc::Scene& scene = window->activeScene()->scene().scene();
    const auto& earth = scene.spheres.at(0);
    int i = -1, j = -1;
    ASSERT_TRUE(innerObjectPixel(window->renderer()->cpuImage()->records, 0, i, j)) << "the falling earth is not seen";
    clickPixel(*window, i, j);
    const lc::PixelRecord& p = record(*window, i, j);
    ASSERT_EQ(p.kind, lc::PixelRecord::Object);
    lc::Vec4 end, start;
    ASSERT_TRUE(highlightEnd(*window, end, start));
    // Oracle: the centre's own geodesic (docs/PHYSICS.md section 2, moved to the centre event): at the
    // end's time the end lies about one radius from the centre (0.7c: contracted to 0.71 of it).
    const double a = dynamic_cast<const lc::GodelCartesian&>(*scene.spacetime).a();
    const auto line = lc::godel::OriginGeodesic::timelike(a, earth.motion.k0, earth.motion.k3, earth.motion.phi0);
    const lc::godel::FreeFall centre(line, lc::godel::Isometry::movingOriginTo(a, earth.centre));
    double lo = -40, hi = 5;  // coordinate time grows along the world line
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (centre.position(mid)(0) < end(0) ? lo : hi) = mid;
    }
    const lc::Vec4 c = centre.position(0.5 * (lo + hi));
    const double d = lc::godel::Isometry::movingToOrigin(a, c).apply(end).tail<3>().norm();
    EXPECT_GT(d, 0.6 * earth.radius) << "the path ends inside the earth";
    EXPECT_LT(d, 1.15 * earth.radius) << "the path ends off the earth";

    // The images table lists the falling earth's images from its world line: each image's ray
    // ends on that world line at the emission time it states (the same oracle), and the
    // frequency ratios differ from 1 (the earth moves at 0.7 c).
    auto* table = window->docks()->imagesTable();
    ASSERT_GT(table->rowCount(), 0) << window->findChild<QDockWidget*>("imagesDock")->windowTitle().toStdString();
    bool shifted = false;
    for (int row = 0; row < table->rowCount(); ++row) {
        const auto path = table->lightPathOfRow(row);
        ASSERT_FALSE(path.empty());
        const lc::Vec4 emitted = lc::gui::observerChartToWorld(scene, path.back());
        EXPECT_NEAR(emitted(0), table->item(row, 4)->text().toDouble(), 1e-3) << "row " << row;
        double lo2 = -40, hi2 = 5;
        for (int k = 0; k < 200; ++k) {
            const double mid = 0.5 * (lo2 + hi2);
            (centre.position(mid)(0) < emitted(0) ? lo2 : hi2) = mid;
        }
        EXPECT_LT((centre.position(0.5 * (lo2 + hi2)) - emitted).norm(), 1e-5)
            << "row " << row << ": not on the world line";
        shifted = shifted || std::abs(table->item(row, 5)->text().toDouble() - 1) > 0.05;
    }
    EXPECT_TRUE(shifted) << "no Doppler shift for a body at 0.7 c";
}

TEST_F(Workbench, ImagesTableRowMarksAPixelOfThatImage) {
    open(kData + "godel_many_images.json");
    ASSERT_TRUE(window->activeScene()->edit({{"camera.width", Json::Value(540)}, {"camera.height", Json::Value(210)}},
                                            "smaller"));
    ASSERT_TRUE(waitForCpuImage(*window));
    QTableWidget* table = window->docks()->imagesTable();
    ASSERT_GE(table->rowCount(), 6) << "the ball is seen on two paths per winding";
    int checked = 0, shownItself = 0;
    for (int row = 0; row < table->rowCount(); ++row) {
        if (table->item(row, 7)->text() == "outside the view") continue;
        const QRect cell = table->visualItemRect(table->item(row, 0));
        table->scrollToItem(table->item(row, 0));
        QTest::mouseClick(table->viewport(), Qt::LeftButton, Qt::NoModifier,
                          table->visualItemRect(table->item(row, 0)).center());
        (void)cell;
        const auto [i, j] = window->selection()->markedPixel();
        ASSERT_GE(i, 0) << "row " << row << " marked nothing";
        // The marked pixel shows the ball, emitted at that image's time (the centre's; the surface
        // seen is within a radius of it).
        const lc::PixelRecord& p = record(*window, i, j);
        EXPECT_EQ(p.kind, lc::PixelRecord::Object) << "row " << row << " pixel " << i << "," << j;
        // That image, or a nearer one in front of it (images of high windings overlap): then the
        // pixel's depth is smaller than the image's.
        const double t = table->item(row, 4)->text().toDouble(), depth = table->item(row, 6)->text().toDouble();
        if (std::abs(p.emissionTime - t) > 0.5) {
            EXPECT_LT(p.affine, depth - 0.5)
                << "row " << row << ": the marked pixel shows neither this image nor one in front of it";
        } else {
            ++shownItself;
        }
        EXPECT_NE(window->docks()->diagramView()->highlightPlot(), nullptr);
        ++checked;
    }
    EXPECT_GE(checked, 4);
    EXPECT_GE(shownItself, 4);
}

TEST_F(Workbench, SessionRoundTripGivesTheSamePixelsAndSettings) {
    TempFolder tmp;
    open(kData + "default.json");
    typeIntoField(*window, "metric.a", "0.9");
    ASSERT_TRUE(waitForCpuImage(*window));
    window->camera()->zoom(2);  // the wheel's edit: a narrower field of view
    ASSERT_TRUE(waitForCpuImage(*window));
    int i = -1, j = -1;
    ASSERT_TRUE(innerObjectPixel(window->renderer()->cpuImage()->records, 0, i, j));
    clickPixel(*window, i, j);
    // The 3D view turned by a drag (#46 item 7: sessions keep it).
    lc::gui::SpacetimeViewDock* dock3d = window->docks()->spacetimeView();
    dock3d->refresh();
    const std::vector<double> fitted = dock3d->cameraState();
    ASSERT_EQ(fitted.size(), 10u);
    QWidget* view3d = dock3d->renderWidget();
    const QPoint from = view3d->rect().center();
    QTest::mousePress(view3d, Qt::LeftButton, Qt::NoModifier, from);
    for (int k = 1; k <= 6; ++k) lc::test::dragMoveTo(view3d, from + QPoint(10 * k, 4 * k));
    QTest::mouseRelease(view3d, Qt::LeftButton, Qt::NoModifier, from + QPoint(60, 24));
    QApplication::processEvents();
    const std::vector<double> turned = dock3d->cameraState();
    ASSERT_EQ(turned.size(), 10u);
    EXPECT_GT(std::abs(turned[0] - fitted[0]) + std::abs(turned[1] - fitted[1]) + std::abs(turned[2] - fitted[2]), 1e-3)
        << "the drag did not turn the camera";
    const QString file = tmp / "s.lcsession";
    ASSERT_TRUE(window->sessions()->saveSession(file)) << window->report()->lastError().toStdString();
    EXPECT_FALSE(window->isWindowModified());
    const std::vector<float> shown = window->renderer()->shownImage(), cpu = window->renderer()->cpuImage()->rgb;
    const Json::Value document = window->activeScene()->scene().document();

    lc::gui::MainWindow other;
    other.resize(1280, 800);
    other.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&other));
    ASSERT_TRUE(other.sessions()->openFile(file)) << other.report()->lastError().toStdString();
    ASSERT_TRUE(waitForCpuImage(other));
    EXPECT_EQ(other.activeScene()->scene().document(), document);
    EXPECT_EQ(other.renderer()->shownImage(), shown) << "the session's shader image differs";
    EXPECT_EQ(other.renderer()->cpuImage()->rgb, cpu) << "the session's CPU image differs";
    EXPECT_EQ(other.selection()->pickedI(), i);
    EXPECT_EQ(other.selection()->pickedJ(), j);
    EXPECT_NE(other.docks()->diagramView()->highlightPlot(), nullptr) << "the picked path is not restored";
    EXPECT_FALSE(other.isWindowModified());
    EXPECT_TRUE(other.windowTitle().contains("s.lcsession"));
    // The 3D camera as it was left, and the undo history: both edits undoable, back to the file.
    other.docks()->spacetimeView()->refresh();
    const std::vector<double> reopened = other.docks()->spacetimeView()->cameraState();
    ASSERT_EQ(reopened.size(), 10u);
    for (std::size_t k = 0; k < 10; ++k) EXPECT_NEAR(reopened[k], turned[k], 1e-9 * (1 + std::abs(turned[k]))) << k;
    QUndoStack* history = other.activeScene()->undoStack();
    ASSERT_EQ(history->count(), window->activeScene()->undoStack()->count());
    ASSERT_EQ(history->count(), 2);
    EXPECT_EQ(history->text(0), window->activeScene()->undoStack()->text(0));
    EXPECT_EQ(history->undoText(), window->activeScene()->undoStack()->undoText());
    other.activateWindow();
    (void)QTest::qWaitForWindowActive(&other, 2000);
    QTest::keyClick(&other, Qt::Key_Z, Qt::ControlModifier);
    QTest::keyClick(&other, Qt::Key_Z, Qt::ControlModifier);
    ASSERT_TRUE(waitForCpuImage(other));
    EXPECT_EQ(other.activeScene()->scene().document(), other.activeScene()->scene().original());
    EXPECT_TRUE(other.isWindowModified());
    other.activeScene()->undoStack()->setClean();
    other.close();

    // The CLI renders the same session (GUI/CLI parity): the same file as the GUI's export.
    ASSERT_TRUE(window->exports()->exportImage(tmp / "gui.png"));
    ASSERT_EQ(lc::cli::runRender({"--session", file.toStdString(), "-o", (tmp.path / "cli.png").string(), "--quiet"}),
              0);
    EXPECT_EQ(fileBytes(tmp.path / "gui.png"), fileBytes(tmp.path / "cli.png"));
}

// File > Export diagram, Export figure and Export VTK data write what `lightcone diagram`,
// `lightcone figure` and `lightcone export` write for the same scene, file for file.
TEST_F(Workbench, DiagramFigureAndVtkExportsEqualTheCommandLines) {
    TempFolder tmp;
    open(kData + "default.json");
    ASSERT_TRUE(window->exports()->exportDiagram(tmp / "gui.svg")) << window->report()->lastError().toStdString();
    ASSERT_TRUE(window->exports()->exportVtk(tmp / "gui_export")) << window->report()->lastError().toStdString();
    const std::string scene = (kData + "default.json").toStdString();
    ASSERT_EQ(lc::cli::runDiagram({scene, "-o", (tmp.path / "cli.svg").string()}), 0);
    ASSERT_EQ(lc::cli::runExport({scene, "-o", (tmp.path / "cli_export").string()}), 0);
    // File > Export figure: the render on angular axes, as `lightcone figure`.
    ASSERT_TRUE(waitForCpuImage(*window));
    ASSERT_TRUE(window->exports()->exportFigure(tmp / "gui_figure.svg", "emission-time"))
        << window->report()->lastError().toStdString();
    ASSERT_EQ(lc::cli::runFigure({scene, "-o", (tmp.path / "cli_figure.svg").string(), "--quantity", "emission-time"}),
              0);
    EXPECT_EQ(fileBytes(tmp.path / "gui_figure.svg"), fileBytes(tmp.path / "cli_figure.svg"));
    EXPECT_NE(fileBytes(tmp.path / "gui_figure.svg").find("<image"), std::string::npos);
    EXPECT_GT(fileBytes(tmp.path / "gui.svg").size(), 1000u);
    EXPECT_EQ(fileBytes(tmp.path / "gui.svg"), fileBytes(tmp.path / "cli.svg"));
    int files = 0;
    for (const auto& e : fs::recursive_directory_iterator(tmp.path / "cli_export")) {
        if (!e.is_regular_file()) continue;
        const fs::path rel = fs::relative(e.path(), tmp.path / "cli_export");
        EXPECT_EQ(fileBytes(e.path()), fileBytes(tmp.path / "gui_export" / rel)) << rel;
        ++files;
    }
    EXPECT_GE(files, 6);
    // Refused before any work: a folder where a file belongs, an unknown format.
    EXPECT_FALSE(window->exports()->exportDiagram(tmp / "gui_export"));
    EXPECT_FALSE(window->exports()->exportImage(tmp / "image.txt"));
    EXPECT_TRUE(window->report()->lastError().contains("image file")) << window->report()->lastError().toStdString();
}

TEST_F(Workbench, MalformedSessionAndMissingSceneShowTheReasonAndKeepTheState) {
    TempFolder tmp;
    open(kData + "default.json");
    typeIntoField(*window, "objects[0].radius", "0.3");
    ASSERT_TRUE(waitForCpuImage(*window));
    const Json::Value document = window->activeScene()->scene().document();
    const int undoCount = window->activeScene()->undoStack()->count();

    std::ofstream(tmp.path / "bad.lcsession")
        << "{\"lightcone_session\": 1,\n \"scene\": {\"path\": \"x.json\",\n  \"edits\": 3}}";
    EXPECT_FALSE(window->sessions()->openFile(tmp / "bad.lcsession"));
    EXPECT_TRUE(window->report()->lastError().contains("bad.lcsession:3"))
        << window->report()->lastError().toStdString();
    EXPECT_TRUE(window->report()->lastError().contains("scene.edits")) << window->report()->lastError().toStdString();
    auto* dialog = window->findChild<QMessageBox*>("errorDialog");
    ASSERT_NE(dialog, nullptr);
    EXPECT_TRUE(dialog->isVisible());
    EXPECT_TRUE(dialog->text().contains("bad.lcsession:3"));
    dialog->close();
    QApplication::processEvents();

    std::ofstream(tmp.path / "gone.lcsession") << "{\"lightcone_session\": 1, \"scene\": {\"path\": \"nowhere.json\"}}";
    EXPECT_FALSE(window->sessions()->openFile(tmp / "gone.lcsession"));
    EXPECT_TRUE(window->report()->lastError().contains("nowhere.json is not there"))
        << window->report()->lastError().toStdString();
    EXPECT_FALSE(window->sessions()->openFile(QString(LIGHTCONE_SOURCE_DIR) + "/tests/data/bad_radius.json"));
    EXPECT_TRUE(window->report()->lastError().contains("bad_radius.json:5: field 'objects[0].radius'"))
        << window->report()->lastError().toStdString();

    EXPECT_EQ(window->activeScene()->scene().document(), document) << "a failed open changed the scene";
    EXPECT_EQ(window->activeScene()->undoStack()->count(), undoCount);
    EXPECT_TRUE(window->isWindowModified());

    // A session whose scene moved opens from its saved copy, with a notice, nothing lost.
    fs::copy_file(QString(kData + "default.json").toStdString(), tmp.path / "scene.json");
    ASSERT_TRUE(window->sessions()->openScene(tmp / "scene.json"));
    typeIntoField(*window, "objects[0].radius", "0.35");
    ASSERT_TRUE(window->sessions()->saveSession(tmp / "moved.lcsession"));
    fs::remove(tmp.path / "scene.json");
    ASSERT_TRUE(window->sessions()->openFile(tmp / "moved.lcsession")) << window->report()->lastError().toStdString();
    EXPECT_TRUE(window->report()->lastNotice().contains("scene.json is not there"))
        << window->report()->lastNotice().toStdString();
    EXPECT_DOUBLE_EQ(window->activeScene()->scene().scene().spheres[0].radius, 0.35);
    ASSERT_TRUE(waitForCpuImage(*window));
}

TEST_F(Workbench, KerrRenderKeepsTheEventLoopResponsiveAndCancelStopsIt) {
    // The longest gap between ticks of a 5 ms timer while the numeric Kerr image renders on the CPU.
    open(kData + "default.json");
    ASSERT_TRUE(window->sessions()->openScene(kData + "kerr.json"));
    // 280 x 140: a numeric Kerr image of a few seconds on two cores, as the test budget allows
    // (a quarter of the width and height in the instrumented build, ~75 times slower).
    const int shrink = timeScale() > 1 ? 4 : 1;
    ASSERT_TRUE(window->activeScene()->edit(
        {{"camera.width", Json::Value(280 / shrink)}, {"camera.height", Json::Value(140 / shrink)}}, "test size"));
    ASSERT_TRUE(window->renderer()->rendering());
    QElapsedTimer clock;
    clock.start();
    qint64 last = 0, longest = 0;
    QTimer tick;
    QObject::connect(&tick, &QTimer::timeout, [&] {
        const qint64 now = clock.elapsed();
        longest = std::max(longest, now - last);
        last = now;
    });
    tick.start(5);
    const qint64 start = clock.elapsed();
    last = start;
    while (window->renderer()->rendering() && clock.elapsed() - start < 60000 * timeScale()) QTest::qWait(5);
    const double seconds = (clock.elapsed() - start) / 1000.0;
    tick.stop();
    ASSERT_NE(window->renderer()->cpuImage(), nullptr);
    std::printf("[ measured ] Kerr %dx%d CPU render in the GUI: %.2f s, longest event-loop stall %lld ms\n",
                window->renderer()->cpuImage()->records.width, window->renderer()->cpuImage()->records.height, seconds,
                static_cast<long long>(longest));
    EXPECT_LT(longest, 100 * timeScale()) << "an event-loop frame took longer than 100 ms during the render";

    // Cancel through the status bar's button: the render stops within 0.5 s.
    ASSERT_TRUE(window->activeScene()->edit({{"render.tolerance", Json::Value(1e-9)}}, "tighter"));
    ASSERT_TRUE(window->renderer()->rendering());
    QTest::qWait(300);
    ASSERT_TRUE(window->progress()->cancelButton()->isVisible());
    bool cancelled = false;
    QObject::connect(window->renderer()->renderJob(), &lc::gui::RenderJob::cancelled, [&] { cancelled = true; });
    QElapsedTimer t;
    t.start();
    QTest::mouseClick(window->progress()->cancelButton(), Qt::LeftButton);
    while (!cancelled && t.elapsed() < 5000 * timeScale()) QTest::qWait(2);
    std::printf("[ measured ] Cancel stopped the Kerr render in %lld ms\n", static_cast<long long>(t.elapsed()));
    EXPECT_TRUE(cancelled);
    EXPECT_LT(t.elapsed(), 500 * timeScale());
    EXPECT_FALSE(window->renderer()->rendering());
    EXPECT_EQ(window->renderer()->cpuImage(), nullptr);

    // Every state has a way out: after Cancel a click on the image traces the data and answers
    // the pick; cancelled again, Ctrl+R traces it; an edit renders as always.
    const lc::Camera& cam = window->activeScene()->scene().scene().camera;
    const QPoint centre = window->docks()->imageView()->widgetPointOfPixel(cam.width / 2, cam.height / 2);
    QTest::mouseClick(window->docks()->imageView(), Qt::LeftButton, Qt::NoModifier, centre);
    EXPECT_TRUE(window->renderer()->rendering()) << "a pick after Cancel started no trace";
    ASSERT_TRUE(waitForCpuImage(*window, 120000));
    EXPECT_EQ(window->selection()->pickedI(), cam.width / 2);
    EXPECT_EQ(window->selection()->pickedJ(), cam.height / 2);
    ASSERT_TRUE(window->activeScene()->edit({{"render.tolerance", Json::Value(1e-8)}}, "looser"));
    QTest::qWait(200);
    QTest::mouseClick(window->progress()->cancelButton(), Qt::LeftButton);
    t.restart();
    while (window->renderer()->rendering() && t.elapsed() < 5000 * timeScale()) QTest::qWait(2);
    ASSERT_EQ(window->renderer()->cpuImage(), nullptr);
    QTest::keyClick(window.get(), Qt::Key_R, Qt::ControlModifier);
    EXPECT_TRUE(window->renderer()->rendering()) << "Ctrl+R after Cancel started no trace";
    ASSERT_TRUE(waitForCpuImage(*window, 120000));
    ASSERT_TRUE(window->activeScene()->edit({{"render.tolerance", Json::Value(1e-7)}}, "looser still"));
    EXPECT_TRUE(window->renderer()->rendering());
    ASSERT_TRUE(waitForCpuImage(*window, 120000));
}

TEST_F(Workbench, ClosingWithUnsavedEditsAsksFirst) {
    open(kData + "default.json");
    typeIntoField(*window, "objects[0].radius", "0.3");
    ASSERT_TRUE(window->isWindowModified());
    auto answer = [](QMessageBox::StandardButton which) {
        QTimer::singleShot(200, [which] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (box) box->button(which)->click();
        });
    };
    answer(QMessageBox::Cancel);
    EXPECT_FALSE(window->close()) << "closed without asking";
    EXPECT_TRUE(window->isVisible());
    answer(QMessageBox::Discard);
    EXPECT_TRUE(window->close());
    window.reset();
}

TEST_F(Workbench, LookAroundZoomProjectionAndResetViewAreUndoableEdits) {
    open(kData + "default.json");
    ASSERT_TRUE(window->activeScene()->edit({{"camera.width", Json::Value(480)}, {"camera.height", Json::Value(160)}},
                                            "test size"));
    ASSERT_TRUE(waitForCpuImage(*window));
    const lc::Camera cam0 = window->activeScene()->scene().scene().camera;
    // A drag to the right by a quarter of the width: the panorama turns by 90 degrees.
    auto* image = window->docks()->imageView();
    const QPoint from = image->widgetPointOfPixel(cam0.width / 2, cam0.height / 2);
    const QPoint to = image->widgetPointOfPixel(cam0.width / 2 + cam0.width / 4, cam0.height / 2);
    QTest::mousePress(image, Qt::LeftButton, Qt::NoModifier, from);
    dragMoveTo(image, (from + to) / 2);
    dragMoveTo(image, to);
    QTest::mouseRelease(image, Qt::LeftButton, Qt::NoModifier, to);
    ASSERT_TRUE(waitForCpuImage(*window));
    const lc::Vec3 f = window->activeScene()->scene().scene().camera.forward.normalized();
    EXPECT_NEAR(std::acos(std::clamp(f.dot(cam0.forward.normalized()), -1.0, 1.0)) * 180 / lc::kPi, 90, 2.0);
    EXPECT_EQ(window->selection()->pickedI(), -1) << "a drag is not a pick";
    // The turned forward vector to 12 significant digits too (#46: "1.4999999889068953").
    for (const QString& c : window->docks()->properties()->itemOf("camera.forward")->text(1).split(',')) {
        const QString digits = QString(c).remove(QRegularExpression("[^0-9e]")).section('e', 0, 0);
        EXPECT_LE(QString(digits).remove(QRegularExpression("^0+")).size(), 12) << c.toStdString();
    }

    window->camera()->setPanorama(false);
    ASSERT_TRUE(waitForCpuImage(*window));
    EXPECT_EQ(window->activeScene()->scene().scene().camera.projection, lc::Camera::Projection::Pinhole);
    window->camera()->zoom(1);
    ASSERT_TRUE(waitForCpuImage(*window));
    EXPECT_NEAR(window->activeScene()->scene().scene().camera.fovXDeg, 90 / 1.1, 1e-9);
    // 12 significant digits in the dock, not 17 (issue 26: "159.72000000..."): "81.8181818182".
    const QString fov = window->docks()->properties()->itemOf("camera.fov")->text(1);
    EXPECT_TRUE(fov.startsWith("[81.8181818182,")) << fov.toStdString();
    EXPECT_EQ(window->activeScene()->undoStack()->count(), 4);
    window->camera()->resetView();
    ASSERT_TRUE(waitForCpuImage(*window));
    ASSERT_EQ(window->activeScene()->scene().edits().size(), 2u) << "only the test size is left";
    EXPECT_EQ(window->activeScene()->scene().edits()[0].field, "camera.width");
    EXPECT_EQ(window->activeScene()->undoStack()->count(), 5);
}

// The spacetime dock: each checkbox shows its layer (the filter's own point count) and runs at most
// that filter; moving the observer runs the filters of the visible layers that depend on it, once.
TEST_F(Workbench, SpacetimeViewTogglesRunOnlyTheirFilterAndAnObserverMoveTheDependentOnes) {
    open(kData + "default.json");
    SpacetimeView* view = window->docks()->spacetimeView()->view();
    ASSERT_TRUE(window->docks()->spacetimeView()->isVisible());
    ASSERT_TRUE(view->GetLayerVisibility(SpacetimeView::GEODESICS));
    EXPECT_GT(drawnPoints(view->GetLayerActors(SpacetimeView::GEODESICS)[0]), 0);

    auto before = executions(view);
    ASSERT_FALSE(view->GetLayerVisibility(SpacetimeView::KILLING_FIELD));
    clickToggle(*window, SpacetimeView::KILLING_FIELD);
    ASSERT_TRUE(view->GetLayerVisibility(SpacetimeView::KILLING_FIELD));
    std::vector<int> expected(SpacetimeView::NUMBER_OF_ALGORITHMS, 0);
    expected[SpacetimeView::KILLING_FIELD_SOURCE] = 1;
    EXPECT_EQ(runsSince(view, before), expected);
    vtkNew<vtkLightconeKillingFieldSource> killing;  // the same filter on its own
    lc::views::configureKillingFields(killing, window->activeScene()->scene().scene());
    killing->Update();
    vtkActor* glyphs = view->GetLayerActors(SpacetimeView::KILLING_FIELD)[0];
    EXPECT_TRUE(glyphs->GetVisibility());
    EXPECT_EQ(drawnPoints(glyphs), vtkDataSet::SafeDownCast(killing->GetOutputDataObject(0))->GetNumberOfPoints());

    before = executions(view);
    clickToggle(*window, SpacetimeView::HORIZON);  // off: nothing runs
    EXPECT_FALSE(view->GetLayerActors(SpacetimeView::HORIZON)[0]->GetVisibility());
    EXPECT_EQ(runsSince(view, before), std::vector<int>(SpacetimeView::NUMBER_OF_ALGORITHMS, 0));

    // The observer moves in space: rays, Killing grid and photo-object again; the hidden horizon,
    // the orbits (seeded at the observer's time, hidden) and the highlight source stay.
    before = executions(view);
    typeIntoField(*window, "observer.position", "[0, -0.3, 0.2, 0]");
    ASSERT_TRUE(waitForCpuImage(*window));
    const auto moved = runsSince(view, before);
    EXPECT_EQ(moved[SpacetimeView::GEODESIC_SOURCE], 1);
    EXPECT_EQ(moved[SpacetimeView::KILLING_FIELD_SOURCE], 1);
    EXPECT_EQ(moved[SpacetimeView::PHOTO_OBJECT_FILTERS], 1);
    EXPECT_EQ(moved[SpacetimeView::HORIZON_SOURCE], 0);
    EXPECT_EQ(moved[SpacetimeView::ORBIT_SOURCE], 0);
    EXPECT_EQ(moved[SpacetimeView::HIGHLIGHT_SOURCE], 0);
}

// The curvature layer: its checkbox runs the curvature source once; on Kerr's equator (a = 0.9,
// data/kerr.json) the slice holds 48 M^2 / r^6 with r^2 = x^2 + y^2 - a^2 (Henry 2000 at
// theta = 90 degrees) and draws log10 of it; the quantity chosen in the dock follows; Goedel's
// universe (default.json, a = 1) is a stiff fluid of density 1/(16 pi a^2) without Lambda
// (docs/PHYSICS.md section 13). docs/GUI.md's screenshot.
TEST_F(Workbench, CurvatureLayerShowsKerrsKretschmannAndTheQuantityChosen) {
    open(kData + "kerr.json");
    lc::gui::SpacetimeViewDock* dock = window->docks()->spacetimeView();
    SpacetimeView* view = dock->view();
    ASSERT_TRUE(dock->isVisible());
    ASSERT_TRUE(view->IsLayerAvailable(SpacetimeView::CURVATURE))
        << view->GetLayerUnavailableReason(SpacetimeView::CURVATURE);
    auto before = executions(view);
    clickToggle(*window, SpacetimeView::CURVATURE);
    ASSERT_TRUE(view->GetLayerVisibility(SpacetimeView::CURVATURE));
    std::vector<int> expected(SpacetimeView::NUMBER_OF_ALGORITHMS, 0);
    expected[SpacetimeView::CURVATURE_SOURCE] = 1;
    EXPECT_EQ(runsSince(view, before), expected);
    vtkActor* slice = view->GetLayerActors(SpacetimeView::CURVATURE)[0];
    ASSERT_TRUE(slice->GetVisibility());
    vtkImageData* field = view->GetCurvatureField();
    ASSERT_NE(field, nullptr);
    vtkDataArray* K = field->GetPointData()->GetArray("kretschmann");
    vtkDataArray* drawn = vtkDataSet::SafeDownCast(slice->GetMapper()->GetInput())->GetPointData()->GetScalars();
    ASSERT_TRUE(K && drawn);
    int checked = 0;
    for (vtkIdType id = 0; id < field->GetNumberOfPoints(); id += 97) {
        double p[3];
        field->GetPoint(id, p);
        const double r2 = p[0] * p[0] + p[1] * p[1] - 0.81;
        if (r2 < 1 || std::abs(p[2]) > 0) continue;
        const double closed = 48 / (r2 * r2 * r2);
        EXPECT_NEAR(K->GetTuple1(id) / closed, 1, 1e-9) << p[0] << "," << p[1];
        EXPECT_NEAR(drawn->GetTuple1(id), std::log10(closed), 1e-9);
        ++checked;
    }
    EXPECT_GT(checked, 200);

    // A pick: the picked pixel's ray, a sky pixel beside the shadow whose light passed close to
    // the hole, is coloured by the same quantity, which at every point of the ray is Henry's
    // (2000) closed form K = 48 M^2 (r^2 - a^2 c^2)(r^4 - 14 a^2 r^2 c^2 + a^4 c^4) / (r^2 + a^2 c^2)^6.
    const lc::RenderResult& data = window->renderer()->cpuImage()->records;
    int i = -1, j = data.height / 2;
    for (int q = 1; q < data.width && i < 0; ++q)
        if (record(*window, q, j).kind == lc::PixelRecord::Sky &&
            record(*window, q - 1, j).kind == lc::PixelRecord::Horizon)
            i = q;
    ASSERT_GE(i, 0) << "no shadow edge on the middle row";
    clickPixel(*window, i, j);
    ASSERT_TRUE(view->HasHighlightedRay());
    dock->refresh();
    vtkPolyData* along = view->GetHighlightedRayCurvature();
    ASSERT_NE(along, nullptr) << "the picked ray is not coloured by the curvature";
    EXPECT_TRUE(view->GetHighlightActor()->GetMapper()->GetScalarVisibility());
    vtkDataArray* onRay = along->GetPointData()->GetArray("kretschmann");
    ASSERT_NE(onRay, nullptr);
    double closest = 1e9;
    for (vtkIdType id = 0; id < along->GetNumberOfPoints(); ++id) {
        double p[3];
        along->GetPoint(id, p);
        const double r = lc::kerrSchildRadius(p[0], p[1], p[2], 0.9), c = p[2] / r, a2c2 = 0.81 * c * c;
        const double henry =
            48 * (r * r - a2c2) * (r * r * r * r - 14 * 0.81 * r * r * c * c + a2c2 * a2c2) / std::pow(r * r + a2c2, 6);
        EXPECT_NEAR(onRay->GetTuple1(id) / henry, 1, 1e-9) << "r = " << r;
        closest = std::min(closest, r);
    }
    EXPECT_LT(closest, 6);  // the light passed a few M from the hole (the observer is 30 M away)
    EXPECT_TRUE(lc::test::saveScreenshot(*window, "gui_curvature.png"));  // docs/GUI.md's

    // In 3D, chosen with the keyboard: the cube's isosurfaces (their levels against Henry's form:
    // SpacetimeView.CurvatureIsosurfacesLieOnKerrsKretschmannLevelsAndTheVolumeDrawsTheField),
    // then the volume; the picked ray keeps the quantity's colours.
    clickToggle(*window, SpacetimeView::GEODESICS);  // the camera fits the cube, not the fan
    QComboBox* style = dock->curvatureStyleChoice();
    style->setFocus();
    QTest::keyClick(style, Qt::Key_Down);
    QApplication::processEvents();
    ASSERT_EQ(view->GetCurvatureStyle(), SpacetimeView::CURVATURE_ISOSURFACES);
    EXPECT_EQ(view->GetCurvatureIsosurfaceLevels().size(), 6u);
    EXPECT_GT(drawnPoints(slice), 1000);
    EXPECT_EQ(view->GetCurvatureField()->GetDimensions()[2], 65);
    EXPECT_NE(view->GetHighlightedRayCurvature(), nullptr);
    EXPECT_TRUE(lc::test::saveWidgetScreenshot(dock, "gui_curvature_isosurfaces.png"));  // docs/GUI.md's
    QTest::keyClick(style, Qt::Key_Down);
    QApplication::processEvents();
    ASSERT_EQ(view->GetCurvatureStyle(), SpacetimeView::CURVATURE_VOLUME);
    EXPECT_TRUE(view->GetCurvatureVolume()->GetVisibility());
    EXPECT_FALSE(slice->GetVisibility());
    EXPECT_TRUE(lc::test::saveWidgetScreenshot(dock, "gui_curvature_volume.png"));  // docs/GUI.md's
    QTest::keyClick(style, Qt::Key_Up);
    QTest::keyClick(style, Qt::Key_Up);
    QApplication::processEvents();
    ASSERT_EQ(view->GetCurvatureStyle(), SpacetimeView::CURVATURE_SLICE);

    // The dock's quantity, chosen with the keyboard as a user would.
    QComboBox* choice = dock->curvatureChoice();
    choice->setFocus();
    while (choice->currentText() != "energy_density" && choice->currentIndex() + 1 < choice->count())
        QTest::keyClick(choice, Qt::Key_Down);
    QApplication::processEvents();
    ASSERT_EQ(view->GetCurvatureQuantity(), "energy_density");
    open(kData + "default.json");
    ASSERT_TRUE(view->GetLayerVisibility(SpacetimeView::CURVATURE));
    ASSERT_TRUE(view->IsLayerAvailable(SpacetimeView::CURVATURE))
        << view->GetLayerUnavailableReason(SpacetimeView::CURVATURE);
    dock->refresh();
    field = view->GetCurvatureField();
    ASSERT_NE(field, nullptr);
    vtkDataArray* rho = field->GetPointData()->GetArray("energy_density");
    ASSERT_NE(rho, nullptr);
    for (vtkIdType id = 0; id < rho->GetNumberOfTuples(); id += 113)
        EXPECT_NEAR(rho->GetTuple1(id) * 16 * lc::kPi, 1, 1e-9);
}

// A click on the image: the diagram and the 3D view highlight the same geodesic. Oracles: the
// pixel's camera direction and its record (emission event on the sphere), the diagram's path.
TEST_F(Workbench, ClickedPixelHighlightsTheSameGeodesicInTheDiagramAndTheSpacetimeView) {
    open(kData + "default.json");
    typeIntoField(*window, "observer.position", "[0, -0.3, 0.2, 0.1]");  // off the axis
    ASSERT_TRUE(waitForCpuImage(*window));
    int i = -1, j = -1;
    ASSERT_TRUE(innerObjectPixel(window->renderer()->cpuImage()->records, 0, i, j));
    clickPixel(*window, i, j);
    const lc::PixelRecord& p = record(*window, i, j);
    ASSERT_EQ(p.kind, lc::PixelRecord::Object);
    const lc::Scene& scene = window->activeScene()->scene().scene();
    ASSERT_TRUE(window->selection()->selectionModel()->ray().has_value());

    SpacetimeView* view = window->docks()->spacetimeView()->view();
    ASSERT_TRUE(view->HasHighlightedRay());
    EXPECT_TRUE(view->GetHighlightActor()->GetVisibility());
    vtkPolyData* ray = view->GetHighlightedRay();
    ASSERT_EQ(ray->GetNumberOfCells(), 1);
    // Its direction is the pixel's.
    const lc::Vec3 n = scene.camera.direction(i, j);
    EXPECT_NEAR(ray->GetCellData()->GetArray("psi")->GetTuple1(0), std::acos(n(2)), 1e-9);
    EXPECT_NEAR(ray->GetCellData()->GetArray("phi0")->GetTuple1(0), std::atan2(n(1), n(0)), 1e-9);
    // Both end at the emission event on the ball.
    const vtkIdType last = ray->GetNumberOfPoints() - 1;
    double xyz[3];
    ray->GetPoint(last, xyz);
    const lc::Vec4 end3d(ray->GetPointData()->GetArray("t")->GetTuple1(last), xyz[0], xyz[1], xyz[2]);
    lc::Vec4 endDiagram, start;
    ASSERT_TRUE(highlightEnd(*window, endDiagram, start));
    EXPECT_LT((end3d - endDiagram).norm(), 1e-6) << "the diagram and the 3D view show different rays";
    EXPECT_NEAR(end3d(0), p.emissionTime, 1e-4);
    const auto& ball = scene.spheres[0];
    EXPECT_NEAR(ball.placement->toLocal(end3d).norm(), ball.radius, 1e-3);
    // The picked object is selected everywhere: its photo-objects drawn opaque.
    EXPECT_EQ(window->selection()->selectedObject(), 0);
    EXPECT_EQ(view->GetSelectedObject(), 0);
    EXPECT_DOUBLE_EQ(view->GetLayerActors(SpacetimeView::PHOTO_OBJECTS)[0]->GetProperty()->GetOpacity(), 1.0);
    EXPECT_EQ(window->selection()->markedPixel(), std::make_pair(i, j));
}

// A click on a ray in the 3D view marks the pixel of that ray's direction in the image.
TEST_F(Workbench, PickedRayInTheSpacetimeViewMarksItsPixelInTheImage) {
    open(kData + "default.json");  // a 360-degree panorama: every ray of the fan is in the image
    lc::gui::SpacetimeViewDock* dock = window->docks()->spacetimeView();
    clickToggle(*window, SpacetimeView::PHOTO_OBJECTS);  // off: the ball's images would be in front of some rays
    ASSERT_FALSE(dock->view()->GetLayerVisibility(SpacetimeView::PHOTO_OBJECTS));
    vtkRenderer* renderer = dock->view()->GetRenderer();
    const int ray = 7;
    double p[3];
    ASSERT_TRUE(lc::test::isolatedPointOfRay(dock->view()->GetGeodesics(), ray, p));
    renderer->SetWorldPoint(p[0], p[1], p[2], 1);
    renderer->WorldToDisplay();
    const double d[2] = {renderer->GetDisplayPoint()[0], renderer->GetDisplayPoint()[1]};
    QWidget* widget = dock->renderWidget();
    const double ratio = widget->devicePixelRatioF();
    const QPoint at(static_cast<int>(std::lround(d[0] / ratio)),
                    static_cast<int>(std::lround(widget->height() - 1 - d[1] / ratio)));
    ASSERT_TRUE(widget->rect().contains(at));
    QTest::mouseClick(widget, Qt::LeftButton, Qt::NoModifier, at);
    QApplication::processEvents();
    // Oracle: the fan lies in the observer's horizontal plane, ray k at azimuth 2 pi k / N.
    const double phi = 2 * lc::kPi * ray / dock->view()->GetNumberOfRays();
    const lc::Vec3 n(std::cos(phi), std::sin(phi), 0);
    double x = 0, y = 0;
    ASSERT_TRUE(window->activeScene()->scene().scene().camera.project(n, x, y));
    // The fan lies on the image's horizon row, at a pixel edge: a rounding of the direction moves it by one.
    EXPECT_NEAR(window->selection()->markedPixel().first, x, 1.0) << window->report()->statusText().toStdString();
    EXPECT_NEAR(window->selection()->markedPixel().second, y, 1.0) << window->report()->statusText().toStdString();
    ASSERT_TRUE(window->selection()->selectionModel()->ray().has_value());
    EXPECT_NEAR((window->selection()->selectionModel()->ray()->direction - n).norm(), 0, 1e-9);
    EXPECT_TRUE(dock->view()->HasHighlightedRay());
    EXPECT_TRUE(window->report()->statusText().contains(QString("picked ray %1").arg(ray)))
        << window->report()->statusText().toStdString();
}

// A click on a fan ray of the r-phi diagram selects that ray: the image marks the pixel of its
// direction and the 3D view highlights the same geodesic. Oracle: a known direction's closed-form
// planar ray, clicked at a known affine length.
TEST_F(Workbench, ClickedRayInTheDiagramMarksItsPixelAndHighlightsTheSameGeodesic) {
    open(kData + "default.json");  // observer at the origin, a 360-degree panorama
    lc::gui::DiagramWidget* diagram = window->docks()->diagramView();
    diagram->renderWindow()->Render();  // the axes know their place once drawn
    const lc::Scene& scene = window->activeScene()->scene().scene();
    const double a = 1.0, phi = 2.2, lambda = 0.3 * 2 * lc::kPi * a;  // outbound, r = 2a sin(0.3 pi)
    const auto oracle = lc::godel::OriginGeodesic::null(a, lc::kPi / 2, phi, -1);
    const lc::Vec4 p = oracle.cartesian(lambda);
    const QPoint at = widgetPointOfDiagramPoint(diagram, p(1), p(2));
    ASSERT_TRUE(diagram->rect().contains(at));
    QTest::mouseClick(diagram, Qt::LeftButton, Qt::NoModifier, at);
    QApplication::processEvents();
    ASSERT_TRUE(window->selection()->selectionModel()->ray().has_value())
        << window->report()->statusText().toStdString();
    const lc::gui::SelectedRay& ray = *window->selection()->selectionModel()->ray();

    // The click lands within a pixel of the point: the azimuth moves by about a pixel over the
    // radius, the affine length by about a pixel over the ray's coordinate speed there.
    const double pixel = diagramPixel(diagram);
    const double radius = std::hypot(p(1), p(2));
    const double speed = oracle.tangentCartesian(lambda).segment<2>(1).norm();
    const lc::Vec3 n(std::cos(phi), std::sin(phi), 0);  // observer at the origin: camera frame = chart
    EXPECT_LT((ray.direction - n).norm(), 2 * pixel / radius);
    EXPECT_NEAR(ray.affine, lambda, 2 * pixel / speed);
    double x = 0, y = 0;
    ASSERT_TRUE(scene.camera.project(n, x, y));
    const double pixelsPerRadian = scene.camera.width / (2 * lc::kPi);
    EXPECT_NEAR(window->selection()->markedPixel().first, x, 1 + 2 * pixel / radius * pixelsPerRadian);
    EXPECT_NEAR(window->selection()->markedPixel().second, y, 1.0);
    EXPECT_EQ(window->selection()->markedPixel(), lc::gui::pixelOfDirection(scene.camera, ray.direction));

    // The 3D view and the diagram draw the same geodesic, ending at the clicked point.
    SpacetimeView* view = window->docks()->spacetimeView()->view();
    ASSERT_TRUE(view->HasHighlightedRay());
    const lc::Vec4 end3d = highlightedRayEnd(view);
    lc::Vec4 endDiagram, start;
    ASSERT_TRUE(highlightEnd(*window, endDiagram, start));
    EXPECT_LT((end3d - endDiagram).norm(), 1e-6) << "the diagram and the 3D view show different rays";
    EXPECT_LT((end3d - lc::gui::observerChartToWorld(scene, p)).segment<2>(1).norm(), 3 * pixel);
}

// The image says at once that it is being rendered (the previous image greyed below), and when a
// render shows no object it says why in the view itself: a ball moved beyond the observer's
// Goedel horizon (r = 3 > 2a) has no image (the inverse problem: no null ray reaches it).
TEST_F(Workbench, ImageSaysRenderingAtOnceAndWhyNoObjectIsSeen) {
    window->resize(1400, 860);
    window->docks()->resetLayout();
    open(kData + "default.json");
    EXPECT_TRUE(window->docks()->imageView()->notice().isEmpty());
    EXPECT_FALSE(window->docks()->imageView()->dimmed());
    ASSERT_TRUE(window->sessions()->openFile(kData + "godel_many_images.json"));
    EXPECT_EQ(window->docks()->imageView()->notice(), "rendering...");  // before any work is done
    EXPECT_TRUE(window->docks()->imageView()->dimmed());
    ASSERT_TRUE(waitForCpuImage(*window));
    EXPECT_TRUE(window->docks()->imageView()->notice().isEmpty())
        << window->docks()->imageView()->notice().toStdString();
    EXPECT_FALSE(window->docks()->imageView()->dimmed());

    open(kData + "default.json");
    typeIntoField(*window, "objects[0].centre", "[0, 3, 0, 0]");
    ASSERT_TRUE(waitForCpuImage(*window));
    EXPECT_EQ(window->renderer()->cpuImage()->records.stats.hits, 0u);
    EXPECT_TRUE(window->docks()->imageView()->notice().contains("beyond the observer's Goedel horizon"))
        << window->docks()->imageView()->notice().toStdString();
    EXPECT_EQ(window->docks()->imagesTable()->rowCount(), 0);
    EXPECT_TRUE(
        window->findChild<QDockWidget*>("imagesDock")->windowTitle().contains("beyond the observer's Goedel horizon"));
    EXPECT_FALSE(window->docks()->imageView()->dimmed());                      // the image is this scene's: sky only
    EXPECT_TRUE(lc::test::saveScreenshot(*window, "gui_beyond_horizon.png"));  // docs/GUI.md's
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);             // undo: the ball is seen again
    ASSERT_TRUE(waitForCpuImage(*window));
    EXPECT_GT(window->renderer()->cpuImage()->records.stats.hits, 0u);
    EXPECT_TRUE(window->docks()->imageView()->notice().isEmpty());
}

// Selecting an object (a click on its pixel) emphasises exactly its image paths in the diagram,
// as many as the images table lists, and greys the other object's.
TEST_F(Workbench, SelectedObjectHighlightsExactlyItsImagePathsInTheDiagram) {
    TempFolder tmp;
    std::string text = fileBytes(fs::path(LIGHTCONE_SOURCE_DIR) / "data" / "default.json");
    const std::string rock =
        ",\n    {\"type\": \"sphere\", \"name\": \"rock\", \"centre\": [0, -0.8, 0.6, 0.0], "
        "\"radius\": 0.2, \"texture\": {\"type\": \"checker\", \"cells\": [8, 4], "
        "\"colors\": [[0.2, 0.3, 0.9], [0.9, 0.9, 0.2]]}}";
    const auto end = text.find("\n  ],");
    ASSERT_NE(end, std::string::npos);
    text.insert(end, rock);
    const QString file = tmp / "two_objects.json";
    std::ofstream(file.toStdString()) << text;
    open(file);
    lc::gui::DiagramWidget* diagram = window->docks()->diagramView();
    window->selection()->selectionModel()->selectObject(-1);
    EXPECT_EQ(diagram->numberOfHighlightedImagePaths(), 0);

    int i = -1, j = -1;
    ASSERT_TRUE(innerObjectPixel(window->renderer()->cpuImage()->records, 1, i, j));
    clickPixel(*window, i, j);
    ASSERT_EQ(window->selection()->selectedObject(), 1);
    const int n = window->docks()->imagesTable()->rowCount();
    ASSERT_GT(n, 1);
    EXPECT_EQ(diagram->numberOfHighlightedImagePaths(), n);
    // Read off the chart's plots: the rock's paths wider in their colours, the ball's grey.
    int rockPaths = 0, ballPaths = 0;
    vtkChartXY* chart = diagram->chart();
    for (vtkIdType k = 0; k < chart->GetNumberOfPlots(); ++k) {
        vtkPlot* plot = chart->GetPlot(k);
        const std::string label = plot->GetLabel();
        int winding = -1;
        if (std::sscanf(label.c_str(), "image of '%*[^']': winding %d", &winding) != 1) continue;
        double rgb[3];
        plot->GetColor(rgb);
        bool grey = true;  // the pen keeps 8 bits per channel
        for (int c = 0; c < 3; ++c) grey = grey && std::abs(rgb[c] - lc::views::kDimmedImageColour[c]) < 1.0 / 255;
        if (label.rfind("image of 'rock'", 0) == 0) {
            ++rockPaths;
            EXPECT_FLOAT_EQ(plot->GetWidth(), lc::views::imagePathWidth(winding) + lc::views::kHighlightExtraWidth);
            EXPECT_FALSE(grey) << label;
        } else {
            ++ballPaths;
            EXPECT_FLOAT_EQ(plot->GetWidth(), lc::views::imagePathWidth(winding));
            EXPECT_TRUE(grey) << label;
        }
    }
    EXPECT_EQ(rockPaths, n);
    EXPECT_GT(ballPaths, 0);
    EXPECT_EQ(rockPaths + ballPaths, diagram->numberOfImagePaths());
    // The picked pixel's light path stays highlighted on top.
    EXPECT_NE(diagram->highlightPlot(), nullptr);
}

// Kerr: rays are drawn (integrated), the horizon layer draws the hole's horizon and ergosurface
// (SpacetimeView.KerrHorizonLayerDrawsTheEventHorizonAndTheErgosurface holds them to the closed
// forms), the Goedel-only layers are disabled with the reason as tooltip.
TEST_F(Workbench, NonGodelSceneDisablesTheGodelOnlyLayersAndSaysWhy) {
    open(kData + "kerr.json");
    lc::gui::SpacetimeViewDock* dock = window->docks()->spacetimeView();
    EXPECT_TRUE(dock->layerToggle(SpacetimeView::HORIZON)->isEnabled());
    dock->refresh();
    EXPECT_FALSE(dock->view()->GetLayerActors(SpacetimeView::HORIZON)[0]->GetVisibility()) << "Goedel's";
    EXPECT_GT(drawnPoints(dock->view()->GetLayerActors(SpacetimeView::HORIZON)[1]), 1000) << "Kerr's";
    for (int layer : {SpacetimeView::LIGHT_CONE, SpacetimeView::KILLING_FIELD, SpacetimeView::ORBITS}) {
        SCOPED_TRACE(SpacetimeView::GetLayerName(layer));
        EXPECT_FALSE(dock->layerToggle(layer)->isEnabled());
        EXPECT_TRUE(dock->layerToggle(layer)->toolTip().contains("Goedel"))
            << dock->layerToggle(layer)->toolTip().toStdString();
        EXPECT_TRUE(dock->layerToggle(layer)->toolTip().contains("'kerr'"));
        EXPECT_FALSE(dock->view()->GetLayerActors(layer)[0]->GetVisibility());
    }
    EXPECT_TRUE(dock->layerToggle(SpacetimeView::WORLD_LINES)->toolTip().contains("no object"));
    EXPECT_TRUE(dock->layerToggle(SpacetimeView::GEODESICS)->isEnabled());
    EXPECT_GT(drawnPoints(dock->view()->GetLayerActors(SpacetimeView::GEODESICS)[0]), 0);
    EXPECT_EQ(dock->view()->GetExecutionCount(SpacetimeView::HORIZON_SOURCE), 1) << "Kerr's horizon, once";
    // The chart choice still works, a click on a disabled box changes nothing.
    clickToggle(*window, SpacetimeView::ORBITS);
    EXPECT_FALSE(dock->view()->GetLayerVisibility(SpacetimeView::ORBITS));
    EXPECT_EQ(dock->view()->GetExecutionCount(SpacetimeView::ORBIT_SOURCE), 0);
    dock->chartChoice()->setCurrentIndex(1);  // r, phi, t
    QApplication::processEvents();
    EXPECT_EQ(dock->view()->GetOutputChart(), 1);
    EXPECT_TRUE(dock->layerToggle(SpacetimeView::PHOTO_OBJECTS)->toolTip().contains("Embedding"));
}

// The screenshots of docs/GUI.md, taken on the way through a short tour (scripts/screenshots
// copies them into docs/images). Each step also checks what the screenshot is meant to show.
TEST_F(Workbench, TourScreenshots) {
    auto shoot = [&](const char* name) { ASSERT_TRUE(lc::test::saveScreenshot(*window, name)); };
    window->resize(1280, 800);  // #46: the screen size a laptop user has
    window->docks()->resetLayout();
    // 1. Open a scene: the shader image, the diagram, the properties.
    open(kData + "default.json");
    shoot("gui_open_scene.png");
    // 2. Pick an image of the ball: its light path in the diagram, its data in the status bar.
    int i = -1, j = -1;
    ASSERT_TRUE(innerObjectPixel(window->renderer()->cpuImage()->records, 0, i, j));
    clickPixel(*window, i, j);
    ASSERT_NE(window->docks()->diagramView()->highlightPlot(), nullptr);
    ASSERT_TRUE(window->docks()->spacetimeView()->view()->HasHighlightedRay());
    shoot("gui_linked_views.png");  // the same ray in the image, the diagram and the 3D view
    window->docks()->imagesTable()->selectRow(1);
    ASSERT_GE(window->selection()->markedPixel().first, 0);
    shoot("gui_pick_image.png");
    // 3. Move the observer in the properties dock; a refused value shows the reader's reason.
    typeIntoField(*window, "observer.position", "[0, -0.3, 0.2, 0]");
    ASSERT_TRUE(waitForCpuImage(*window));
    typeIntoField(*window, "metric.a", "-2");
    ASSERT_FALSE(window->docks()->properties()->refusalText().isEmpty());
    shoot("gui_move_observer.png");
    // 4. Post-rendering: the CPU's per-pixel data coloured again on the GPU, black body checked.
    open(kData + "godel_many_images.json");
    window->findChild<QDockWidget*>("postRenderDock")->raise();
    QTest::qWait(50);
    lc::gui::PostRenderDock* post = window->docks()->postRenderView();
    ASSERT_TRUE(post->enableBox()->isEnabled());
    for (QCheckBox* box : {post->enableBox(), post->temperatureBox()})
        QTest::mouseClick(box, Qt::LeftButton, Qt::NoModifier, QPoint(8, box->height() / 2));
    ASSERT_EQ(window->renderer()->imageSource(), "post-render");
    shoot("gui_post_render.png");
    QTest::mouseClick(post->enableBox(), Qt::LeftButton, Qt::NoModifier, QPoint(8, post->enableBox()->height() / 2));
    window->findChild<QDockWidget*>("propertiesDock")->raise();
    // 5. A Kerr scene while its CPU data is traced: shader image, progress bar and Cancel.
    ASSERT_TRUE(window->sessions()->openScene(kData + "kerr.json"));
    QTest::qWait(400);
    ASSERT_TRUE(window->renderer()->rendering());
    shoot("gui_kerr_rendering.png");
    window->renderer()->cancel();
    // 6. An accretion disk: the brightest pixel picked, what its colour is made of in the status bar.
    open(kData + "kerr_disk.json");
    auto [di, dj] = brightestDiskPixel(window->renderer()->cpuImage()->records);
    clickPixel(*window, di, dj);
    ASSERT_TRUE(window->report()->statusText().contains("disk 'disk'")) << window->report()->statusText().toStdString();
    shoot("gui_accretion_disk.png");
}

// The time machine in the workbench (docs/PHYSICS.md section 11): the scene opens with both ages
// of the traveller in view, a pick lists the images with their ages, and the tool bar's slider
// moves the observer's proper time (one undoable edit): before the traveller is back only the
// younger one is seen. Oracle: the ages lc::ageImages solves for the edited scene (closed forms).
TEST_F(Workbench, TimeTravellerShowsTwoAgesAndTheSliderMovesTheObserversTime) {
    if (std::getenv("LIGHTCONE_SCREENSHOT_DIR") == nullptr) window->resize(1400, 860);
    open(kData + "godel_time_traveller.json");
    auto ages = [&] {
        std::set<int> older;  // 0: waiting to leave (tau < 30), 1: back from the trip
        for (const lc::AgeImage& a : lc::ageImages(window->activeScene()->scene().scene()))
            older.insert(a.properTime > 30);
        return older;
    };
    EXPECT_EQ(ages().size(), 2u);
    // Pick the traveller: the images table lists its images with their ages (column 8).
    int i = -1, j = -1;
    ASSERT_TRUE(innerObjectPixel(window->renderer()->cpuImage()->records, 0, i, j));
    clickPixel(*window, i, j);
    ASSERT_EQ(window->selection()->selectedObject(), 0);
    std::set<int> listed;
    for (int row = 0; row < window->docks()->imagesTable()->rowCount(); ++row)
        listed.insert(window->docks()->imagesTable()->item(row, 8)->text().toDouble() > 30);
    EXPECT_EQ(listed.size(), 2u);
    // The pick says the age of the image it hit and selects that image's row (#46 item 5): one of
    // the ages lc::ageImages solves, the row's own.
    lc::gui::ImagesTable* table = window->docks()->imagesTable();
    const QString said = window->report()->statusText();
    const int at = said.indexOf("age (proper time) at emission ");
    ASSERT_GE(at, 0) << said.toStdString();
    const double age = said.mid(at + 30).section(';', 0, 0).toDouble();
    bool solved = false;
    for (const lc::AgeImage& a : lc::ageImages(window->activeScene()->scene().scene()))
        solved = solved || std::abs(a.properTime - age) < 1e-4;
    EXPECT_TRUE(solved) << said.toStdString();
    ASSERT_EQ(table->selectionModel()->selectedRows().size(), 1);
    const int row = table->selectionModel()->selectedRows()[0].row();
    EXPECT_NEAR(table->item(row, 8)->text().toDouble(), age, 1e-12);
    EXPECT_TRUE(said.contains(QString("its image in row %1 of the images table").arg(row + 1))) << said.toStdString();
    // For papers (#46 item 8): the table and the picked pixel as CSV, cell for cell and value for value.
    const fs::path csv = fs::temp_directory_path() / ("lc-traveller-" + std::to_string(::getpid()));
    fs::create_directories(csv);
    ASSERT_TRUE(window->exports()->exportImagesTable(QString::fromStdString((csv / "images.csv").string())))
        << window->report()->lastError().toStdString();
    std::ifstream tableFile(csv / "images.csv");
    std::vector<std::string> lines;
    for (std::string line; std::getline(tableFile, line);) lines.push_back(line);
    ASSERT_EQ(static_cast<int>(lines.size()), table->rowCount() + 1);
    EXPECT_EQ(lines[0],
              "winding,branch,psi (deg),phi (deg),emission t,nu_obs/nu_em,affine depth,pixel,age (proper time)");
    for (int r = 0; r < table->rowCount(); ++r) {
        QStringList cells;
        for (int c = 0; c < table->columnCount(); ++c) {
            const QString t = table->item(r, c)->text();
            cells << (t.contains(',') ? '"' + t + '"' : t);  // RFC 4180: the pixel "i, j" quoted
        }
        EXPECT_EQ(lines[static_cast<std::size_t>(r) + 1], cells.join(',').toStdString());
    }
    ASSERT_TRUE(window->exports()->exportPick(QString::fromStdString((csv / "pixel.csv").string())));
    std::ifstream pickFile(csv / "pixel.csv");
    std::map<std::string, std::string> values;
    for (std::string line; std::getline(pickFile, line);)
        values[line.substr(0, line.find(','))] =
            line.substr(line.find(',') + 1, line.find(',', line.find(',') + 1) - line.find(',') - 1);
    const lc::PixelRecord& picked = record(*window, window->selection()->pickedI(), window->selection()->pickedJ());
    EXPECT_EQ(values["kind"], "object");
    EXPECT_EQ(std::stod(values["g"]), static_cast<double>(picked.frequencyRatio));
    EXPECT_EQ(std::stod(values["emission_time"]), static_cast<double>(picked.emissionTime));
    EXPECT_EQ(std::stoi(values["i"]), window->selection()->pickedI());
    EXPECT_FALSE(window->exports()->exportPick(QString::fromStdString((csv / "pixel.txt").string())));
    EXPECT_TRUE(window->report()->lastError().contains(".csv")) << window->report()->lastError().toStdString();
    fs::remove_all(csv);
    const std::string dir = std::getenv("LIGHTCONE_SCREENSHOT_DIR") ? std::getenv("LIGHTCONE_SCREENSHOT_DIR") : "";
    if (!dir.empty()) {
        ASSERT_TRUE(window->grab().toImage().save(QString::fromStdString(dir + "/gui_time_traveller.png")));
    }
    // Seven page steps back (7 units of proper time, t = -10): the older one is not back yet.
    lc::gui::ObserverTimeSlider* slider = window->docks()->observerTimeSlider();
    ASSERT_TRUE(slider->isEnabled());
    slider->slider()->setFocus();
    for (int k = 0; k < 7; ++k) QTest::keyClick(slider->slider(), Qt::Key_PageDown);
    QElapsedTimer t;
    t.start();
    while (std::abs(window->activeScene()->scene().scene().observer(0) + 10) > 1e-9 && t.elapsed() < 5000)
        QTest::qWait(20);
    EXPECT_NEAR(window->activeScene()->scene().scene().observer(0), -10, 1e-9);
    ASSERT_TRUE(waitForCpuImage(*window));
    EXPECT_EQ(ages(), std::set<int>{0});
    EXPECT_NEAR(slider->properTime(), -7, 1e-9);
    // Undo brings the observer back to the file's time, and the slider with it.
    window->activeScene()->undoStack()->undo();
    ASSERT_TRUE(waitForCpuImage(*window));
    EXPECT_NEAR(window->activeScene()->scene().scene().observer(0), -3, 1e-9);
    EXPECT_NEAR(slider->properTime(), 0, 1e-9);
    EXPECT_EQ(ages().size(), 2u);
}

// A number field's tooltip gives its accepted range, unit and why, as the scene reader checks it:
// the text the reader's refusal of a bad value quotes (an independent path: the edit is refused).
TEST_F(Workbench, PropertyTooltipsGiveTheRangeTheReaderEnforces) {
    open(kData + "default.json");
    lc::gui::PropertiesPanel* panel = window->docks()->properties();
    QTreeWidgetItem* radius = panel->itemOf("objects[0].radius");
    ASSERT_NE(radius, nullptr);
    // Shown as Qt shows tooltips: a ToolTip event on the tree's viewport over the value.
    QTreeWidget* tree = panel->tree();
    tree->scrollToItem(radius);
    const QRect cell = tree->visualItemRect(radius);
    const QPoint at(tree->header()->sectionPosition(1) + 10, cell.center().y());
    QHelpEvent help(QEvent::ToolTip, at, tree->viewport()->mapToGlobal(at));
    QApplication::sendEvent(tree->viewport(), &help);
    QApplication::processEvents();
    const QString tip = QToolTip::text();
    EXPECT_TRUE(tip.startsWith("objects[0].radius: ")) << tip.toStdString();
    EXPECT_TRUE(tip.contains("accepted: a number in [")) << tip.toStdString();
    // The reader refuses a value outside it, quoting the same range.
    typeIntoField(*window, "objects[0].radius", "-0.5");
    const QString refusal = panel->refusalText();
    const int from = tip.indexOf("a number in");
    const QString range = tip.mid(from, tip.indexOf(']', from) - from + 1);  // "a number in [lo, hi]"
    EXPECT_TRUE(refusal.contains("expected " + range)) << refusal.toStdString() << " / " << range.toStdString();
    // Units and metric parameters too.
    EXPECT_TRUE(panel->itemOf("camera.fov")->toolTip(1).contains("deg"))
        << panel->itemOf("camera.fov")->toolTip(1).toStdString();
    EXPECT_TRUE(panel->itemOf("metric.a")->toolTip(1).contains("accepted: a number in"))
        << panel->itemOf("metric.a")->toolTip(1).toStdString();
    // Grey defaults (fields the file leaves out) give the range an edit may set, which the
    // reader then enforces: here the render method's tolerance and windings of a plain scene.
    const fs::path plain = fs::temp_directory_path() / ("lc-plain-" + std::to_string(::getpid()) + ".json");
    std::ofstream(plain) << R"({"metric": {"name": "godel"}, "camera": {"width": 64, "height": 32}})";
    open(QString::fromStdString(plain.string()));
    for (const char* field : {"metric.a", "render.tolerance", "render.windings"}) {
        QTreeWidgetItem* item = panel->itemOf(field);
        ASSERT_NE(item, nullptr) << field;
        const QString greyTip = item->toolTip(1);
        ASSERT_GE(greyTip.indexOf(QString(field) + ": "), 0) << greyTip.toStdString();
        const int accepted = greyTip.indexOf("accepted: ");
        ASSERT_GE(accepted, 0) << greyTip.toStdString();
        const int start = accepted + 10;
        const QString greyRange = greyTip.mid(start, greyTip.indexOf(']', start) - start + 1);
        typeIntoField(*window, field, "1e9");
        EXPECT_TRUE(panel->refusalText().contains("expected " + greyRange))
            << field << ": " << panel->refusalText().toStdString() << " / " << greyRange.toStdString();
    }
    fs::remove(plain);
}

TEST_F(Workbench, HoverShowsThePixelAndTheLayoutIsRememberedBetweenRuns) {
    open(kData + "default.json");
    int i = -1, j = -1;
    ASSERT_TRUE(innerObjectPixel(window->renderer()->cpuImage()->records, 0, i, j));
    QMouseEvent move(QEvent::MouseMove, window->docks()->imageView()->widgetPointOfPixel(i, j), Qt::NoButton,
                     Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(window->docks()->imageView(), &move);
    QApplication::processEvents();
    EXPECT_TRUE(QToolTip::text().contains("object 'ball'")) << QToolTip::text().toStdString();

    // A dock closed in one run stays closed in the next (QSettings, written on close).
    auto* images = window->findChild<QDockWidget*>("imagesDock");
    ASSERT_NE(images, nullptr);
    images->close();
    ASSERT_TRUE(window->close());
    window.reset();
    lc::gui::MainWindow next;
    next.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&next));
    EXPECT_FALSE(next.findChild<QDockWidget*>("imagesDock")->isVisible());
    next.docks()->resetLayout();  // and View > Reset layout brings it back
    EXPECT_TRUE(next.findChild<QDockWidget*>("imagesDock")->isVisible());
    next.close();
}

TEST_F(Workbench, AboutNamesTheVersionsAndTheOpenGLRenderer) {
    const QString about = lc::gui::WorkbenchMenus::aboutText(*window->docks());
    for (const char* what :
         {"Lightcone 0.", "(commit ", "VTK 9", "Qt 5", "OpenImageIO 2", "OpenGL renderer", "BSD-3-Clause"})
        EXPECT_TRUE(about.contains(what)) << what << " missing in: " << about.toStdString();
    EXPECT_FALSE(about.contains("OpenGL renderer: unknown")) << about.toStdString();
}

}  // namespace

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    // Listing the tests (gtest_discover_tests at build time) needs no display.
    if (::testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();
    // QSettings of this process only: not the user's, and not shared with the test processes
    // ctest runs in parallel (the layout test closes and reopens a window).
    const fs::path settings = fs::temp_directory_path() / ("lc-gui-settings-" + std::to_string(::getpid()));
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, QString::fromStdString(settings.string()));
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName("LightconeTests");
    QCoreApplication::setApplicationName("gui_tests");
    const int rc = RUN_ALL_TESTS();
    fs::remove_all(settings);
    return rc;
}
