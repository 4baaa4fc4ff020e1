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
}

}  // namespace
