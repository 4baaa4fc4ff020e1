// SPDX-License-Identifier: BSD-3-Clause
// `lightcone export` at its limits (issue #47): 1000 windings once wrote 1.9 GB of .vtp in two
// minutes with no word. Now the light paths' size is estimated before they are traced and the
// files are counted as they are made, against --max-size; a refused export writes nothing.
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

using namespace lc::test;
namespace fs = std::filesystem;

namespace {

// data/default.json (Goedel, one ball) drawn with `windings`.
std::string godelSceneWithWindings(const ScratchFolder& dir, int windings) {
    const std::string text =
        std::regex_replace(fileBytes(sourcePath("data/default.json")), std::regex("\"windings\": *[0-9]+"),
                           "\"windings\": " + std::to_string(windings));
    const std::string path = dir / ("w" + std::to_string(windings) + ".json");
    std::ofstream(path) << text;
    return path;
}

TEST(ExportCommand, LightPathsOverTheLimitAreRefusedBeforeTheyAreTraced) {
    const ScratchFolder dir("export-limit");
    const CommandResult r =
        runCommand(lightcone() + " export " + godelSceneWithWindings(dir, 1000) + " -o " + dir / "out");
    EXPECT_NE(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("the export would write about "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("1001 loops for the scene's windings), over --max-size 500 MB"), std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(ExportCommand, FilesPastTheLimitStopTheExportWritingNothingAndProgressIsShown) {
    const ScratchFolder dir("export-count");
    // Kerr: no estimate (its rays have a fixed length); 10 kB is passed by the first file.
    CommandResult r =
        runCommand(lightcone() + " export " + sourcePath("data/kerr.json") + " -o " + dir / "out" + " --max-size 0.01");
    EXPECT_NE(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("the export passes --max-size 0.01 MB with "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("after geodesics_fan.vtp (1 files); nothing was written"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out"));
    r = runCommand(lightcone() + " export " + sourcePath("data/kerr.json") + " -o " + dir / "out");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("files progress 100%"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(dir / "out/horizon.vtp"));
}

}  // namespace
