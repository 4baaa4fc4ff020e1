// The linked views of lightcone-gui (app/gui): a click on an image of the sphere highlights
// exactly one light path in the r-phi diagram, which ends on the sphere, and the status bar
// names the object; a click on the background highlights nothing. Needs an X display
// (ctest runs under xvfb-run, README).
#include "lightconeEgocentricImageWidget.h"
#include "lightconeMainWindow.h"
#include "lightconeRPhiDiagramWidget.h"

#include "readers/io/scene_reader.hpp"

#include <QApplication>
#include <QSlider>
#include <QSpinBox>
#include <QSurfaceFormat>
#include <QTest>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkChartXY.h>
#include <vtkDoubleArray.h>
#include <vtkPlot.h>
#include <vtkTable.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

namespace {

const std::string kDefaultScene = std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json";

struct Region {
    long count = 0;
    double si = 0, sj = 0;
    int minJ = 1 << 30;
};

// A pixel deep inside the largest image of object `object` (pixels bucketed by emission
// time), halfway between its centroid and its top row: off the image's horizontal midline, so
// that a picking error that mirrors rows lands elsewhere.
bool innerObjectPixel(const lc::RenderResult& r, int object, int& pi, int& pj) {
    std::map<int, Region> byTime;  // images differ in emission time: bucket by it
    for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i) {
            const auto& p = r.pixels[static_cast<std::size_t>(j) * r.width + i];
            if (p.kind != lc::PixelRecord::Object || p.object != object) continue;
            auto& reg = byTime[static_cast<int>(std::floor(p.emissionTime))];
            ++reg.count;
            reg.si += i;
            reg.sj += j;
            reg.minJ = std::min(reg.minJ, j);
        }
    if (byTime.empty()) return false;
    int bucket = byTime.begin()->first;
    for (const auto& [k, reg] : byTime)
        if (reg.count > byTime[bucket].count) bucket = k;
    const Region& reg = byTime[bucket];
    const double ci = reg.si / reg.count, cj = 0.5 * (reg.sj / reg.count + reg.minJ);
    double best = 1e300;
    for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i) {
            const auto& p = r.pixels[static_cast<std::size_t>(j) * r.width + i];
            if (p.kind != lc::PixelRecord::Object || p.object != object ||
                static_cast<int>(std::floor(p.emissionTime)) != bucket)
                continue;
            // Deep inside: all four neighbours show the object too.
            bool inner = i > 0 && j > 0 && i + 1 < r.width && j + 1 < r.height;
            for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
                if (inner) inner = r.pixels[static_cast<std::size_t>(j + dj) * r.width + i + di].kind == lc::PixelRecord::Object;
            const double d2 = (i - ci) * (i - ci) + (j - cj) * (j - cj);
            if (inner && d2 < best) {
                best = d2;
                pi = i;
                pj = j;
            }
        }
    return best < 1e300;
}

class GuiTest : public ::testing::Test {
protected:
    void SetUp() override {
        window = std::make_unique<lcgui::MainWindow>(lc::io::readScene(kDefaultScene), 240, 80);
        window->resize(900, 400);
        window->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
        QApplication::processEvents();
    }
    void click(int i, int j) {
        auto* image = window->imageView();
        const QPoint at = image->widgetPointOfPixel(i, j);
        ASSERT_TRUE(image->rect().contains(at)) << "pixel (" << i << ", " << j << ") maps outside the widget";
        QTest::mouseClick(image, Qt::LeftButton, Qt::NoModifier, at);
        QApplication::processEvents();
    }
    int countHighlightedPlots() const {
        vtkChartXY* chart = window->diagramView()->chart();
        int n = 0;
        for (vtkIdType k = 0; k < chart->GetNumberOfPlots(); ++k)
            if (std::string(chart->GetPlot(k)->GetLabel()).rfind("picked", 0) == 0) ++n;
        return n;
    }
    // The highlighted path starts at the observer and ends on the sphere's surface, at the
    // picked pixel's emission event.
    void expectHighlightEndsOnSphere(const lc::PixelRecord& p) {
        const auto& ball = window->session().scene().spheres[0];
        vtkPlot* plot = window->diagramView()->highlightPlot();
        ASSERT_NE(plot, nullptr);
        vtkTable* table = plot->GetInput();
        ASSERT_NE(table, nullptr);
        ASSERT_GT(table->GetNumberOfRows(), 10);
        const vtkIdType last = table->GetNumberOfRows() - 1;
        auto col = [&](const char* name, vtkIdType row) {
            auto* a = vtkDoubleArray::SafeDownCast(table->GetColumnByName(name));
            return a ? a->GetValue(row) : std::nan("");
        };
        // Starts at the observer, ends where it was emitted: on the sphere's surface.
        EXPECT_NEAR(col("x", 0), 0, 1e-12);
        EXPECT_NEAR(col("y", 0), 0, 1e-12);
        const lc::Vec4 endObserverChart(col("t", last), col("x", last), col("y", last), col("z", last));
        const lc::Vec4 endWorld = window->session().toWorld(endObserverChart);
        const double localRadius = ball.placement->toLocal(endWorld).norm();
        EXPECT_LE(localRadius, ball.radius + 1e-3) << "the highlighted path ends off the sphere";
        EXPECT_GE(localRadius, ball.radius - 1e-3) << "the highlighted path ends inside the sphere, not on it";
        EXPECT_NEAR(endWorld(0), p.emissionTime, 1e-4);
        // The path is a ray of the observer: it is not trivially short.
        EXPECT_GT(p.affine, 0.1);
    }
    std::unique_ptr<lcgui::MainWindow> window;
};

