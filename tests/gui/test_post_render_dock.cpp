// SPDX-License-Identifier: BSD-3-Clause
// The post-rendering dock through real Qt events (clicks on its check boxes, keys on its sliders
// and combo boxes): each change draws on the GPU without tracing, and the image equals the CPU
// reference lc::shadePixels of the settings the controls describe (to one 8-bit level), and the
// controls mean what their labels say (a hotter black body is bluer, a time window hides light).
#include "workbench_test_support.hpp"

#include "main_window.hpp"
#include "post_render_dock.hpp"

#include "core/render/render.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/scene_reader.hpp"

#include <QCheckBox>
#include <QLabel>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>

#include <gtest/gtest.h>

#include <cmath>

namespace {

struct PostRenderDockTest : ::testing::Test {
    void SetUp() override {
        scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/godel_many_images.json");
        scene.camera.width = 200;
        scene.camera.height = 80;
        auto image = std::make_shared<lc::ColouredImage>();
        image->records = lc::render(scene);
        image->rgb = lc::shadePixels(scene, image->records);
        data = image;
        dock.setInput(scene, data);
        dock.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&dock));
    }
    // Pixels farther than one level from the CPU reference of the dock's settings.
    std::size_t disagreeing() const {
        const std::vector<float> ref = lc::shadePixels(scene, data->records, dock.settings());
        const std::vector<unsigned char>& gpu = dock.lastSrgb();
        EXPECT_EQ(gpu.size(), ref.size());
        std::size_t bad = 0;
        for (std::size_t k = 0; k < std::min(gpu.size(), ref.size()); ++k)
            bad += std::abs(int(gpu[k]) - int(std::lround(255.0f * lc::io::srgbEncode(ref[k])))) > 1;
        return bad;
    }
    double meanBlueOverRed() const {
        double red = 0, blue = 0;
        const auto& g = dock.lastSrgb();
        for (std::size_t p = 0; p < data->records.pixels.size(); ++p)
            if (data->records.pixels[p].kind == lc::PixelRecord::Object) {
                red += g[3 * p];
                blue += g[3 * p + 2];
            }
        return blue / red;
    }
    lc::Scene scene;
    std::shared_ptr<const lc::ColouredImage> data;
    lc::gui::PostRenderDock dock;
};

void click(QCheckBox* box) { QTest::mouseClick(box, Qt::LeftButton, {}, QPoint(8, box->height() / 2)); }

TEST_F(PostRenderDockTest, SlidersRedrawOnTheGpuAsShadeWouldColour) {
    qRegisterMetaType<std::vector<float>>();
    QSignalSpy drawn(&dock, &lc::gui::PostRenderDock::imageReady);
    click(dock.enableBox());
    ASSERT_TRUE(dock.active());
    ASSERT_GE(drawn.count(), 1);
    EXPECT_EQ(disagreeing(), 0u);

    // (a) another texture, turned by the u offset slider.
    dock.textureChoice()->setFocus();
    QTest::keyClick(dock.textureChoice(), Qt::Key_Down);
    EXPECT_EQ(dock.textureChoice()->currentIndex(), 1);
    QTest::keyClick(dock.uOffsetSlider(), Qt::Key_PageUp);
    EXPECT_GT(dock.settings().uOffset, 0.0);
    EXPECT_EQ(disagreeing(), 0u);

    // (b) a black body, hotter with each page: bluer.
    click(dock.temperatureBox());
    ASSERT_TRUE(dock.settings().temperature.has_value());
    const double coolRatio = meanBlueOverRed();
    const double cool = *dock.settings().temperature;
    for (int k = 0; k < 5; ++k) QTest::keyClick(dock.temperatureSlider(), Qt::Key_PageUp);
    EXPECT_GT(*dock.settings().temperature, cool);
    // The value beside the slider is the temperature the image is drawn at (#46 item 4).
    EXPECT_EQ(dock.valueText(dock.temperatureSlider()), QString("%1 K").arg(*dock.settings().temperature, 0, 'f', 0));
    bool shown = false;
    for (const QLabel* l : dock.findChildren<QLabel*>())
        shown = shown || (!l->isHidden() && l->text() == dock.valueText(dock.temperatureSlider()));
    EXPECT_TRUE(shown) << "no label beside the slider shows " << dock.valueText(dock.temperatureSlider()).toStdString();
    EXPECT_GT(meanBlueOverRed(), coolRatio);
    EXPECT_EQ(disagreeing(), 0u);
    click(dock.temperatureBox());

    // (c) a time window: fewer object pixels keep their colour; over a second texture they return.
    click(dock.windowBox());
    ASSERT_TRUE(dock.settings().timeWindow.has_value());
    EXPECT_LE(disagreeing(), 1u);
    QTest::keyClick(dock.outsideChoice(), Qt::Key_Down);
    EXPECT_NE(dock.settings().outsideTexture, nullptr);
    EXPECT_LE(disagreeing(), 1u);

    // Blinking, its phase moved by a key.
    click(dock.blinkBox());
    QTest::keyClick(dock.blinkPhaseSlider(), Qt::Key_PageUp);
    EXPECT_GT(dock.settings().blinkPeriod, 0.0);
    EXPECT_LE(disagreeing(), 2u);
    EXPECT_GE(drawn.count(), 8);
    EXPECT_LT(dock.lastSeconds(), 2.0);
}

