// SPDX-License-Identifier: BSD-3-Clause
// `lightcone animate` as a user runs it: frames equal separate renders of the frames' scenes
// (written by hand here), --resume skips what exists, --movie makes a movie through ffmpeg, and
// bad paths fail before any frame with nothing written.
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

using namespace lc::test;
namespace fs = std::filesystem;

namespace {

// data/godel_free_fall_earth.json with the observer at coordinate time t (its clock: the
// static Goedel observer on the axis is a dust world line, g_tt = 1, so t is its proper time).
std::string freeFallEarthAt(double t) {
    char position[64];
    std::snprintf(position, sizeof position, "[%.17g, 0, 0, 0]", t);
    std::string scene = fileBytes(sourcePath("data/godel_free_fall_earth.json"));
    return std::regex_replace(scene, std::regex(R"("position": \[0, 0, 0, 0\])"),
                              std::string("\"position\": ") + position);
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

const std::string kSmall = " --width 220 --height 25 --quiet";

TEST(AnimateCommand, ThreeFramesOfProperTimeEqualThreeRendersOfTheFramesScenes) {
    const ScratchFolder dir("animate-three");
    const CommandResult run = runCommand(lightcone() + " animate " + sourcePath("data/godel_free_fall_earth.json") +
                                         " -o " + dir / "frames/%02d.png --proper-time 0:1.5:3" + kSmall);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("3 rendered, 0 skipped"), std::string::npos) << run.output;
    for (int k = 0; k < 3; ++k) {
        const std::string scene = dir / ("scene" + std::to_string(k) + ".json");
        writeText(scene, freeFallEarthAt(0.75 * k));
        const std::string single = dir / ("single" + std::to_string(k) + ".png");
        const CommandResult r = runCommand(lightcone() + " render " + scene + " -o " + single + kSmall);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const std::string frame = dir / ("frames/0" + std::to_string(k) + ".png");
        EXPECT_EQ(fileBytes(frame), fileBytes(single)) << "frame " << k << " differs from its render";
    }
    // The earth moves between frames: the frames are not all the same picture.
    EXPECT_NE(fileBytes(dir / "frames/00.png"), fileBytes(dir / "frames/02.png"));
}

TEST(AnimateCommand, PanAndSweepFramesEqualRendersOfTheTurnedAndEditedScenes) {
    const ScratchFolder dir("animate-pan-sweep");
    const std::string kerr = sourcePath("data/kerr.json");
    const std::string tiny = " --width 48 --height 24 --quiet";
    ASSERT_EQ(runCommand(lightcone() + " animate " + kerr + " -o " + dir / "pan%d.png --pan 0:90:2" + tiny).exitCode,
              0);
    ASSERT_EQ(runCommand(lightcone() + " animate " + kerr + " -o " + dir / "spin%d.png --sweep metric.a=0:0.5:2" + tiny)
                  .exitCode,
              0);
    std::string scene = fileBytes(kerr);
    writeText(dir / "turned.json",
              std::regex_replace(scene, std::regex(R"("forward": \[-1, 0, 0\])"), "\"forward\": [0, -1, 0]"));
    writeText(dir / "spin.json", std::regex_replace(scene, std::regex(R"("a": 0.9)"), "\"a\": 0.5"));
    ASSERT_EQ(runCommand(lightcone() + " render " + dir / "turned.json -o " + dir / "turned.png" + tiny).exitCode, 0);
    ASSERT_EQ(runCommand(lightcone() + " render " + dir / "spin.json -o " + dir / "spin.png" + tiny).exitCode, 0);
    EXPECT_EQ(fileBytes(dir / "pan1.png"), fileBytes(dir / "turned.png"));
    EXPECT_EQ(fileBytes(dir / "spin1.png"), fileBytes(dir / "spin.png"));
    EXPECT_NE(fileBytes(dir / "spin0.png"), fileBytes(dir / "spin1.png"));
}

// Every run reports its error (issue 52): the animation's summary gives the worst of its frames'
// render error estimates (each the one `render` prints for that frame's scene, checked against the
// exact deflection by the render's own tests) and the frame it comes from.
TEST(AnimateCommand, SummaryGivesTheWorstOfTheFramesErrorEstimates) {
    const ScratchFolder dir("animate-error");
    const std::string kerr = sourcePath("data/kerr.json");
    const std::string tiny = " --width 48 --height 24 --quiet";
    const CommandResult run =
        runCommand(lightcone() + " animate " + kerr + " -o " + dir / "spin%d.png --sweep metric.a=0:0.5:2" + tiny);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::regex animated(R"(estimated error: escape directions within (\S+) px \(frame (\d))");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(run.output, m, animated)) << run.output;
    const double worst = std::stod(m[1]);
    const int frame = std::stoi(m[2]);
    const std::string scene = fileBytes(kerr);
    std::vector<double> frames;
    for (const char* a : {"0", "0.5"}) {
        writeText(dir / "frame.json", std::regex_replace(scene, std::regex(R"("a": 0.9)"), std::string("\"a\": ") + a));
        const CommandResult r = runCommand(lightcone() + " render " + dir / "frame.json -o " + dir / "frame.png" +
                                           " --width 48 --height 24");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        std::smatch f;
        ASSERT_TRUE(std::regex_search(r.output, f, std::regex(R"(escape directions within (\S+) px)"))) << r.output;
        frames.push_back(std::stod(f[1]));
    }
    EXPECT_EQ(worst, std::max(frames[0], frames[1])) << run.output;
    EXPECT_EQ(frame, frames[1] > frames[0] ? 1 : 0);
    EXPECT_GT(worst, 0);
    EXPECT_LT(worst, 0.05) << "the default tolerance keeps escape directions far below a pixel";
}

