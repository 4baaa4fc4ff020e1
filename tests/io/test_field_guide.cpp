// SPDX-License-Identifier: BSD-3-Clause
// The help a property tooltip and F1 give (io/field_guide): every field of every shipped scene is
// explained; every event, 4-velocity and direction names the chart the scene reader actually
// built (its spacetime's coordinates) and a unit; every section it points at is a heading of the
// user guide; every word offered as a choice is one the scene reader accepts.
#include "core/scene/scene.hpp"
#include "core/spacetime/integrator.hpp"
#include "readers/io/field_guide.hpp"
#include "readers/io/json_document.hpp"
#include "readers/io/scene_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using namespace lc;
namespace fs = std::filesystem;

namespace {

const std::string kSource = LIGHTCONE_SOURCE_DIR;

std::string fileText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

Json::Value jsonOf(const std::string& text) {
    Json::Value v;
    std::istringstream in(text);
    in >> v;
    return v;
}

// Every field path of a document: "observer.position", "objects[0].motion.points[3]", ...
void collectFields(const Json::Value& v, const std::string& path, std::vector<std::string>& out) {
    if (!path.empty()) out.push_back(path);
    const bool numberList = v.isArray() && v.size() > 0 && v[0].isNumeric();
    if (v.isObject()) {
        for (const auto& key : v.getMemberNames()) collectFields(v[key], path.empty() ? key : path + "." + key, out);
    } else if (v.isArray() && !numberList) {
        for (Json::ArrayIndex k = 0; k < v.size() && k < 8; ++k)
            collectFields(v[k], path + "[" + std::to_string(k) + "]", out);
    }
}

// The "## heading" lines of a guide page.
std::set<std::string> headingsOf(const std::string& page) {
    std::set<std::string> headings;
    std::istringstream in(fileText(fs::path(kSource) / "docs/guide" / page));
    for (std::string line; std::getline(in, line);)
        if (line.rfind("#", 0) == 0) headings.insert(line.substr(line.find_first_not_of("# ")));
    return headings;
}

bool isChartQuantity(const std::string& field) {
    for (const char* end : {"observer.position", "observer.velocity", ".centre", "].position", "camera.forward",
                            "camera.up", "camera.look_at"})
        if (field.size() >= std::strlen(end) &&
            field.compare(field.size() - std::strlen(end), std::string::npos, end) == 0)
            return true;
    return field.find("motion.points[") != std::string::npos;
}

}  // namespace

TEST(FieldGuide, EveryFieldOfEveryShippedSceneIsExplainedWhereTheGuideHasThatSection) {
    int scenes = 0, fields = 0, chartFields = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(kSource) / "data")) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().filename().string());
        const Scene scene = io::readScene(entry.path().string());
        const Json::Value document = jsonOf(fileText(entry.path()));
        const io::ChartGuide chart = io::chartGuideOf(document["metric"], *scene.spacetime);
        const auto& pages = io::guidePages();
        EXPECT_NE(std::find(pages.begin(), pages.end(), chart.page), pages.end()) << chart.page;
        EXPECT_FALSE(headingsOf(chart.page).empty()) << "docs/guide/" << chart.page << " has no heading";
        std::vector<std::string> paths;
        collectFields(document, "", paths);
        for (const std::string& field : paths) {
            const io::FieldGuide help = io::fieldGuide(field, chart, document);
            EXPECT_FALSE(help.meaning.empty()) << field << " has no help";
            EXPECT_EQ(headingsOf(help.page).count(help.section), 1u)
                << field << ": docs/guide/" << help.page << " has no section '" << help.section << "'";
            ++fields;
            if (!isChartQuantity(field)) continue;
            // The chart the reader built: its spacetime's coordinate names, all four for an event and
            // a 4-velocity, the spatial three for a direction or a place.
            const auto names = scene.spacetime->coordinateNames();
            const bool spatial = field.find("camera.") == 0;
            for (int k = spatial ? 1 : 0; k < 4; ++k)
                EXPECT_NE(help.unit.find(names[k]), std::string::npos) << field << ": " << help.unit;
            EXPECT_NE(help.unit.find(chart.chart), std::string::npos) << field << ": " << help.unit;
            EXPECT_NE(help.tooltip().find("unit: "), std::string::npos);
            ++chartFields;
        }
        ++scenes;
    }
    EXPECT_GE(scenes, 19);
    EXPECT_GE(chartFields, 60);
    std::cout << scenes << " scenes, " << fields << " fields, " << chartFields << " with a chart\n";
}