// In the workbench: the dock follows each CPU render, and the image it draws replaces the one
// shown until it is switched off again.
TEST(PostRenderDock, InTheWorkbenchItRecoloursTheShownImageWithoutTracing) {
    lc::gui::MainWindow w;
    w.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
    ASSERT_TRUE(w.sessions()->openScene(QString(LIGHTCONE_SOURCE_DIR) + "/data/godel_many_images.json"));
    QElapsedTimer t;
    t.start();
    while ((w.renderer()->rendering() || !w.renderer()->cpuImage()) && t.elapsed() < 60000) QTest::qWait(20);
    ASSERT_NE(w.renderer()->cpuImage(), nullptr);
    lc::gui::PostRenderDock* dock = w.docks()->postRenderView();
    w.findChild<QDockWidget*>("postRenderDock")->raise();
    QTest::qWait(50);
    ASSERT_TRUE(dock->enableBox()->isEnabled());
    click(dock->enableBox());
    click(dock->temperatureBox());
    EXPECT_EQ(w.renderer()->imageSource(), "post-render");
    const lc::Scene& scene = w.activeScene()->scene().scene();
    const std::vector<float> ref = lc::shadePixels(scene, w.renderer()->cpuImage()->records, dock->settings());
    ASSERT_EQ(w.renderer()->shownImage().size(), ref.size());
    std::size_t bad = 0;
    for (std::size_t k = 0; k < ref.size(); ++k)
        bad += std::abs(std::lround(255.0f * lc::io::srgbEncode(w.renderer()->shownImage()[k])) -
                        std::lround(255.0f * lc::io::srgbEncode(ref[k]))) > 1;
    EXPECT_EQ(bad, 0u);
    click(dock->enableBox());
    EXPECT_EQ(w.renderer()->imageSource(), "cpu");
    EXPECT_TRUE(w.renderer()->shownImage() == w.renderer()->cpuImage()->rgb);
}

TEST(PostRenderDock, WithoutDataTheControlsAreOff) {
    lc::gui::PostRenderDock dock;
    EXPECT_FALSE(dock.enableBox()->isEnabled());
    EXPECT_FALSE(dock.active());
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/godel_many_images.json");
    auto bad = std::make_shared<lc::ColouredImage>();
    bad->records.width = 2;
    bad->records.height = 1;
    bad->records.pixels.resize(2);
    bad->records.pixels[1].kind = lc::PixelRecord::Object;
    bad->records.pixels[1].object = 9;  // no such object: refused, the dock stays off
    dock.setInput(scene, bad);
    EXPECT_FALSE(dock.enableBox()->isEnabled());
}

}  // namespace
