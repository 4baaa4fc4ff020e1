// SPDX-License-Identifier: BSD-3-Clause
// core/input/ranges: strict numbers, the documented ranges (docs/SCENES.md shows exactly the
// table the code enforces, and the metric parameters of core/metrics/factory).
#include "core/input/ranges.hpp"
#include "core/metrics/factory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;
using namespace lc;

namespace {

std::string readText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

TEST(Ranges, NumbersAreParsedStrictly) {
    EXPECT_EQ(input::parseNumber("0.5"), 0.5);
    EXPECT_EQ(input::parseNumber("-1e3"), -1000.0);
    for (const char* bad : {"0.5xyz", "", " 1", "1 ", "nan", "NaN", "inf", "-inf", "1e999", "0x", "--1", "1,2"})
        EXPECT_FALSE(input::parseNumber(bad).has_value()) << bad;
}

TEST(Ranges, IntegersFinitenessAndBounds) {
    EXPECT_TRUE(input::kImageSide.contains(16384));
    EXPECT_FALSE(input::kImageSide.contains(2.5));
    EXPECT_FALSE(input::kImageSide.contains(0));
    EXPECT_FALSE(input::kTolerance.contains(std::nan("")));
    EXPECT_FALSE(input::kCoordinate.contains(1e308));
    EXPECT_EQ(input::kImageSide.problem(2.5), "expected an integer in [1, 16384] px, got 2.5");
    EXPECT_EQ(input::kTolerance.problem(-INFINITY), "expected a number in [1e-15, 0.1], got -inf");
    EXPECT_NO_THROW(input::kImageSide.require(16384, "camera width"));
    try {
        input::kImageSide.require(0, "camera width");
        ADD_FAILURE() << "0 px accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "camera width: expected an integer in [1, 16384] px, got 0");
    }
}

TEST(Ranges, DocsListExactlyTheEnforcedTable) {
    const std::string doc = readText(fs::path(LIGHTCONE_SOURCE_DIR) / "docs" / "SCENES.md");
    EXPECT_NE(doc.find(input::rangesMarkdown()), std::string::npos)
        << "docs/SCENES.md must contain the output of `lightcone ranges`:\n"
        << input::rangesMarkdown();
    EXPECT_NE(doc.find(metricParametersMarkdown()), std::string::npos) << "docs/SCENES.md must contain:\n"
                                                                       << metricParametersMarkdown();
}