TEST(FieldGuide, ChartsAndUnitsFollowTheMetric) {
    auto chartOf = [](const std::string& file) {
        const Scene scene = io::readScene(kSource + "/data/" + file);
        return io::chartGuideOf(jsonOf(fileText(kSource + "/data/" + file))["metric"], *scene.spacetime);
    };
    const io::ChartGuide kerr = chartOf("kerr.json");
    EXPECT_EQ(kerr.page, "black_holes.md");
    EXPECT_NE(kerr.unit.find("units of M"), std::string::npos) << kerr.unit;
    EXPECT_NE(kerr.chart.find("Kerr-Schild"), std::string::npos) << kerr.chart;
    // Kerr typed as text: the formula's own parameter meaning gives the unit.
    const io::ChartGuide typed = chartOf("kerr_formula.json");
    EXPECT_NE(typed.unit.find("units of M"), std::string::npos) << typed.unit;
    EXPECT_EQ(typed.page, "black_holes.md");  // it declares a horizon
    const io::ChartGuide godel = chartOf("default.json");
    EXPECT_EQ(godel.page, "godel.md");
    EXPECT_NE(godel.unit.find("r = 2a"), std::string::npos) << godel.unit;
    EXPECT_EQ(chartOf("sr_cube.json").page, "special_relativity.md");
    EXPECT_EQ(chartOf("alcubierre_bubble.json").page, "warp_drives_and_wormholes.md");
    EXPECT_EQ(chartOf("ellis_wormhole.json").page, "warp_drives_and_wormholes.md");

    // A metric typed in spherical coordinates: scene positions are in the Cartesian pull-back.
    const Scene spherical = io::parseScene(
        R"({"metric": {"file": "metrics/schwarzschild_spherical.json"}, "observer": {"position": [0, 0, 0, 30]},
            "camera": {"width": 8, "height": 8}})",
        "spherical.json", kSource + "/data");
    const io::ChartGuide pulled =
        io::chartGuideOf(jsonOf(R"({"file": "metrics/schwarzschild_spherical.json"})"), *spherical.spacetime);
    EXPECT_NE(pulled.chart.find("pulled back"), std::string::npos) << pulled.chart;
    EXPECT_EQ(pulled.coordinateList(), "(t, x, y, z)");
    const io::FieldGuide position = io::fieldGuide("observer.position", pulled, Json::Value());
    EXPECT_NE(position.unit.find("(t, x, y, z)"), std::string::npos) << position.unit;
}

TEST(FieldGuide, ADisksTemperatureIsItsHottestRingAndFieldsNotListedFallBackToTheirParent) {
    const Json::Value scene = jsonOf(fileText(kSource + "/data/kerr_disk.json"));
    io::ChartGuide chart = io::defaultChartGuide();
    chart.page = "black_holes.md";
    Json::ArrayIndex disk = 0;
    while (disk < scene["objects"].size() && scene["objects"][disk]["type"].asString() != "disk") ++disk;
    ASSERT_LT(disk, scene["objects"].size());
    const io::FieldGuide temperature =
        io::fieldGuide("objects[" + std::to_string(disk) + "].temperature", chart, scene);
    EXPECT_NE(temperature.meaning.find("maximum"), std::string::npos) << temperature.meaning;
    EXPECT_EQ(temperature.section, "The accretion disk");
    const io::FieldGuide cells = io::fieldGuide("objects[0].texture.cells", chart, scene);
    EXPECT_EQ(cells.meaning.rfind("part of objects[].texture", 0), 0u) << cells.meaning;
    EXPECT_TRUE(io::fieldGuide("nonsense", chart, scene).meaning.empty());
}