TEST(AnimateCommand, SpecialRelativityFramesSeeTheCubeAtTheObserversLaterTimes) {
    const ScratchFolder dir("animate-sr");
    const std::string size = " --width 96 --height 54 --quiet";
    const CommandResult run = runCommand(lightcone() + " animate " + sourcePath("data/sr_cube.json") + " -o " +
                                         dir / "%d.png --proper-time 0:3:2" + size);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("special relativity"), std::string::npos) << run.output;
    // An observer at rest in flat spacetime: its proper time is the coordinate time.
    writeText(dir / "later.json",
              std::regex_replace(fileBytes(sourcePath("data/sr_cube.json")),
                                 std::regex(R"("position": \[0, 0, 0, 0\])"), "\"position\": [3, 0, 0, 0]"));
    const CommandResult single =
        runCommand(lightcone() + " render " + dir / "later.json -o " + dir / "later.png" + size);
    ASSERT_EQ(single.exitCode, 0) << single.output;
    EXPECT_EQ(fileBytes(dir / "1.png"), fileBytes(dir / "later.png"));
    EXPECT_NE(fileBytes(dir / "0.png"), fileBytes(dir / "1.png"));  // the cube has moved on
}

TEST(AnimateCommand, ShaderFramesEqualShaderRendersOfTheTurnedScene) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "the shader renderers need an X display (ctest runs under xvfb-run)";
    const ScratchFolder dir("animate-gpu");
    // Goedel photo-objects built once for the whole pan, drawn with the camera turned per frame.
    const std::string size = " --width 180 --height 60 --gpu --quiet";
    const CommandResult run = runCommand(lightcone() + " animate " + sourcePath("data/default.json") + " -o " +
                                         dir / "%d.png --pan 0:90:2" + size);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    writeText(dir / "turned.json",
              std::regex_replace(fileBytes(sourcePath("data/default.json")), std::regex(R"("forward": \[1, 0, 0\])"),
                                 "\"forward\": [0, 1, 0]"));
    const CommandResult single =
        runCommand(lightcone() + " render " + dir / "turned.json -o " + dir / "turned.png --orbit-frames 1" + size);
    ASSERT_EQ(single.exitCode, 0) << single.output;
    EXPECT_EQ(fileBytes(dir / "1.png"), fileBytes(dir / "turned.png"));
    EXPECT_NE(fileBytes(dir / "0.png"), fileBytes(dir / "1.png"));
}

