// SPDX-License-Identifier: BSD-3-Clause
// In-place scene edits (io::EditableScene), as the GUI's properties dock makes them: an edit is
// accepted or refused by the scene reader itself. Oracle: the same value written into a scene
// file by hand and read by io::parseScene.
#include "core/metrics/godel.hpp"
#include "readers/io/scene_edits.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>

using namespace lc;

namespace {

const std::string kDefault = std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json";
const std::string kKerr = std::string(LIGHTCONE_SOURCE_DIR) + "/data/kerr.json";

std::string fileText(const std::string& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The reader's reason for the default scene with `from` replaced by `to` in its text.
std::string readerReasonForText(const std::string& from, const std::string& to) {
    std::string text = fileText(kDefault);
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    try {
        io::parseScene(text, "hand-edited.json", std::string(LIGHTCONE_SOURCE_DIR) + "/data");
    } catch (const io::InputError& e) {
        return e.reason();
    }
    return "";
}

TEST(SceneEdits, MetricParameterEditChangesTheSpacetime) {
    auto s = io::EditableScene::load(kDefault);
    s.apply({"metric.a", Json::Value(0.7)});
    const auto* g = dynamic_cast<const GodelCartesian*>(s.scene().spacetime.get());
    ASSERT_NE(g, nullptr);
    EXPECT_DOUBLE_EQ(g->a(), 0.7);
    // The windings' affine length follows a, as when the file says a = 0.7.
    EXPECT_NEAR(s.scene().settings.trace.maxAffine, g->affineLengthForWindings(1), 1e-12);
    ASSERT_EQ(s.edits().size(), 1u);
    EXPECT_EQ(s.edits()[0].field, "metric.a");
}

TEST(SceneEdits, AbsentFieldCanBeSetAndRemovedAgain) {
    auto s = io::EditableScene::load(kKerr);
    Json::Value grey(Json::arrayValue);
    for (double c : {0.5, 0.25, 0.125}) grey.append(c);
    s.apply({"background", grey});
    EXPECT_EQ(s.scene().background, Vec3(0.5, 0.25, 0.125));
    s.apply({"background", Json::Value()});  // back to the file: no background, the default
    EXPECT_TRUE(s.value("background").isNull());
    EXPECT_TRUE(s.edits().empty()) << "removing a field the file does not have is no edit";
    EXPECT_EQ(s.document(), s.original());
    EXPECT_EQ(s.scene().background, Scene().background);
}

TEST(SceneEdits, RefusedEditGivesTheReadersOwnReasonAndChangesNothing) {
    auto s = io::EditableScene::load(kDefault);
    const Json::Value before = s.document();
    Json::Value radius(-0.5);
    try {
        s.apply({"objects[0].radius", radius});
        FAIL() << "a negative radius was accepted";
    } catch (const io::InputError& e) {
        EXPECT_EQ(e.field(), "objects[0].radius");
        EXPECT_EQ(e.reason(), readerReasonForText("\"radius\": 0.25", "\"radius\": -0.5"));
        EXPECT_NE(e.reason().find("expected a number in [1e-06, 1e+06], got -0.5"), std::string::npos) << e.reason();
    }
    EXPECT_EQ(s.document(), before);
    EXPECT_TRUE(s.edits().empty());
    EXPECT_DOUBLE_EQ(s.scene().spheres[0].radius, 0.25);

    // A text where a number belongs, and an observer outside the Goedel range.
    EXPECT_THROW(s.apply({"metric.a", Json::Value("one")}), io::InputError);
    Json::Value far(Json::arrayValue);
    for (double x : {0.0, 1e6, 0.0, 0.0}) far.append(x);
    try {
        s.apply({"observer.position", far});
        FAIL();
    } catch (const io::InputError& e) {
        EXPECT_EQ(e.reason(), readerReasonForText("\"position\": [0, 0, 0, 0]", "\"position\": [0, 1e6, 0, 0]"));
    }
}

// Edits are made in the document itself (a copy of a 40 MB scene per edit took seconds): a group
// the reader refuses puts back every value it overwrote, member it created and field it removed.
TEST(SceneEdits, ARefusedGroupOfEditsLeavesTheDocumentAsItWas) {
    auto s = io::EditableScene::load(kKerr);
    ASSERT_TRUE(s.document().isMember("sky"));
    ASSERT_FALSE(s.document().isMember("animation"));
    const Json::Value before = s.document();
    Json::Value fov(Json::arrayValue);
    for (double deg : {20.0, 10.0}) fov.append(deg);
    Json::Value pan(Json::arrayValue);
    for (double deg : {0.0, 30.0}) pan.append(deg);
    const std::vector<io::SceneEdit> group{{"animation.frames", Json::Value(12)},  // creates "animation"
                                           {"animation.pan", pan},
                                           {"camera.fov", fov},     // overwrites
                                           {"sky", Json::Value()},  // removes
                                           {"metric.a", Json::Value(0.5)},
                                           {"camera.width", Json::Value(-3)}};  // refused
    EXPECT_THROW(s.apply(group), io::InputError);
    EXPECT_EQ(s.document(), before);
    EXPECT_TRUE(s.edits().empty());
    // The same group without the refused edit is taken whole, and the scene follows it.
    s.apply(std::vector<io::SceneEdit>(group.begin(), group.end() - 1));
    EXPECT_EQ(s.value("animation.pan"), pan);
    EXPECT_FALSE(s.document().isMember("sky"));
    EXPECT_EQ(s.edits().size(), 5u);
    EXPECT_EQ(s.originalValue("sky"), before["sky"]);
    EXPECT_EQ(s.original(), before);
}

TEST(SceneEdits, MalformedFieldPathsAreRefusedWithTheField) {
    auto s = io::EditableScene::load(kDefault);
    for (const char* bad : {"", "objects[9].radius", "objects[x]", "metric..a", "metric.a.b", "objects[", "metric.",
                            "objects[0]radius", "objects[00].radius", "objects[0].", "camera.fov[0]x"}) {
        try {
            s.apply({bad, Json::Value(1.0)});
            ADD_FAILURE() << "accepted field '" << bad << "'";
        } catch (const io::InputError& e) {
            EXPECT_FALSE(e.reason().empty()) << bad;
        }
    }
    EXPECT_THROW(s.apply({"", Json::Value()}), io::InputError) << "removing the empty field";
    EXPECT_EQ(s.document(), s.original());
    // Unknown fields are the reader's to refuse, naming the accepted ones.
    try {
        s.apply({"metric.b", Json::Value(1.0)});
        FAIL();
    } catch (const io::InputError& e) {
        EXPECT_NE(e.reason().find("a"), std::string::npos);
    }
    EXPECT_TRUE(s.edits().empty());
}

TEST(SceneEdits, EditBackToTheFilesValueIsNoEdit) {
    auto s = io::EditableScene::load(kDefault);
    s.apply({"metric.a", Json::Value(2.0)});
    s.apply({"objects[0].radius", Json::Value(0.3)});
    EXPECT_EQ(s.edits().size(), 2u);
    s.apply({"metric.a", Json::Value(1.0)});
    ASSERT_EQ(s.edits().size(), 1u);
    EXPECT_EQ(s.edits()[0].field, "objects[0].radius");
}

// Replaying edits() on the file must give the edited document, also when a whole object and
// one of its fields are edited in turns (a session stores the edits, not only the result).
TEST(SceneEdits, ReplayingTheEditsGivesTheEditedDocument) {
    auto s = io::EditableScene::load(kDefault);
    s.apply({"objects[0].radius", Json::Value(0.3)});
    Json::Value ball = s.value("objects[0]");
    ball["radius"] = 0.5;
    s.apply({"objects[0]", ball});
    s.apply({"objects[0].radius", Json::Value(0.4)});
    s.apply({"objects[0].radius", Json::Value(0.25)});  // the file's value, but objects[0] is edited too
    auto replay = io::EditableScene::load(kDefault);
    for (const auto& e : s.edits()) replay.apply(e);
    EXPECT_EQ(replay.document(), s.document());
    EXPECT_DOUBLE_EQ(replay.scene().spheres[0].radius, 0.25);
}

// A sphere added, its radius edited, both undone (each undo an edit back): the edits still
// replay on the file, although the radius edit was last recorded after the list's.
TEST(SceneEdits, EditsInsideALaterEditOfTheirWholeFieldAreSuperseded) {
    auto s = io::EditableScene::load(kDefault);
    const Json::Value objects = s.value("objects");
    Json::Value more = objects;
    Json::Value sphere = objects[0];
    sphere["name"] = "copy";
    more.append(sphere);
    s.apply({"objects", more});                        // + sphere
    s.apply({"objects[1].radius", Json::Value(0.3)});  // its radius
    s.apply({"objects[1].radius", sphere["radius"]});  // undo the radius
    s.apply({"objects", objects});                     // undo the sphere
    auto replay = io::EditableScene::load(kDefault);
    for (const auto& e : s.edits()) replay.apply(e);
    EXPECT_EQ(replay.document(), s.document());
    EXPECT_TRUE(s.edits().empty());
    EXPECT_EQ(s.document(), s.original());
}

// A path malformed below members it would create is refused with nothing created; the next edit
// is taken as if it had not been tried.
TEST(SceneEdits, AMalformedPathLeavesNoMemberBehind) {
    auto s = io::EditableScene::load(kDefault);
    const Json::Value before = s.document();
    EXPECT_THROW(s.apply({"objects[0].foo[0]", Json::Value(1)}), io::InputError);
    EXPECT_THROW(s.apply({"render.max_steps.", Json::Value(1)}), io::InputError);
    EXPECT_THROW(s.apply({{"camera.width", Json::Value(64)}, {"sky.bogus[0]", Json::Value(1)}}), io::InputError);
    EXPECT_EQ(s.document(), before);
    s.apply({"camera.width", Json::Value(64)});
    EXPECT_EQ(s.scene().camera.width, 64);
}

// Undoing an edit that created members above its field removes them again.
TEST(SceneEdits, TheUndoOfAnEditThatCreatedAMemberRemovesIt) {
    auto s = io::EditableScene::load(kKerr);
    ASSERT_FALSE(s.document().isMember("background"));
    const io::SceneEdit undo = s.undoing("animation.frames");
    EXPECT_EQ(undo.field, "animation");
    EXPECT_TRUE(undo.value.isNull());
    const io::SceneEdit undoStepper = s.undoing("render.stepper");
    EXPECT_EQ(undoStepper.field, "render.stepper");
    EXPECT_EQ(undoStepper.value, s.value("render.stepper"));
    Json::Value grey(Json::arrayValue);
    for (double c : {0.5, 0.5, 0.5}) grey.append(c);
    const io::SceneEdit undoGrey = s.undoing("background");
    s.apply({"background", grey});
    s.apply(undoGrey);
    EXPECT_EQ(s.document(), s.original());
    EXPECT_TRUE(s.edits().empty());
}

}  // namespace

// The ranges the GUI's tooltips show come from the reader's own checks, one entry per kind of
// field: a world line of many events adds none per event (a 40 MB scene's log once held 280 MB),
// yet each event, a list read at once, still has its range.
TEST(SceneEdits, RangesAreLoggedPerKindOfFieldNotPerNumber) {
    auto withEvents = [](int events) {
        Json::Value scene;
        scene["metric"]["name"] = "godel";
        Json::Value sphere;
        sphere["type"] = "sphere";
        sphere["radius"] = 0.1;
        sphere["motion"]["type"] = "world_line";
        for (int k = 0; k < events; ++k) {
            Json::Value e(Json::arrayValue);
            for (double c : {0.1 * k - 2, 0.5 + 0.001 * k, 0.0, 0.0}) e.append(c);
            sphere["motion"]["points"].append(e);
        }
        sphere["centre"] = sphere["motion"]["points"][0];
        scene["objects"].append(sphere);
        return io::EditableScene::fromDocument(scene, "events.json", ".");
    };
    const io::EditableScene few = withEvents(3), many = withEvents(300);
    for (const char* field : {"objects[0].motion.points[2]", "objects[0].radius", "objects[0].centre"}) {
        ASSERT_NE(few.rangeOf(field), nullptr) << field;
        ASSERT_NE(many.rangeOf(field), nullptr) << field;
        EXPECT_EQ(few.rangeOf(field)->describe(), many.rangeOf(field)->describe()) << field;
    }
    ASSERT_NE(many.rangeOf("objects[0].motion.points[299]"), nullptr);
    EXPECT_EQ(few.checkedRangeCount(), many.checkedRangeCount());
}
