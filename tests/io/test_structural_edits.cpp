// SPDX-License-Identifier: BSD-3-Clause
// Edits that change what a scene holds (io::metricChange, sphereAdded, lightAdded,
// elementDuplicated, elementRemoved), as the GUI's properties dock makes them. Oracles: the same
// scene written by hand as a file and read by io::parseScene; positions by plain arithmetic from the
// scene file's numbers; the reader's own refusals.
#include "core/metrics/factory.hpp"
#include "readers/io/scene_reader.hpp"
#include "readers/io/structural_edits.hpp"

#include <gtest/gtest.h>

#include <fstream>

using namespace lc;

namespace {

const std::string kDataFolder = std::string(LIGHTCONE_SOURCE_DIR) + "/data/";

// A hand-written scene read as a file would be.
Scene sceneFromHandWrittenText(const std::string& text) {
    return io::parseScene(text, "hand-written.json", kDataFolder);
}

}  // namespace

TEST(StructuralEdits, MetricChangeIsTheNewMetricAtItsDefaults) {
    auto s = io::EditableScene::load(kDataFolder + "kerr.json");
    s.apply(io::metricChange("schwarzschild"));
    const Scene byHand =
        sceneFromHandWrittenText(R"({"metric": {"name": "schwarzschild"}, "observer": {"position": [0, 30, 0, 0]},
        "camera": {"projection": "pinhole", "width": 480, "height": 240, "fov": [60, 32.2],
                   "forward": [-1, 0, 0], "up": [0, 0, 1]}})");
    EXPECT_EQ(s.scene().spacetime->name(), byHand.spacetime->name());
    EXPECT_EQ(s.scene().spacetime->parameters(), byHand.spacetime->parameters());
    EXPECT_EQ(s.scene().spacetime->parameters().at("M"), 1.0);  // docs/SCENES.md's default
    EXPECT_EQ(s.scene().spacetime->parameters().at("a"), 0.0);
    // Kerr-Newman's defaults are its table's (a = 0.5, Q = 0.5), not the file's spin.
    s.apply(io::metricChange("kerr-newman"));
    EXPECT_EQ(s.scene().spacetime->parameters().at("a"), 0.5);
    EXPECT_EQ(s.scene().spacetime->parameters().at("Q"), 0.5);
    // Undone by the value it had: the file's own document again.
    s.apply({"metric", s.original()["metric"]});
    EXPECT_EQ(s.document(), s.original());
}

TEST(StructuralEdits, MetricChangeTheSceneCannotHoldIsRefusedAndChangesNothing) {
    auto s = io::EditableScene::load(kDataFolder + "default.json");  // Goedel, observer on the axis
    const Json::Value before = s.document();
    // At the chart origin of Schwarzschild the observer would sit on the singularity.
    EXPECT_THROW(s.apply(io::metricChange("schwarzschild")), io::InputError);
    EXPECT_EQ(s.document(), before);
    EXPECT_EQ(s.scene().spacetime->name(), "godel");
    try {
        io::metricChange("goedel");
        FAIL() << "an unknown metric must be refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("godel-cylindrical"), std::string::npos) << e.what();
    }
}