// Each word a field offers is one the scene reader takes there.
TEST(FieldGuide, EveryWordOfferedAsAChoiceIsAcceptedByTheSceneReader) {
    const std::string base = fileText(kSource + "/data/kerr_disk.json");
    struct Case {
        std::string field;
        std::function<void(Json::Value&, const std::string&)> set;
    };
    const std::vector<Case> cases{
        {"render.stepper", [](Json::Value& s, const std::string& w) { s["render"]["stepper"] = w; }},
        {"render.method", [](Json::Value& s, const std::string& w) { s["render"]["method"] = w; }},
        {"camera.projection", [](Json::Value& s, const std::string& w) { s["camera"]["projection"] = w; }},
        {"objects[0].sense", [](Json::Value& s, const std::string& w) { s["objects"][0]["sense"] = w; }},
        {"objects[0].emission", [](Json::Value& s, const std::string& w) { s["objects"][0]["emission"] = w; }},
        {"render.magnification",
         [](Json::Value& s, const std::string& w) { s["render"]["magnification"] = w == "true"; }},
    };
    int words = 0;
    for (const Case& c : cases) {
        Json::Value scene = jsonOf(base);
        ASSERT_EQ(scene["objects"][0]["type"].asString(), "disk");
        const io::FieldGuide help = io::fieldGuide(c.field, io::defaultChartGuide(), scene);
        ASSERT_GE(help.choices.size(), 2u) << c.field;
        for (const std::string& choice : help.choices) {
            const std::string word = choice.substr(0, choice.find(' '));
            if (word == "closed_form" || word == "per_vertex") continue;  // Goedel's: below
            Json::Value edited = scene;
            c.set(edited, word);
            if (word == "texture") edited["objects"][0]["texture"] = "checker";
            Json::StreamWriterBuilder w;
            EXPECT_NO_THROW(io::parseScene(Json::writeString(w, edited), "choice.json", kSource + "/data"))
                << c.field << " = " << word;
            ++words;
        }
    }
    // The Goedel renderers on a Goedel scene; the named observers where each exists.
    Json::Value godel = jsonOf(fileText(kSource + "/data/default.json"));
    for (const char* method : {"closed_form", "per_vertex"}) {
        godel["render"]["method"] = method;
        EXPECT_NO_THROW(
            io::parseScene(Json::writeString(Json::StreamWriterBuilder(), godel), "g.json", kSource + "/data"));
    }
    const std::vector<std::string> stepperWords =
        io::fieldGuide("render.stepper", io::defaultChartGuide(), godel).choices;
    EXPECT_EQ(stepperWords.size(), sceneStepperNames().size());
    const std::vector<std::string> observers =
        io::fieldGuide("observer.velocity", io::defaultChartGuide(), godel).choices;
    Json::Value kerr = jsonOf(fileText(kSource + "/data/kerr_infall.json"));
    int named = 0;
    for (const std::string& o : observers) {
        if (o.find(' ') != std::string::npos) continue;  // "four numbers ..."
        kerr["observer"]["velocity"] = o;
        if (o == "normal" || o == "static" || o == "zamo" || o == "carter" || o == "free_fall") ++named;
        // Kerr far out has every named observer.
        kerr["observer"]["position"] = Json::Value(Json::arrayValue);
        for (double x : {0.0, 20.0, 3.0, 4.0}) kerr["observer"]["position"].append(x);
        EXPECT_NO_THROW(
            io::parseScene(Json::writeString(Json::StreamWriterBuilder(), kerr), "k.json", kSource + "/data"))
            << "observer.velocity = " << o;
    }
    EXPECT_EQ(named, 5);
    EXPECT_GE(words, 14);
}
