// SPDX-License-Identifier: BSD-3-Clause
// Frame paths of `lightcone animate` (app/commands/frame_sequence): patterns, intervals, and each frame's
// scene against what the path means: the camera turned, the observer carried round the axis or
// moved along its world line, a field of the scene file swept.
#include "app/commands/frame_sequence.hpp"
#include "core/analysis/shadow.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/scene/frame_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace lc;
using namespace lc::cli;

namespace {

io::EditableScene kerrScene() {
    return io::EditableScene::fromDocument(io::JsonDocument::parse(R"({"metric": {"name": "kerr", "M": 1.0, "a": 0.9},
            "observer": {"position": [0, 30, 0, 0]},
            "camera": {"width": 40, "height": 20, "fov": [60, 30], "forward": [-1, 0, 0], "up": [0, 0, 1]}})",
                                                                   "kerr.json")
                                               ->rootValue(),
                                           "kerr.json", ".");
}

TEST(FramePattern, NumbersFramesAsPrintfWouldAndRefusesAnythingElse) {
    EXPECT_EQ(FramePattern("frames/%04d.png", "-o").path(7), "frames/0007.png");
    EXPECT_EQ(FramePattern("f%d.exr", "-o").path(123), "f123.exr");
    EXPECT_EQ(FramePattern("100%%-%02d.png", "-o").path(3), "100%-03.png");
    for (const char* bad : {"frames.png", "%d-%d.png", "%s.png", "%4.png", "%x.png", "%", "run%d/f.png"})
        EXPECT_THROW(FramePattern(bad, "-o"), std::invalid_argument) << bad;
}

TEST(FrameInterval, IncludesBothEndsAndChecksEachPart) {
    const FrameInterval v = parseFrameInterval("--pan", "0:90:4", input::kTurnDegrees);
    EXPECT_EQ(v.frames, 4);
    EXPECT_DOUBLE_EQ(v.at(0), 0);
    EXPECT_DOUBLE_EQ(v.at(1), 30);
    EXPECT_DOUBLE_EQ(v.at(3), 90);
    EXPECT_DOUBLE_EQ(parseFrameInterval("--pan", "5:9:1", input::kTurnDegrees).at(0), 5);
    for (const char* bad : {"0:90", "0:90:0", "0:90:2.5", "0:nan:3", "0:1e9:3", "a:b:c", "0:90:4:5"})
        EXPECT_THROW(parseFrameInterval("--pan", bad, input::kTurnDegrees), std::invalid_argument) << bad;
    const FieldSweep s = parseFieldSweep("--sweep", "metric.a=0.5:2:60");
    EXPECT_EQ(s.field, "metric.a");
    EXPECT_EQ(s.values.frames, 60);
    EXPECT_THROW(parseFieldSweep("--sweep", "0.5:2:60"), std::invalid_argument);
}

TEST(AnimationPath, PathsTogetherNeedOneFrameCount) {
    AnimationPath p;
    EXPECT_THROW(p.frames(), std::invalid_argument);
    p.panDegrees = FrameInterval{0, 90, 10};
    p.orbitDegrees = FrameInterval{0, 360, 10};
    EXPECT_EQ(p.frames(), 10);
    p.properTime = FrameInterval{0, 5, 11};
    EXPECT_THROW(p.frames(), std::invalid_argument);
}

TEST(FrameSequence, PanTurnsTheCameraLeftAboutItsUp) {
    AnimationPath p;
    p.panDegrees = FrameInterval{0, 90, 2};
    const FrameSequence seq(kerrScene(), p, {});
    EXPECT_LT((seq.scene(0).camera.forward - Vec3(-1, 0, 0)).norm(), 1e-12);
    // Facing -x with +z up, a quarter turn to the left faces -y: a right angle as the observer
    // measures it (its rest space; in Kerr-Schild not the chart's angle), to the camera's left.
    const Camera before = frameCamera(seq.scene(0)), after = frameCamera(seq.scene(1));
    const Vec3 f0 = before.forward.normalized(), f1 = after.forward.normalized();
    const Vec3 left = before.up.normalized().cross(f0);
    EXPECT_NEAR(f0.dot(f1), 0, 1e-12);
    EXPECT_NEAR(f1.dot(left.normalized()), 1, 1e-12);
    EXPECT_GT(seq.scene(1).camera.forward.normalized().dot(Vec3(0, -1, 0)), 0.999);
    EXPECT_LT((seq.scene(1).camera.up - Vec3(0, 0, 1)).norm(), 1e-15);
    EXPECT_TRUE(p.cameraOnly());
}