// #46 item 3: the metric chooser proposes an observer the new metric serves. From data/default.json
// (Goedel, observer at the chart origin looking along +x): Schwarzschild's origin is its singularity,
// so the observer moves against the camera's forward direction to six capture radii, the hole ahead
// (oracle: the new scene's numbers and the far field of the metric built alone); Alcubierre's
// static observer is not timelike in the bubble (g_tt = 1 - v^2 < 0 at its centre), so the observer
// stays and takes the normal (Eulerian) velocity, u = d/dt + v d/dx there (Alcubierre 1994: the
// Eulerian observers ride the bubble at dx/dt = v); Goedel's cylindrical chart is degenerate on its
// axis, so the observer moves off it; Minkowski takes the scene as it is. Each plan reads.
TEST(StructuralEdits, MetricChangePlanMovesTheObserverWhereTheNewMetricServesAndSaysWhy) {
    const auto s = io::EditableScene::load(kDataFolder + "default.json");
    const auto applied = [&](const io::MetricChangePlan& plan) {
        io::EditableScene trial = s;
        trial.apply(plan.edits);
        return trial.scene();
    };

    const io::MetricChangePlan hole = io::plannedMetricChange(s, io::metricChange("schwarzschild"));
    ASSERT_EQ(hole.edits.size(), 2u);
    EXPECT_EQ(hole.edits[0].field, "metric");
    EXPECT_EQ(hole.edits[1].field, "observer.position");
    const double capture = makeSpacetime("schwarzschild", {})->farField(Vec4(0, 100, 0, 0)).captureRadius;
    const Scene moved = applied(hole);
    EXPECT_NEAR(moved.observer.tail<3>().norm(), 6 * capture, 1e-12);
    EXPECT_NEAR(moved.camera.forward.normalized().dot(-moved.observer.tail<3>().normalized()), 1, 1e-12)
        << "the hole is straight ahead";
    EXPECT_NE(hole.moved.find("moved to (0, -"), std::string::npos) << hole.moved;
    EXPECT_NE(hole.moved.find("g_tt = nan"), std::string::npos) << "the old place's real cause: " << hole.moved;

    const io::MetricChangePlan warp = io::plannedMetricChange(s, io::metricChange("alcubierre"));
    ASSERT_EQ(warp.edits.size(), 2u);
    EXPECT_EQ(warp.edits[1].field, "observer.velocity");
    EXPECT_EQ(warp.edits[1].value.asString(), "normal");
    const Scene riding = applied(warp);
    EXPECT_EQ(riding.observer, s.scene().observer);
    const double v = riding.spacetime->parameters().at("v");
    EXPECT_NEAR(riding.observerVelocity(1) / riding.observerVelocity(0), v, 1e-9);
    EXPECT_NE(warp.moved.find("d/dt is not timelike"), std::string::npos) << warp.moved;

    const io::MetricChangePlan cylinder = io::plannedMetricChange(s, io::metricChange("godel-cylindrical"));
    ASSERT_EQ(cylinder.edits.size(), 2u);
    const Scene offAxis = applied(cylinder);
    EXPECT_NEAR(offAxis.observer(1), 0.1, 1e-12) << "r = a / 10";
    EXPECT_NE(cylinder.moved.find("det g = 0"), std::string::npos) << cylinder.moved;

    const io::MetricChangePlan flat = io::plannedMetricChange(s, io::metricChange("minkowski"));
    EXPECT_EQ(flat.edits.size(), 1u);
    EXPECT_TRUE(flat.moved.empty());

    // An object the new metric cannot hold (Goedel's free fall) stays a refusal, naming the object.
    const auto falling = io::EditableScene::load(kDataFolder + "godel_free_fall_earth.json");
    try {
        (void)io::plannedMetricChange(falling, io::metricChange("schwarzschild"));
        FAIL() << "a free fall in Schwarzschild must be refused";
    } catch (const io::InputError& e) {
        EXPECT_NE(e.field().find("objects[0].motion"), std::string::npos) << e.what();
    }
}

TEST(StructuralEdits, SphereAddedLiesAheadOfTheCamera) {
    // Kerr from r = 30 M looking along -x: 0.3 of the distance ahead, i.e. at x = 21, radius 0.9.
    auto kerr = io::EditableScene::load(kDataFolder + "kerr.json");
    kerr.apply(io::sphereAdded(kerr.document(), kerr.scene()));
    ASSERT_EQ(kerr.scene().spheres.size(), 1u);
    const SphereObject& s = kerr.scene().spheres[0];
    EXPECT_EQ(s.name, "sphere-1");
    EXPECT_NEAR((s.centre - Vec4(0, 21, 0, 0)).norm(), 0, 1e-12);
    EXPECT_DOUBLE_EQ(s.radius, 0.9);
    kerr.apply(io::sphereAdded(kerr.document(), kerr.scene()));
    EXPECT_EQ(kerr.scene().spheres[1].name, "sphere-2") << "names stay unique";

    // An inclined observer with look_at: along the chart line to the hole, at 0.3 r0 = 15 M.
    auto disk = io::EditableScene::load(kDataFolder + "kerr_disk.json");
    disk.apply(io::sphereAdded(disk.document(), disk.scene()));
    const Vec4 observer(0, 48.296291, 0, 12.940952);
    const Vec4 expected = observer - 0.3 * observer.tail<3>().norm() * Vec4(0, 48.296291, 0, 12.940952).normalized();
    EXPECT_NEAR((disk.scene().spheres.at(0).centre - expected).norm(), 0, 1e-9);

    // Goedel: a ahead (inside the horizon 2a), here the panorama's forward +x from the axis.
    auto godel = io::EditableScene::load(kDataFolder + "default.json");
    godel.apply(io::sphereAdded(godel.document(), godel.scene()));
    ASSERT_EQ(godel.scene().spheres.size(), 2u);
    EXPECT_NEAR((godel.scene().spheres[1].centre - Vec4(0, 1, 0, 0)).norm(), 0, 1e-12);
}

