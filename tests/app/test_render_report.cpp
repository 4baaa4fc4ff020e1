// SPDX-License-Identifier: BSD-3-Clause
// `lightcone render --data OUT.exr` keeps the render's figures (the lines it prints, its error
// estimate among them) in the EXR's header as "lightcone:report", so the per-pixel data says how
// far to trust it wherever it goes (issue #52).
#include "readers/io/image_io.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

using namespace lc::test;

namespace {

TEST(RenderReport, DataFileCarriesTheRenderFiguresAndItsErrorEstimate) {
    const ScratchFolder dir("render-report");
    const CommandResult r = runCommand(lightcone() + " render " + sourcePath("data/kerr.json") +
                                       " --width 64 --height 32 -o " + dir / "k.png --data " + dir / "k.exr --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::size_t at = r.output.find("estimated error: escape directions within ");
    ASSERT_NE(at, std::string::npos) << r.output;
    const std::string line = r.output.substr(at, r.output.find('\n', at) - at);
    const lc::io::ImageChannels data = lc::io::readImageChannels(dir / "k.exr");
    std::string report;
    for (const auto& [name, value] : data.attributes)
        if (name == "lightcone:report") report = value;
    EXPECT_NE(report.find(line), std::string::npos) << report;
    EXPECT_NE(report.find("worst null-condition drift"), std::string::npos) << report;
    EXPECT_EQ(r.output.find("warning: rk4"), std::string::npos) << r.output;
}

// An escape angle above pi traces fates only (GYOTO's shadow example, bench/gyoto): the directions
// are not settled, so no pixel figure is made of them; the line says why instead.
TEST(RenderReport, AboveAnEscapeAngleOfPiNoDirectionErrorIsClaimed) {
    const ScratchFolder dir("render-fates");
    const CommandResult r = runCommand(lightcone() + " render " + sourcePath("data/kerr.json") +
                                       " --width 16 --height 8 --escape-angle 3.2 -o " + dir / "k.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("escape directions within"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("estimated error: escape directions not estimated: escape_angle 3.2 rad (above pi)"),
              std::string::npos)
        << r.output;
}

// rk4 steps at its fixed 0.01 whatever the tolerance: on Kerr a ray takes ~5e4 steps (23 s for
// 64x32). The run says so before it starts and after, and names the step instead of a tolerance
// it ignores (issue #47).
TEST(RenderReport, FixedStepRk4IsWarnedAboutBeforeAndAfterAndReportsItsStepNotATolerance) {
    const ScratchFolder dir("render-rk4");
    const CommandResult r =
        runCommand(lightcone() + " render " + sourcePath("data/kerr.json") +
                   " --width 4 --height 2 --stepper rk4 --tolerance 1e-8 -o " + dir / "k.png --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("warning: rk4 takes fixed steps of 0.01 in the affine parameter and does not use the "
                            "tolerance"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("kerr, rk4 fixed step 0.01 (no tolerance)"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("tol 1.0e-08"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("warning: rk4 took "), std::string::npos) << r.output;
}

}  // namespace
