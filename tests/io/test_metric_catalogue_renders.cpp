// SPDX-License-Identifier: BSD-3-Clause
// Every metric file of the catalogue (data/metrics, issue #43) renders a 64 x 32 image from the
// view its file declares, as a user's first render would: every pixel finite, every ray ended for
// a reason, the null condition held along the rays (the worst drift is printed for the table in
// docs/METRICS.md). One test per file, so the suite runs them in parallel and names a failure.
#include "core/render/render.hpp"
#include "readers/io/json_document.hpp"
#include "readers/io/scene_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <json/json.h>

namespace {

const std::string kCatalogueData = std::string(LIGHTCONE_SOURCE_DIR) + "/data/";

std::vector<std::string> catalogueStems() {
    std::vector<std::string> stems;
    for (const auto& entry : std::filesystem::directory_iterator(kCatalogueData + "metrics"))
        if (entry.path().extension() == ".json") stems.push_back(entry.path().stem().string());
    std::sort(stems.begin(), stems.end());
    return stems;
}

// The scene a user would write for the file's view: the metric at its defaults, a static
// observer, the view's objects.
std::string viewScene(const std::string& stem) {
    const auto doc = lc::io::JsonDocument::load(kCatalogueData + "metrics/" + stem + ".json");
    const Json::Value& view = doc->rootValue()["view"];
    Json::Value scene;
    scene["metric"]["file"] = "metrics/" + stem + ".json";
    scene["observer"]["position"] = view["observer"];
    Json::Value& camera = scene["camera"];
    camera["width"] = 64;
    camera["height"] = 32;
    camera["fov"].append(90);
    camera["fov"].append(45);
    camera["look_at"] = view.isMember("look_at") ? view["look_at"] : Json::Value(Json::arrayValue);
    if (!view.isMember("look_at"))
        for (int i = 0; i < 3; ++i) camera["look_at"].append(0);
    for (const int up : {0, 0, 1}) camera["up"].append(up);
    scene["render"]["tolerance"] = 1e-9;
    if (view.isMember("max_affine")) scene["render"]["max_affine"] = view["max_affine"];
    if (view.isMember("objects")) scene["objects"] = view["objects"];
    return Json::writeString(Json::StreamWriterBuilder(), scene);
}

class CatalogueView : public ::testing::TestWithParam<std::string> {};

TEST_P(CatalogueView, RendersAFiniteImageWithTheNullConditionHeld) {
    const std::string stem = GetParam();
    const lc::Scene scene = lc::io::parseScene(viewScene(stem), stem + "_view.json", kCatalogueData);
    const lc::RenderResult r = lc::renderNumeric(scene);
    ASSERT_EQ(r.pixels.size(), 64u * 32u);
    std::array<std::size_t, 6> kinds{};  // by PixelRecord::Kind
    for (const lc::PixelRecord& p : r.pixels) {
        ASSERT_TRUE(std::isfinite(p.u) && std::isfinite(p.v) && std::isfinite(p.emissionTime) &&
                    std::isfinite(p.affine) && std::isfinite(p.frequencyRatio))
            << stem;
        ++kinds.at(static_cast<std::size_t>(p.kind));
    }
    std::printf("| `%s` | %zu sky, %zu object, %zu horizon, %zu at the affine limit, %zu failed | %.1e | %.2f s |\n",
                stem.c_str(), kinds[lc::PixelRecord::Sky], kinds[lc::PixelRecord::Object],
                kinds[lc::PixelRecord::Horizon], kinds[lc::PixelRecord::Background], kinds[lc::PixelRecord::Failed],
                r.stats.worstDrift, r.stats.seconds);
    EXPECT_EQ(kinds[lc::PixelRecord::Failed], 0u) << stem;
    // |H| is absolute, and a ray's momentum grows as it is blueshifted towards where it ends:
    // 1090 times towards last scattering, without bound at a horizon of a singular chart. Rays
    // from the sky keep |H| near the tolerance; rays that end at such a boundary are held to the
    // tracer's own limit (constraintTolerance, where it would stop them as failed).
    EXPECT_TRUE(std::isfinite(r.stats.worstDrift)) << stem;
    EXPECT_LT(r.stats.worstDrift, scene.spacetime->asymptoticallyFlat() ? 1e-5 : 1e-3) << stem;
}

INSTANTIATE_TEST_SUITE_P(MetricCatalogue, CatalogueView, ::testing::ValuesIn(catalogueStems()),
                         [](const ::testing::TestParamInfo<std::string>& file) { return file.param; });

}  // namespace