TEST(StructuralEdits, LightAddedAboveTheObserver) {
    auto s = io::EditableScene::load(kDataFolder + "default.json");
    s.apply(io::lightAdded(s.document(), s.scene()));
    ASSERT_EQ(s.scene().lights.size(), 1u);
    EXPECT_EQ(s.scene().lights[0].name, "light-1");
    EXPECT_NEAR((s.scene().lights[0].position - Vec4(0, 0, 0, 1)).norm(), 0, 1e-12);  // up = +z, a = 1
    EXPECT_EQ(s.scene().lights[0].temperature, 6500);
}

// A copy sits right after its source in the list and beside it in the picture: moved to the
// camera's right by 2.5 sizes (sr_cube.json: forward -z, up +y, so right = forward x up = +x; the
// cube of edge 4 reaches 2 sqrt(3) from its centre), a light by 0.3 placeDistance (3 in flat space).
TEST(StructuralEdits, DuplicateCopiesRightAfterWithAFreeNameBesideTheOriginal) {
    auto s = io::EditableScene::load(kDataFolder + "sr_cube.json");
    s.apply(io::elementDuplicated(s.document(), s.scene(), io::SceneList::Objects, 0));
    s.apply(io::elementDuplicated(s.document(), s.scene(), io::SceneList::Objects, 0));
    ASSERT_EQ(s.scene().meshes.size(), 3u);
    EXPECT_EQ(s.scene().meshes[0].name, "cube");
    EXPECT_EQ(s.scene().meshes[1].name, "cube-copy-2");  // the newest copy sits right after its source
    EXPECT_EQ(s.scene().meshes[2].name, "cube-copy");
    EXPECT_EQ(s.scene().meshes[1].positions.size(), s.scene().meshes[0].positions.size());
    const Vec4 shift = s.scene().meshes[2].centre - s.scene().meshes[0].centre;
    EXPECT_NEAR((shift - Vec4(0, 2.5 * 2 * std::sqrt(3.0), 0, 0)).norm(), 0, 1e-12) << shift.transpose();
    s.apply(io::elementDuplicated(s.document(), s.scene(), io::SceneList::Lights, 0));
    EXPECT_EQ(s.scene().lights.at(1).name, "lamp-copy");
    EXPECT_NEAR((s.scene().lights[1].position - s.scene().lights[0].position - Vec4(0, 0.9, 0, 0)).norm(), 0, 1e-12);
    EXPECT_THROW(io::elementDuplicated(s.document(), s.scene(), io::SceneList::Lights, 2), std::invalid_argument);
    EXPECT_THROW(io::elementDuplicated(s.document(), s.scene(), io::SceneList::Objects, -1), std::invalid_argument);

    // A sphere: 2.5 radii (default.json: the ball of radius 0.25 at x = 1, camera forward +x, up +z:
    // right = -y).
    auto godel = io::EditableScene::load(kDataFolder + "default.json");
    godel.apply(io::elementDuplicated(godel.document(), godel.scene(), io::SceneList::Objects, 0));
    EXPECT_NEAR((godel.scene().spheres[1].centre - Vec4(0, 1, -0.625, 0)).norm(), 0, 1e-12);
}

TEST(StructuralEdits, DuplicateTheDiskIsRefusedByTheReader) {
    auto s = io::EditableScene::load(kDataFolder + "kerr_disk.json");
    try {
        s.apply(io::elementDuplicated(s.document(), s.scene(), io::SceneList::Objects, 0));
        FAIL() << "a second disk must be refused";
    } catch (const io::InputError& e) {
        EXPECT_NE(e.reason().find("second disk"), std::string::npos) << e.reason();
    }
    EXPECT_EQ(s.document(), s.original());
}

TEST(StructuralEdits, RemoveTheLastElementRemovesTheList) {
    auto s = io::EditableScene::load(kDataFolder + "sr_cube.json");
    s.apply(io::elementRemoved(s.document(), io::SceneList::Lights, 0));
    EXPECT_TRUE(s.scene().lights.empty());
    EXPECT_FALSE(s.document().isMember("lights"));
    s.apply(io::elementRemoved(s.document(), io::SceneList::Objects, 0));
    EXPECT_TRUE(s.scene().meshes.empty());
    EXPECT_THROW(io::elementRemoved(s.document(), io::SceneList::Objects, 0), std::invalid_argument);
    // Put back by the values they had: the file's document, and no edit left.
    s.apply({{"objects", s.original()["objects"]}, {"lights", s.original()["lights"]}});
    EXPECT_EQ(s.document(), s.original());
    EXPECT_TRUE(s.edits().empty());
}
