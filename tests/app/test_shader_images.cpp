// SPDX-License-Identifier: BSD-3-Clause
// Every scene of data/ on the shader path `lightcone render --gpu` takes for it
// (lc::cli::renderShaderImage: the Goedel photo-object mapper, the special-relativity mappers or the
// fragment-shader geodesic tracer, in float) against the CPU image of the same scene
// (lc::renderColouredImage: the closed form or the inverse problem per vertex, SR local ray tracing,
// or odeint in double), 192 pixels wide, over the pixels where either image shows something. They
// differ only where a silhouette, a texel or a checker edge falls between a float and a double
// answer (measured: at most 1.1 % of those pixels by more than 0.1, mean difference at most 0.009,
// the many-images scene): the test allows 3 % and 0.015; a wrong formula, frame or technique
// changes most pixels. Gödel scenes are drawn twice: as the command line does, and as the
// workbench does, from the photo scene its worker thread built (lc::buildPhotoScene with
// vertexLight, which lights the vertices there, off the GUI thread).
#include "app/commands/commands.hpp"
#include "core/render/photo_scene.hpp"
#include "core/render/special_relativity.hpp"
#include "readers/io/scene_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

std::vector<std::string> dataScenes() {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(std::string(LIGHTCONE_SOURCE_DIR) + "/data"))
        if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

class ShaderImages : public ::testing::TestWithParam<std::string> {};

TEST_P(ShaderImages, MatchTheCpuImageOfTheScene) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "the shader renderers need an X display (xvfb-run -a)";
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/" + GetParam() + ".json",
                                        lc::cli::sceneReadOptions());
    const int width = 192;
    scene.camera.height = std::max(1, int(std::lround(double(width) * scene.camera.height / scene.camera.width)));
    scene.camera.width = width;
    scene.settings.progress = false;
    ASSERT_NE(lc::cli::shaderPathFor(scene), lc::cli::ShaderPath::None) << "no shader path for " << GetParam();
    const lc::ColouredImage cpu = lc::renderColouredImage(scene);
    std::vector<std::vector<float>> gpus{lc::cli::renderShaderImage(scene, nullptr)};
    if (lc::cli::shaderPathFor(scene) == lc::cli::ShaderPath::Godel) {
        lc::PhotoSceneOptions workbench = lc::photoSceneOptions(scene);
        workbench.vertexLight = true;  // as app/gui/render_job.cpp builds them
        gpus.push_back(lc::cli::renderShaderImage(
            scene, std::make_shared<const std::vector<lc::PhotoSceneObject>>(lc::buildPhotoScene(scene, workbench))));
    }
    for (const std::vector<float>& gpu : gpus) {
        ASSERT_EQ(gpu.size(), cpu.rgb.size());
        // Over the pixels where either image shows something (not the background).
        const std::size_t pixels = gpu.size() / 3;
        std::size_t shown = 0, differing = 0;
        double sum = 0;
        for (std::size_t p = 0; p < pixels; ++p) {
            double worst = 0, fromBackground = 0, pixelSum = 0;
            for (int c = 0; c < 3; ++c) {
                // The framebuffer holds [0, 1], as an image file; a lit side may exceed 1 on the CPU.
                const double d = std::abs(double(gpu[3 * p + c]) - std::clamp(double(cpu.rgb[3 * p + c]), 0.0, 1.0));
                worst = std::max(worst, d);
                pixelSum += d;
                fromBackground = std::max({fromBackground, std::abs(cpu.rgb[3 * p + c] - scene.background(c)),
                                           std::abs(gpu[3 * p + c] - scene.background(c))});
            }
            if (fromBackground < 0.02) continue;
            ++shown;
            differing += worst > 0.1;
            sum += pixelSum / 3;
        }
        const double mean = shown ? sum / double(shown) : 0.0;
        std::printf(
            "%s (%dx%d): %zu pixels show something, %zu of them differ by > 0.1 (%.2f %%), mean difference %.4f\n",
            GetParam().c_str(), scene.camera.width, scene.camera.height, shown, differing,
            shown ? 100.0 * double(differing) / double(shown) : 0.0, mean);
        EXPECT_GT(shown, 100u);
        EXPECT_LT(double(differing), 0.03 * double(shown));
        EXPECT_LT(mean, 0.015);
    }
}

// A metric neither asymptotically flat nor Goedel's (Davidson's universe): no shader path, and
// `render --gpu` says so, naming the metric, instead of blaming the Goedel renderer. (The
// geodesic shader's float fails rays blueshifted into a big bang: 186 of 2048 in
// Bertotti-Kasner's view, where the CPU ends 158 at its horizon.)
TEST(ShaderImagesOfOtherMetrics, RenderGpuRefusesAMetricWithoutAShaderPathByName) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "the shader renderers need an X display (xvfb-run -a)";
    const lc::Scene scene = lc::io::parseScene(
        "{\"metric\": {\"file\": \"metrics/davidson.json\"}, \"observer\": {\"position\": [0, 0.5, 0, 0]},"
        " \"camera\": {\"width\": 8, \"height\": 4}, \"render\": {\"max_affine\": 2}}",
        "davidson_gpu.json", std::string(LIGHTCONE_SOURCE_DIR) + "/data/");
    EXPECT_EQ(lc::cli::shaderPathFor(scene), lc::cli::ShaderPath::None);
    const auto output = std::filesystem::temp_directory_path() / "lightcone_davidson_gpu.png";
    try {
        lc::cli::renderWithShaders(scene, output.string(), 0, false);
        ADD_FAILURE() << "rendered a metric without a shader path";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("metric 'davidson' is neither"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(output));
}

INSTANTIATE_TEST_SUITE_P(Data, ShaderImages, ::testing::ValuesIn(dataScenes()),
                         [](const ::testing::TestParamInfo<std::string>& scene) { return scene.param; });

}  // namespace
