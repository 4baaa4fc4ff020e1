// SPDX-License-Identifier: BSD-3-Clause
// `lightcone diagram --kind` through the real binary: the t-r diagram is written and counts the
// images `lightcone images` finds, the default stays the r-phi diagram, and a bad kind stops
// with exit code 2 before any file is read or written.
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

namespace {

using lc::test::lightcone;
using lc::test::runCommand;
using lc::test::ScratchFolder;
using lc::test::sourcePath;

TEST(DiagramCommand, KindTrWritesTheSpacetimeDiagram) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "VTK's charts need an X display (ctest runs under xvfb-run)";
    ScratchFolder dir("diagram-tr");
    const auto r = runCommand(lightcone() + " diagram " + sourcePath("data/godel_many_images.json") +
                              " --kind t-r -o " + (dir / "tr.svg") + " -o " + (dir / "tr.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("tr.svg (12 image paths)"), std::string::npos) << r.output;  // two per winding, 0..5
    const std::string svg = lc::test::fileBytes(dir / "tr.svg");
    EXPECT_NE(svg.find("Lightcone t-r diagram"), std::string::npos);
    EXPECT_NE(svg.find("t (coordinate time)"), std::string::npos);
    EXPECT_NE(svg.find("closed timelike circles"), std::string::npos);
    EXPECT_EQ(lc::test::fileBytes(dir / "tr.png").substr(1, 3), "PNG");
}

TEST(DiagramCommand, DefaultKindIsTheRPhiDiagram) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "VTK's charts need an X display (ctest runs under xvfb-run)";
    ScratchFolder dir("diagram-rphi");
    const auto r = runCommand(lightcone() + " diagram " + sourcePath("data/default.json") + " -o " + (dir / "d.svg"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(lc::test::fileBytes(dir / "d.svg").find("Lightcone r-phi diagram"), std::string::npos);
}

TEST(DiagramCommand, UnknownKindIsABadCommandLineNamingTheOption) {
    ScratchFolder dir("diagram-bad-kind");
    const auto r = runCommand(lightcone() + " diagram " + sourcePath("data/godel_many_images.json") +
                              " --kind phi-t -o " + (dir / "x.svg"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("option --kind: expected one of r-phi, t-r; got 'phi-t'"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.svg"));
    // A missing value is refused too (every option is declared as taking one).
    const auto missing = runCommand(lightcone() + " diagram " + sourcePath("data/default.json") + " --kind");
    EXPECT_EQ(missing.exitCode, 2) << missing.output;
    EXPECT_NE(missing.output.find("--kind"), std::string::npos) << missing.output;
}

}  // namespace
