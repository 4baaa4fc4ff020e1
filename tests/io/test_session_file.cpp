// SPDX-License-Identifier: BSD-3-Clause
// Session files (docs/SESSIONS.md): round trip, atomic save, a moved scene, malformed sessions.
// Oracle for "the same image": the scene file with the edit typed into its text by hand,
// rendered by the CPU renderer, compared pixel for pixel with the session's scene.
#include "core/render/render.hpp"
#include "core/scene/frame_camera.hpp"
#include "readers/io/provenance.hpp"
#include "readers/io/session_file.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

using namespace lc;
namespace fs = std::filesystem;

namespace {

const std::string kData = std::string(LIGHTCONE_SOURCE_DIR) + "/data";

struct TempFolder {
    fs::path path;
    TempFolder() {
        path = fs::temp_directory_path() / ("lc-session-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempFolder() { fs::remove_all(path); }
};

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
std::string read(const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string sessionErrorOf(const fs::path& session) {
    try {
        const auto s = io::readSession(session.string());
        io::openSessionScene(s, session.string());
    } catch (const io::InputError& e) {
        return e.what();
    }
    return "";
}

RenderResult smallRender(Scene s) {
    s.camera.width = 96;
    s.camera.height = 32;
    s.settings.progress = false;
    return render(s);
}

void expectSamePixels(const RenderResult& a, const RenderResult& b) {
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    std::size_t differ = 0;
    for (std::size_t n = 0; n < a.pixels.size(); ++n)
        differ += a.pixels[n].kind != b.pixels[n].kind || a.pixels[n].u != b.pixels[n].u ||
                  a.pixels[n].v != b.pixels[n].v || a.pixels[n].emissionTime != b.pixels[n].emissionTime;
    EXPECT_EQ(differ, 0u);
}

TEST(SessionFile, RoundTripReproducesTheEditedSceneAndView) {
    TempFolder tmp;
    fs::copy_file(kData + "/default.json", tmp.path / "scene.json");
    auto scene = io::EditableScene::load((tmp.path / "scene.json").string());
    scene.apply({"metric.a", Json::Value(0.8)});
    scene.apply({"objects[0].radius", Json::Value(0.3)});

    io::SessionFile s;
    s.scenePath = io::scenePathForSession(scene.source(), (tmp.path / "s.lcsession").string());
    EXPECT_EQ(s.scenePath, "scene.json");
    s.edits = scene.edits();
    s.sceneDocument = scene.document();
    s.pickedI = 12;
    s.pickedJ = 7;
    s.selectedObject = 0;
    s.windowState = "AAAA/w==";
    s.imageFromShaders = false;
    io::writeSession((tmp.path / "s.lcsession").string(), s);

    const io::SessionFile back = io::readSession((tmp.path / "s.lcsession").string());
    EXPECT_EQ(back.pickedI, 12);
    EXPECT_EQ(back.pickedJ, 7);
    EXPECT_EQ(back.selectedObject, 0);
    EXPECT_EQ(back.windowState, "AAAA/w==");
    EXPECT_FALSE(back.imageFromShaders);
    ASSERT_EQ(back.edits.size(), 2u);
    EXPECT_EQ(io::sessionText(back), io::sessionText(s)) << "a second save must write the same file";
    const auto opened = io::openSessionScene(back, (tmp.path / "s.lcsession").string());
    EXPECT_TRUE(opened.notice.empty());
    EXPECT_EQ(opened.scene.document(), scene.document());

    // Independent path: the edits typed into the scene text by hand.
    std::string text = read(kData + "/default.json");
    text.replace(text.find("\"a\": 1.0"), 8, "\"a\": 0.8");
    text.replace(text.find("\"radius\": 0.25"), 14, "\"radius\": 0.3");
    expectSamePixels(smallRender(opened.scene.scene()), smallRender(io::parseScene(text, "by-hand.json", kData)));
}

// The default scene copied into `tmp` as scene.json with one edit (radius 0.3), saved as the
// session s.lcsession next to it, with the edited scene's copy; returns the session's path.
std::string saveEditedDefaultScene(const TempFolder& tmp, io::SessionFile& s) {
    fs::copy_file(kData + "/default.json", tmp.path / "scene.json");
    auto scene = io::EditableScene::load((tmp.path / "scene.json").string());
    scene.apply({"objects[0].radius", Json::Value(0.3)});
    s.scenePath = "scene.json";
    s.edits = scene.edits();
    s.sceneDocument = scene.document();
    const std::string file = (tmp.path / "s.lcsession").string();
    io::writeSession(file, s);
    return file;
}

TEST(SessionFile, MovedSceneOpensFromTheSavedCopyWithANotice) {
    TempFolder tmp;
    io::SessionFile s;
    const std::string file = saveEditedDefaultScene(tmp, s);
    fs::rename(tmp.path / "scene.json", tmp.path / "moved.json");

    const auto opened = io::openSessionScene(io::readSession(file), file);
    EXPECT_NE(opened.notice.find("scene.json is not there"), std::string::npos) << opened.notice;
    EXPECT_DOUBLE_EQ(opened.scene.scene().spheres.at(0).radius, 0.3) << "the edit was lost";

    // Without the copy: an error naming the session file and the field.
    s.sceneDocument = Json::Value();
    io::writeSession(file, s);
    const std::string e = sessionErrorOf(file);
    EXPECT_NE(e.find("s.lcsession"), std::string::npos) << e;
    EXPECT_NE(e.find("scene.path"), std::string::npos) << e;
}

// The GUI switches projection and field of view in one edit (either alone is refused): the
// session replays them together.
TEST(SessionFile, EditsMadeTogetherReplayTogether) {
    TempFolder tmp;
    fs::copy_file(kData + "/default.json", tmp.path / "scene.json");
    auto scene = io::EditableScene::load((tmp.path / "scene.json").string());
    Json::Value fov(Json::arrayValue);
    fov.append(90);
    fov.append(40);
    scene.apply(std::vector<io::SceneEdit>{{"camera.projection", Json::Value("pinhole")}, {"camera.fov", fov}});
    io::SessionFile s;
    s.scenePath = "scene.json";
    s.edits = scene.edits();
    const std::string file = (tmp.path / "s.lcsession").string();
    io::writeSession(file, s);
    const auto opened = io::openSessionScene(io::readSession(file), file);
    EXPECT_EQ(opened.scene.scene().camera.projection, Camera::Projection::Pinhole);
    EXPECT_DOUBLE_EQ(opened.scene.scene().camera.fovXDeg, 90);
}

// Opened from its saved copy, edited and saved again, a session still replays to the same scene
// once the scene file is back; a scene file that changed meanwhile is reported.
TEST(SessionFile, SavedAgainFromTheCopyKeepsEveryEdit) {
    TempFolder tmp;
    io::SessionFile s;
    const std::string file = saveEditedDefaultScene(tmp, s);
    fs::rename(tmp.path / "scene.json", tmp.path / "away.json");

    auto fromCopy = io::openSessionScene(io::readSession(file), file).scene;
    fromCopy.apply({"metric.a", Json::Value(0.9)});
    s.edits = fromCopy.edits();
    s.sceneDocument = fromCopy.document();
    io::writeSession(file, s);
    fs::rename(tmp.path / "away.json", tmp.path / "scene.json");
    const auto back = io::openSessionScene(io::readSession(file), file);
    EXPECT_TRUE(back.notice.empty()) << back.notice;
    EXPECT_EQ(back.scene.document(), fromCopy.document());
    EXPECT_DOUBLE_EQ(back.scene.scene().spheres[0].radius, 0.3);

    std::string text = read(tmp.path / "scene.json");
    const std::string centre = "\"centre\": [0, 1.0, 0.0, 0.0]";
    ASSERT_NE(text.find(centre), std::string::npos);
    text.replace(text.find(centre), centre.size(), "\"centre\": [0, 0.9, 0.0, 0.0]");
    write(tmp.path / "scene.json", text);
    const auto changed = io::openSessionScene(io::readSession(file), file);
    EXPECT_NE(changed.notice.find("changed since"), std::string::npos) << changed.notice;
}

// The undo history (each step's text, fields, values after and before) and the 3D view's camera
// come back as written, numbers exactly.
TEST(SessionFile, HistoryAndSpacetimeCameraRoundTrip) {
    io::SessionFile s;
    s.scenePath = "scene.json";
    s.edits = {{"metric.a", Json::Value(0.9)}};
    s.history = {{"edit metric.a", {{"metric.a", Json::Value(0.9)}}, {{"metric.a", Json::Value(1.0)}}},
                 {"zoom", {{"camera.fov", Json::Value(Json::arrayValue)}}, {{"camera.fov", Json::Value()}}}};
    s.spacetimeCamera = {0.1, -2.5, 3, 0, 0, 0, 0, 0, 1, 30.000000000000004};
    const io::SessionFile back = io::parseSession(io::sessionText(s), "s.lcsession");
    ASSERT_EQ(back.history.size(), 2u);
    EXPECT_EQ(back.history[0].text, "edit metric.a");
    EXPECT_EQ(back.history[0].after[0].value, Json::Value(0.9));
    EXPECT_EQ(back.history[0].before[0].value, Json::Value(1.0));
    EXPECT_EQ(back.history[1].after[0].field, "camera.fov");
    EXPECT_TRUE(back.history[1].before[0].value.isNull()) << "a field the file did not give";
    EXPECT_EQ(back.spacetimeCamera, s.spacetimeCamera);
    // Without them (a version-2 session of before): empty.
    io::SessionFile plain;
    plain.scenePath = "scene.json";
    const io::SessionFile none = io::parseSession(io::sessionText(plain), "p.lcsession");
    EXPECT_TRUE(none.history.empty());
    EXPECT_TRUE(none.spacetimeCamera.empty());
}

TEST(SessionFile, MalformedSessionsNameFileLineAndField) {
    TempFolder tmp;
    fs::copy_file(kData + "/default.json", tmp.path / "scene.json");
    const fs::path f = tmp.path / "bad.lcsession";
    struct Case {
        const char* text;
        const char* expected;
    };
    const Case cases[] = {
        {"{\"lightcone_session\": 3, \"scene\": {\"path\": \"scene.json\"}}",
         "bad.lcsession:1: field 'lightcone_session': expected an integer in [1, 2]"},
        {"{\"scene\": {\"path\": \"scene.json\"}}", "lightcone_session"},
        {"{\"lightcone_session\": 1,\n \"scene\": {\"path\": \"scene.json\",\n  \"edits\": [\n   {\"field\": "
         "\"objects[0].radius\", \"value\": -1}]}}",
         "bad.lcsession:4: field 'scene.edits[0] (objects[0].radius)': expected a number in [1e-06, 1e+06], got -1"},
        {"{\"lightcone_session\": 1, \"scene\": {\"path\": \"scene.json\", \"edits\": [{\"field\": \"metric.a\"}]}}",
         "'scene.edits[0]': missing required field 'value'"},
        {"{\"lightcone_session\": 1, \"scene\": {\"path\": \"scene.json\"}, \"view\": {\"picked_pixel\": [1e9, 0]}}",
         "view.picked_pixel[0]"},
        {"{\"lightcone_session\": 1, \"scene\": {\"path\": \"scene.json\"}, \"window\": {\"state\": \"<xml/>\"}}",
         "not base64"},
        {"{\"lightcone_session\": 1, \"scene\": {\"path\": \"scene.json\", \"document\": 3}}", "scene.document"},
        {"{\"lightcone_session\": 1, \"scene\": {\"path\": \"scene.json\"}, \"extra\": 1}", "'extra'"},
        {"[1, 2]", "a session is a JSON object"},
        {"{\"lightcone_session\": 1, \"scene\": {\"path\": \"scene.json\"}, \"view\": {\"image_from_shaders\": 1}}",
         "expected true or false"},
        {"{\"lightcone_session\": 1, \"scene\": {\"path\": \"\"}}", "scene.path"},
        {"{\"lightcone_session\": 2, \"scene\": {\"path\": \"scene.json\"},\n \"view\": {\"post_render\": "
         "{\"repeats\": 9}}}",
         "bad.lcsession:2: field 'view.post_render.repeats': expected an integer in [1, 8]"},
        {"{\"lightcone_session\": 2, \"scene\": {\"path\": \"scene.json\"}, \"view\": {\"post_render\": "
         "{\"texture\": \"earth\"}}}",
         "'earth' is not one of scene, checker, stripes"},
        {"{\"lightcone_session\": 2, \"scene\": {\"path\": \"scene.json\"}, \"view\": {\"post_render\": "
         "{\"time_window\": [0.5, 2]}}}",
         "view.post_render.time_window[1]"},
        {"{\"lightcone_session\": 2, \"scene\": {\"path\": \"scene.json\"}, \"view\": {\"post_render\": "
         "{\"temperature\": 1e9}}}",
         "expected a number in [1000, 30000] K"},
        {"{\"lightcone_session\": 2, \"scene\": {\"path\": \"scene.json\"}, \"view\": {\"spacetime_camera\": "
         "[1, 2, 3]}}",
         "view.spacetime_camera"},
        {"{\"lightcone_session\": 2, \"scene\": {\"path\": \"scene.json\", \"history\": [{\"text\": \"edit\", "
         "\"after\": [{\"field\": \"metric.a\", \"value\": 2}], \"before\": []}]}}",
         "scene.history[0].before"},
        {"{\"lightcone_session\": 2, \"scene\": {\"path\": \"scene.json\", \"history\": [{\"text\": 3, "
         "\"after\": [], \"before\": []}]}}",
         "scene.history[0].text"},
    };
    for (const Case& c : cases) {
        write(f, c.text);
        const std::string e = sessionErrorOf(f);
        EXPECT_NE(e.find(c.expected), std::string::npos) << "session: " << c.text << "\nerror: " << e;
    }
}

// 1e4 edits (the most a session holds) with one refused (no later edit mends it): it is named after a
// bisection over prefixes (it was found by reading every prefix: 2.5 minutes); a field path
// 1e5 levels deep is refused before anything is created (it overflowed the stack), its message
// short. The clock guard detects a hang; bench/ measures speed.
TEST(SessionFile, ManyEditsAndDeepFieldPathsAreRefusedByNameAtOnce) {
    TempFolder tmp;
    fs::copy_file(kData + "/default.json", tmp.path / "scene.json");
    const fs::path f = tmp.path / "many.lcsession";
    for (const std::size_t bad : {std::size_t(9999), std::size_t(4321), std::size_t(0)}) {
        std::string text = "{\"lightcone_session\": 2, \"scene\": {\"path\": \"scene.json\", \"edits\": [";
        for (std::size_t k = 0; k < 10000; ++k)
            text += std::string(k ? ",\n" : "") +
                    (k == bad ? std::string("{\"field\": \"objects[0].radius\", \"value\": -1}")
                              : "{\"field\": \"metric.a\", \"value\": " + std::to_string(0.5 + 1e-5 * double(k)) + "}");
        write(f, text + "]}}");
        const auto start = std::chrono::steady_clock::now();
        const std::string e = sessionErrorOf(f);
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30);
        EXPECT_NE(e.find("many.lcsession:" + std::to_string(bad + 1) + ": field 'scene.edits[" + std::to_string(bad) +
                         "] (objects[0].radius)': expected a number in [1e-06, 1e+06], got -1"),
                  std::string::npos)
            << e.substr(0, 300);
    }
    std::string deep = "a";
    for (int k = 0; k < 100000; ++k) deep += ".b";
    write(f, "{\"lightcone_session\": 2, \"scene\": {\"path\": \"scene.json\", \"edits\": [{\"field\": \"" + deep +
                 "\", \"value\": 1}]}}");
    const std::string e = sessionErrorOf(f);
    EXPECT_NE(e.find("a field path of 100001 levels and 200001 characters: scene fields are at most 64 levels"),
              std::string::npos)
        << e.substr(0, 300);
    EXPECT_LT(e.size(), 800u);
}

// The post-rendering dock's settings: written only when it is on, read back equal.
TEST(SessionFile, PostRenderControlsRoundTrip) {
    io::SessionFile s;
    s.scenePath = "scene.json";
    EXPECT_EQ(io::sessionText(s).find("post_render"), std::string::npos) << "off: not written";
    s.postRender.enabled = true;
    s.postRender.texture = "stripes";
    s.postRender.uOffset = 0.125;
    s.postRender.repeats = 3;
    s.postRender.temperature = 4500;
    s.postRender.timeWindow = std::array<double, 2>{0.25, 0.5};
    s.postRender.outside = "checker";
    s.postRender.blinkPhase = 0.75;
    const io::SessionFile back = io::parseSession(io::sessionText(s), "round.lcsession");
    EXPECT_TRUE(back.postRender == s.postRender);
    io::SessionFile plain = s;
    plain.postRender = io::PostRenderControls{};
    plain.postRender.enabled = true;
    EXPECT_TRUE(io::parseSession(io::sessionText(plain), "plain.lcsession").postRender == plain.postRender);
}

// Provenance (issue #45): a saved session names the program that wrote it; the reader reads
// past that field, so sessions without it (older ones) and with any value of it open alike.
TEST(SessionFile, NamesTheProgramThatWroteItAndReadsPastThatName) {
    io::SessionFile s;
    s.scenePath = "scene.json";
    const std::string text = io::sessionText(s);
    EXPECT_NE(text.find("\"written_by\" : \"" + io::softwareName() + "\""), std::string::npos) << text;
    EXPECT_EQ(io::softwareName().rfind("Lightcone ", 0), 0u) << io::softwareName();
    EXPECT_NE(io::softwareName().find(" (commit "), std::string::npos) << io::softwareName();
    for (const char* written : {"", "\"written_by\": \"Lightcone 0.0.9 (commit unknown)\", ", "\"written_by\": 5, "}) {
        const std::string other = std::string("{\"lightcone_session\": 2, ") + written +
                                  "\"scene\": {\"path\": \"scene.json\", \"edits\": []}, \"view\": {}}";
        EXPECT_EQ(io::parseSession(other, "other.lcsession").scenePath, "scene.json") << other;
    }
}

TEST(SessionFile, SavingIsAtomicAndRefusesAFolder) {
    TempFolder tmp;
    const fs::path f = tmp.path / "s.lcsession";
    write(f, "old contents");
    io::SessionFile s;
    s.scenePath = "x.json";
    EXPECT_THROW(io::writeSession(tmp.path.string(), s), std::exception);
    EXPECT_EQ(read(f), "old contents");
    io::writeSession(f.string(), s);
    EXPECT_EQ(read(f), io::sessionText(s));
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(tmp.path)) files += e.is_regular_file();
    EXPECT_EQ(files, 1u) << "a temporary file was left behind";
}

}  // namespace

// Version 1 gave the camera's forward and up in the observer's Gram-Schmidt frame. Opening such a
// session converts them to chart directions that frame sees along the same axes: every pixel's
// direction in the frame (what the renderers trace) is the one version 1 traced.
TEST(SessionFile, Version1CameraIsConvertedToChartDirections) {
    const TempFolder dir;
    const double i = 60 * kPi / 180;
    const Vec3 oldForward(-std::sin(i), 0, -std::cos(i)), oldUp(-std::cos(i), 0, std::sin(i));
    write(dir.path / "hole.json",
          "{\"metric\": {\"name\": \"schwarzschild\", \"M\": 1},\n"
          " \"observer\": {\"position\": [0, " +
              std::to_string(10 * std::sin(i)) + ", 0, " + std::to_string(10 * std::cos(i)) +
              "]},\n"
              " \"camera\": {\"width\": 40, \"height\": 40, \"fov\": [60, 60], \"forward\": [" +
              std::to_string(oldForward(0)) + ", 0, " + std::to_string(oldForward(2)) + "], \"up\": [" +
              std::to_string(oldUp(0)) + ", 0, " + std::to_string(oldUp(2)) + "]}}\n");
    write(dir.path / "v1.lcsession", "{\"lightcone_session\": 1, \"scene\": {\"path\": \"hole.json\"}}\n");
    const auto session = io::readSession((dir.path / "v1.lcsession").string());
    EXPECT_EQ(session.version, 1);
    const io::OpenedSession opened = io::openSessionScene(session, (dir.path / "v1.lcsession").string());
    EXPECT_NE(opened.notice.find("version-1 session"), std::string::npos) << opened.notice;
    const Scene& scene = opened.scene.scene();
    const Camera now = frameCamera(scene);
    const Vec3 read(std::stod(std::to_string(oldForward(0))), 0, std::stod(std::to_string(oldForward(2))));
    EXPECT_LT((now.forward.normalized() - read.normalized()).norm(), 1e-12);
    Camera before = scene.camera;
    before.forward = read;
    before.up = Vec3(std::stod(std::to_string(oldUp(0))), 0, std::stod(std::to_string(oldUp(2))));
    for (const auto& [px, py] : std::vector<std::pair<int, int>>{{0, 0}, {20, 20}, {39, 5}, {7, 33}})
        EXPECT_LT((now.direction(px, py) - before.direction(px, py)).norm(), 1e-12) << px << "," << py;
    // The chart direction is not the old numbers: there the frame is not the chart's.
    EXPECT_GT((scene.camera.forward.normalized() - read.normalized()).norm(), 1e-3);
    // Saved again it is a version-2 session with the converted edits, and opens without a notice.
    io::SessionFile again = session;
    again.edits = opened.scene.edits();
    io::writeSession((dir.path / "v2.lcsession").string(), again);
    const auto reread = io::readSession((dir.path / "v2.lcsession").string());
    EXPECT_EQ(reread.version, 2);
    const io::OpenedSession reopened = io::openSessionScene(reread, (dir.path / "v2.lcsession").string());
    EXPECT_TRUE(reopened.notice.empty()) << reopened.notice;
    EXPECT_LT((frameCamera(reopened.scene.scene()).forward.normalized() - read.normalized()).norm(), 1e-12);
}

// On the Goedel axis the frame is the chart's: a version-1 session opens unchanged, without a notice.
TEST(SessionFile, Version1OnTheGoedelAxisNeedsNoConversion) {
    const auto session = io::readSession(std::string(LIGHTCONE_SOURCE_DIR) + "/tests/data/default_edited.lcsession");
    EXPECT_EQ(session.version, 1);
    const io::OpenedSession opened =
        io::openSessionScene(session, std::string(LIGHTCONE_SOURCE_DIR) + "/tests/data/default_edited.lcsession");
    EXPECT_EQ(opened.notice.find("version-1"), std::string::npos) << opened.notice;
}