TEST(AnimateCommand, ResumeSkipsFramesAlreadyWrittenAndRendersTheRest) {
    const ScratchFolder dir("animate-resume");
    const std::string cmd = lightcone() + " animate " + sourcePath("data/kerr.json") + " -o " + dir / "%d.png" +
                            " --pan 0:20:3 --width 32 --height 16 --quiet";
    ASSERT_EQ(runCommand(cmd).exitCode, 0);
    const std::string middle = fileBytes(dir / "1.png");
    const auto firstTime = fs::last_write_time(dir / "0.png");
    fs::remove(dir / "1.png");
    const CommandResult again = runCommand(cmd + " --resume");
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_NE(again.output.find("1 rendered, 2 skipped"), std::string::npos) << again.output;
    EXPECT_EQ(fileBytes(dir / "1.png"), middle);
    EXPECT_EQ(fs::last_write_time(dir / "0.png"), firstTime);
    // A job-array slice renders only its frames.
    const CommandResult slice = runCommand(cmd + " --frames 2-2");
    EXPECT_NE(slice.output.find("frames 2 to 2 of 3"), std::string::npos) << slice.output;
}

TEST(AnimateCommand, MovieThroughFfmpegHasEveryFrame) {
    if (runCommand("command -v ffmpeg && command -v ffprobe").exitCode != 0)
        GTEST_SKIP() << "ffmpeg is not installed (Debian package ffmpeg): --movie is not available";
    const ScratchFolder dir("animate-movie");
    const CommandResult run =
        runCommand(lightcone() + " animate " + sourcePath("data/kerr.json") + " -o " +
                   dir / "f%03d.png --pan 0:30:5 --width 33 --height 17 --quiet --movie " + dir / "out.mp4 --fps 10");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const CommandResult probe = runCommand(
        "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
        "stream=nb_read_frames,width,height -of csv=p=0 " +
        dir / "out.mp4");
    EXPECT_EQ(probe.output, "34,18,5\n");  // padded to even sizes for 4:2:0 players
}

TEST(AnimateCommand, BadPathsFailBeforeAnyFrameAndWriteNothing) {
    const ScratchFolder dir("animate-bad");
    const std::string base = lightcone() + " animate " + sourcePath("data/kerr.json") + " --width 16 --height 8 ";
    struct Case {
        std::string args, message;
        int exitCode;
    };
    const std::vector<Case> cases{
        {"-o " + dir / "x.png --pan 0:10:2", "needs exactly one frame number", 2},
        {"-o " + dir / "%d.png", "animate needs a path", 2},
        {"-o " + dir / "%d.png --pan 0:10:2 --orbit 0:10:3", "need the same number of frames", 2},
        {"-o " + dir / "%d.png --sweep metric.a=0:1.5:3", "a^2 + Q^2 must not exceed M^2", 3},
        {"-o " + dir / "%d.png --sweep metric.spin=0:0.5:3", "metric.spin", 3},
        {"-o " + dir / "%d.png --proper-time 0:1e13:3", "--proper-time (TO)", 2},
        {"-o " + dir / "%d.png --pan 0:10:2 --frames 1-5", "frames 0 to 1", 2},
        {"-o " + dir / "%d.exr --pan 0:10:2 --movie " + dir / "m.mp4", "PNG or JPEG frames", 2},
        {"-o " + dir / "missing/deeper/%d.png --pan 0:10:2", "-o", 2},
    };
    for (const Case& c : cases) {
        const CommandResult r = runCommand(base + c.args);
        EXPECT_EQ(r.exitCode, c.exitCode) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
    }
    // Without ffmpeg on PATH, --movie says so before rendering.
    const CommandResult noFfmpeg =
        runCommand("PATH=/nonexistent " + base + "-o " + dir / "%d.png --pan 0:10:2 --movie " + dir / "m.mp4");
    EXPECT_EQ(noFfmpeg.exitCode, 2) << noFfmpeg.output;
    EXPECT_NE(noFfmpeg.output.find("--movie needs ffmpeg"), std::string::npos) << noFfmpeg.output;
    EXPECT_TRUE(fs::is_empty(dir.path())) << "a refused command wrote files";
}

}  // namespace