TEST_F(GuiTest, ClickOnSphereImageHighlightsItsLightPathEndingOnTheSphere) {
    const auto& scene = window->session().scene();
    ASSERT_EQ(scene.spheres.size(), 1u);
    const int plotsBefore = static_cast<int>(window->diagramView()->chart()->GetNumberOfPlots());
    EXPECT_EQ(countHighlightedPlots(), 0);

    int i = -1, j = -1;
    ASSERT_TRUE(innerObjectPixel(window->session().result(), 0, i, j)) << "the default scene shows no sphere";
    click(i, j);

    // The click went through VTK's interactor and landed on exactly the pixel aimed at.
    ASSERT_GE(window->pickedI(), 0) << "the click picked no pixel";
    EXPECT_EQ(window->pickedI(), i);
    EXPECT_EQ(window->pickedJ(), j);
    const lc::PixelRecord& p = window->session().pixel(window->pickedI(), window->pickedJ());
    ASSERT_EQ(p.kind, lc::PixelRecord::Object);

    // Exactly one highlighted path in the diagram.
    EXPECT_EQ(static_cast<int>(window->diagramView()->chart()->GetNumberOfPlots()), plotsBefore + 1);
    EXPECT_EQ(countHighlightedPlots(), 1);
    expectHighlightEndsOnSphere(p);

    const QString status = window->statusText();
    EXPECT_TRUE(status.contains("'ball'")) << status.toStdString();
    EXPECT_TRUE(status.contains("emitted")) << status.toStdString();

    // A second pick replaces the first highlight.
    click(i, j);
    EXPECT_EQ(countHighlightedPlots(), 1);
}

TEST_F(GuiTest, ClickOnBackgroundHighlightsNothing) {
    const auto& r = window->session().result();
    // First a sphere pick, so that clearing is tested, then a background pixel.
    int i = -1, j = -1;
    ASSERT_TRUE(innerObjectPixel(r, 0, i, j));
    click(i, j);
    ASSERT_EQ(countHighlightedPlots(), 1);
    int bi = -1, bj = -1;
    for (int jj = 2; jj < r.height - 2 && bi < 0; ++jj)
        for (int ii = 2; ii < r.width - 2 && bi < 0; ++ii)
            if (r.pixels[static_cast<std::size_t>(jj) * r.width + ii].kind != lc::PixelRecord::Object) {
                bool allBackground = true;
                for (int dj = -2; dj <= 2; ++dj)
                    for (int di = -2; di <= 2; ++di)
                        if (r.pixels[static_cast<std::size_t>(jj + dj) * r.width + ii + di].kind == lc::PixelRecord::Object)
                            allBackground = false;
                if (allBackground) bi = ii, bj = jj;
            }
    ASSERT_GE(bi, 0);
    click(bi, bj);
    ASSERT_GE(window->pickedI(), 0);
    EXPECT_NE(window->session().pixel(window->pickedI(), window->pickedJ()).kind, lc::PixelRecord::Object);
    EXPECT_EQ(countHighlightedPlots(), 0);
    EXPECT_EQ(window->diagramView()->highlightPlot(), nullptr);
    EXPECT_FALSE(window->statusText().contains("ball")) << window->statusText().toStdString();
    EXPECT_TRUE(window->statusText().contains("background")) << window->statusText().toStdString();
}

TEST_F(GuiTest, WindingsAndYawReRenderAndRebuildTheDiagram) {
    const int pathsBefore = window->diagramView()->numberOfImagePaths();
    window->windingsBox()->setValue(window->windingsBox()->value() + 1);
    QApplication::processEvents();
    EXPECT_GT(window->diagramView()->numberOfImagePaths(), pathsBefore);
    EXPECT_EQ(window->session().windings(), window->windingsBox()->value());

    // Yaw by 90 degrees to the left (azimuth grows to the left): the 360-degree panorama
    // shifts right by a quarter of its width.
    const auto before = window->session().result().pixels;
    window->yawSlider()->setValue(90);
    QApplication::processEvents();
    EXPECT_DOUBLE_EQ(window->session().yawDegrees(), 90.0);
    const auto& r = window->session().result();
    long same = 0, objects = 0;
    for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i) {
            const auto& now = r.pixels[static_cast<std::size_t>(j) * r.width + i];
            const auto& then = before[static_cast<std::size_t>(j) * r.width + (i - r.width / 4 + r.width) % r.width];
            if (then.kind == lc::PixelRecord::Object || now.kind == lc::PixelRecord::Object) {
                ++objects;
                if (then.kind == now.kind) ++same;
            }
        }
    ASSERT_GT(objects, 0);
    EXPECT_GT(static_cast<double>(same) / objects, 0.9);

    // Picking still links after the camera turned and the windings changed.
    int i = -1, j = -1;
    ASSERT_TRUE(innerObjectPixel(r, 0, i, j));
    click(i, j);
    ASSERT_GE(window->pickedI(), 0);
    const lc::PixelRecord& p = window->session().pixel(window->pickedI(), window->pickedJ());
    ASSERT_EQ(p.kind, lc::PixelRecord::Object);
    EXPECT_EQ(countHighlightedPlots(), 1);
    expectHighlightEndsOnSphere(p);
}

}  // namespace

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    // Listing the tests (gtest_discover_tests at build time) needs no display.
    if (::testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication app(argc, argv);
    return RUN_ALL_TESTS();
}