TEST(FrameSequence, OrbitCarriesObserverAndCameraRoundTheAxis) {
    AnimationPath p;
    p.orbitDegrees = FrameInterval{0, 90, 3};
    const FrameSequence seq(kerrScene(), p, {});
    const Scene quarter = seq.scene(2);
    EXPECT_LT((quarter.observer - Vec4(0, 0, 30, 0)).norm(), 1e-12);
    // The chart directions turn with the event: still facing the hole.
    EXPECT_LT((quarter.camera.forward - Vec3(0, -1, 0)).norm(), 1e-12);
    const Scene eighth = seq.scene(1);
    EXPECT_NEAR(eighth.observer(1), 30 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(eighth.observer(2), 30 / std::sqrt(2.0), 1e-12);
}

TEST(FrameSequence, OrbitKeepsTheHoleStraightAheadWhereTheFrameDoesNotTurnWithTheChart) {
    // Schwarzschild in Kerr-Schild form at r = 6 M: g mixes t with x and y. The camera's chart
    // directions turn with the event; by symmetry the shadow stays centred on the camera's
    // forward direction all the way round.
    io::EditableScene near = io::EditableScene::fromDocument(
        io::JsonDocument::parse(R"({"metric": {"name": "schwarzschild"}, "observer": {"position": [0, 6, 0, 0]},
            "camera": {"fov": [90, 60], "forward": [-1, 0, 0], "up": [0, 0, 1]}})",
                                "near.json")
            ->rootValue(),
        "near.json", ".");
    AnimationPath p;
    p.orbitDegrees = FrameInterval{0, 90, 3};
    const FrameSequence seq(near, p, {});
    for (int k = 0; k < 3; ++k) {
        const ShadowSize s = measureShadow(seq.scene(k), 1e-10);
        EXPECT_NEAR(s.offsetDegrees(), 0, 1e-6) << "frame " << k;
        EXPECT_NEAR(s.leftDegrees, measureShadow(seq.scene(0), 1e-10).leftDegrees, 1e-6) << "frame " << k;
    }
}

TEST(FrameSequence, ProperTimeRunsTheStaticObserversClockAtItsRedshiftedRate) {
    AnimationPath p;
    p.properTime = FrameInterval{0, 10, 3};
    const FrameSequence seq(kerrScene(), p, {});
    // On the equator of Kerr, g_tt = 1 - 2 M r / (r^2 + a^2 cos^2 theta) = 1 - 2M/r with the
    // Boyer-Lindquist r of the Kerr-Schild point (30, 0, 0): x^2 = r^2 + a^2.
    const double r = std::sqrt(30.0 * 30.0 - 0.9 * 0.9), rate = 1 / std::sqrt(1 - 2.0 / r);
    EXPECT_NEAR(seq.scene(1).observer(0), 5 * rate, 1e-9);
    EXPECT_NEAR(seq.scene(2).observer(0), 10 * rate, 1e-9);
    EXPECT_LT((seq.scene(2).observer.tail<3>() - Vec3(30, 0, 0)).norm(), 1e-15);
}

TEST(FrameSequence, SweepEditsTheSceneFileFieldAndRefusesValuesTheReaderRefuses) {
    AnimationPath p;
    p.sweep = FieldSweep{"metric.a", FrameInterval{0, 0.5, 3}};
    const FrameSequence seq(kerrScene(), p, [](Scene& s) { s.camera.width = 24; });
    const auto& kerr = dynamic_cast<const KerrNewman&>(*seq.scene(1).spacetime);
    EXPECT_DOUBLE_EQ(kerr.spin(), 0.25);
    EXPECT_EQ(seq.scene(2).camera.width, 24);  // the command line's overrides apply to every frame
    // a > M at the end of the sweep: refused when the sequence is made, before any frame.
    p.sweep = FieldSweep{"metric.a", FrameInterval{0, 1.5, 3}};
    EXPECT_ANY_THROW(FrameSequence(kerrScene(), p, {}));
    p.sweep = FieldSweep{"metric.nonsense", FrameInterval{0, 1, 3}};
    EXPECT_ANY_THROW(FrameSequence(kerrScene(), p, {}));
    EXPECT_THROW(seq.scene(3), std::out_of_range);
}

}  // namespace
