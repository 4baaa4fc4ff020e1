// SPDX-License-Identifier: BSD-3-Clause
// An accretion disk through the real binary: render's flux, spectrum and per-pixel data agree with
// each other (the spectrum integrates to the printed flux; shade of the data gives the PNG back
// byte for byte; a cooler shade is redder), and sweep's disk columns grow with spin as the ISCO
// moves in (Page-Thorne: more binding energy released, docs/PHYSICS.md section 12).
#include "app/commands/commands.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/scene_reader.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

using namespace lc::test;

namespace {

double printedNumber(const std::string& output, const std::string& before) {
    const std::size_t k = output.find(before);
    return k == std::string::npos ? NAN : std::strtod(output.c_str() + k + before.size(), nullptr);
}

std::vector<std::vector<double>> csvRows(const std::string& text) {
    std::vector<std::vector<double>> rows;
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::istringstream cells(line);
        std::string cell;
        while (std::getline(cells, cell, ',')) row.push_back(std::strtod(cell.c_str(), nullptr));
        rows.push_back(row);
    }
    return rows;
}

TEST(DiskCommands, SpectrumIntegratesToTheFluxAndShadeGivesTheImageBack) {
    const ScratchFolder dir{"disk"};
    const std::string scene = sourcePath("data/kerr_disk.json");
    const CommandResult r =
        runCommand(lightcone() + " render " + scene + " -o " + dir / "disk.png --data " + dir / "disk.exr --spectrum " +
                   dir / "spectrum.csv --spectrum " + dir / "spectrum.svg --width 120 --height 68 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const double flux = printedNumber(r.output, "disk observed flux ");
    ASSERT_GT(flux, 0) << r.output;
    EXPECT_NE(r.output.find("secondary"), std::string::npos);
    const auto rows = csvRows(fileBytes(dir / "spectrum.csv"));
    ASSERT_EQ(rows.size(), 80u);
    double integral = 0;
    for (std::size_t k = 1; k < rows.size(); ++k)
        integral += 0.5 * (rows[k][1] + rows[k - 1][1]) * (rows[k][0] - rows[k - 1][0]);
    EXPECT_NEAR(integral, flux, 0.02 * flux);
    EXPECT_NE(fileBytes(dir / "spectrum.svg").find("<svg"), std::string::npos);

    // Render once, explore after: the stored data shade to the same bytes, and cooler is redder.
    ASSERT_EQ(runCommand(lightcone() + " shade " + scene + " " + dir / "disk.exr -o " + dir / "again.png").exitCode, 0);
    EXPECT_TRUE(fileBytes(dir / "again.png") == fileBytes(dir / "disk.png"));
    ASSERT_EQ(runCommand(lightcone() + " shade " + scene + " " + dir / "disk.exr -o " + dir / "cool.png" +
                         " --temperature 3000")
                  .exitCode,
              0);
    const auto plain = lc::io::readImageRgb(dir / "disk.png"), cool = lc::io::readImageRgb(dir / "cool.png");
    double plainRatio = 0, coolRatio = 0;
    for (std::size_t p = 0; p < plain.data.size() / 3; ++p) {
        plainRatio += plain.data[3 * p + 2] - plain.data[3 * p];
        coolRatio += cool.data[3 * p + 2] - cool.data[3 * p];
    }
    EXPECT_LT(coolRatio, plainRatio) << "a 3000 K disk is redder than a 9000 K one";

    // A scene without a disk has no spectrum: refused before anything is written.
    const CommandResult none = runCommand(lightcone() + " render " + sourcePath("data/kerr.json") + " -o " +
                                          dir / "k.png --spectrum " + dir / "k.csv --quiet");
    EXPECT_EQ(none.exitCode, 2) << none.output;
    EXPECT_NE(none.output.find("--spectrum needs a scene with an accretion disk"), std::string::npos) << none.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "k.png"));
}

TEST(DiskCommands, SweepOverSpinGivesMoreFluxAsTheIscoMovesIn) {
    const ScratchFolder dir{"disk-sweep"};
    const CommandResult r = runCommand(lightcone() + " sweep " + sourcePath("data/kerr_disk.json") +
                                       " --sweep metric.a=0:0.9:3 --table " + dir / "sweep.csv --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string csv = fileBytes(dir / "sweep.csv");
    const std::string header = csv.substr(0, csv.find('\n'));
    std::vector<std::string> names;
    std::istringstream h(header);
    for (std::string n; std::getline(h, n, ',');) names.push_back(n);
    auto column = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    const std::size_t flux = column("disk_flux"), g = column("disk_mean_redshift");
    ASSERT_LT(flux, names.size()) << header;
    ASSERT_LT(g, names.size()) << header;
    const auto rows = csvRows(csv);
    ASSERT_EQ(rows.size(), 3u);
    for (std::size_t k = 1; k < rows.size(); ++k) EXPECT_GT(rows[k][flux], rows[k - 1][flux]);
    for (const auto& row : rows) EXPECT_GT(row[g], 0.5);
}

// A disk out of view sends no light into the image: render says so instead of printing a mean g
// of NaN (issue #47), and sweep leaves the cell empty.
TEST(DiskCommands, ADiskOutOfViewHasNoMeanRedshiftAndSaysWhy) {
    const ScratchFolder dir{"disk-away"};
    std::ofstream(dir / "away.json") << R"({"metric": {"name": "kerr", "M": 1.0, "a": 0.9},
        "observer": {"position": [0, 48.3, 0, 12.9]},
        "camera": {"width": 48, "height": 27, "fov": [48, 27], "forward": [1, 0, 0], "up": [0, 0, 1]},
        "objects": [{"type": "disk", "name": "disk", "outer_radius": 20}]})";
    const CommandResult r = runCommand(lightcone() + " render " + dir / "away.json -o " + dir / "a.png --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("no light of the disk reaches the image"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
}

}  // namespace
