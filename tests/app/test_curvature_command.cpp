// SPDX-License-Identifier: BSD-3-Clause
// `lightcone curvature` as a user runs it: the JSON at an event against Kerr's Kretschmann
// closed form (Henry 2000) and static tides; a .vti of Alcubierre's Eulerian energy density
// (Alcubierre 1994, eq. 19) read back with VTK's reader; the tides along a radial infall against
// -2M/r^3 and the infall's proper time from r = 10 M to the horizon in closed form; bad input
// named with exit status 2 and nothing written.
#ifdef LIGHTCONE_WITH_VTK
#include "readers/io/image_io.hpp"
#include "run_command.hpp"
#include "tests/common/curvature_oracles.hpp"

#include <gtest/gtest.h>
#include <json/json.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <sstream>

using namespace lc::test;

namespace {

// A numeric CSV: its header line and its rows.
std::pair<std::string, std::vector<std::vector<double>>> numericCsv(const std::string& path) {
    std::istringstream in(fileBytes(path));
    std::string header, line;
    std::getline(in, header);
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line)) {
        std::vector<double> cells;
        std::stringstream cellStream(line);
        std::string cell;
        while (std::getline(cellStream, cell, ',')) cells.push_back(std::stod(cell));
        rows.push_back(cells);
    }
    return {header, rows};
}

Json::Value jsonOf(const std::string& text) {
    Json::Value v;
    std::istringstream in(text);
    Json::CharReaderBuilder b;
    std::string errors;
    EXPECT_TRUE(Json::parseFromStream(b, in, &v, &errors)) << errors << "\n" << text;
    return v;
}

TEST(CurvatureCommand, AtAnEventKerrKretschmannAndStaticTidesMatchClosedForms) {
    const CommandResult r = runCommand(lightcone() + " curvature --metric kerr --param a=0.9 --at 0,3,1,0.5");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Json::Value v = jsonOf(r.output);
    const double a = 0.9, x = 3, y = 1, z = 0.5;
    const double rho2 = x * x + y * y + z * z - a * a;
    const double r2 = 0.5 * (rho2 + std::sqrt(rho2 * rho2 + 4 * a * a * z * z)), rr = std::sqrt(r2);
    const double K = kerrNewmanKretschmann(1.0, a, 0.0, rr, z / rr);  // Henry 2000, eq. 9
    EXPECT_NEAR(v["kretschmann"].asDouble() / K, 1, 1e-10) << "r = " << rr;
    EXPECT_NEAR(v["ricci_scalar"].asDouble(), 0, 1e-12);
    EXPECT_EQ(v["observer"]["field"].asString(), "auto");
    ASSERT_EQ(v["observer"]["tidal_eigenvalues"].size(), 3u);
    // Vacuum: the tidal tensor is trace-free (R_ab u^a u^b = 0), and nothing is there.
    double trace = 0;
    for (const auto& e : v["observer"]["tidal_eigenvalues"]) trace += e.asDouble();
    EXPECT_NEAR(trace, 0, 1e-12);
    EXPECT_NEAR(v["observer"]["energy_density"].asDouble(), 0, 1e-13);
    EXPECT_EQ(v["matter"]["hawking_ellis_type"].asString(), "I");
}

TEST(CurvatureCommand, AlcubierreEnergyDensityGridAsVtkImageData) {
    const ScratchFolder dir("curvature-grid");
    const std::string out = dir / "warp.vti";
    const CommandResult r = runCommand(lightcone() +
                                       " curvature --metric alcubierre --param v=0.5 --param R=1 --param sigma=4"
                                       " --quantity energy_density --quantity weak_energy_violation"
                                       " --observers normal --bounds -2,2,-2,2,0,0 --dims 41,41,1 --quiet -o " +
                                       out);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName(out.c_str());
    reader->Update();
    vtkImageData* img = reader->GetOutput();
    ASSERT_EQ(img->GetNumberOfPoints(), 41 * 41);
    vtkDataArray* rho = img->GetPointData()->GetArray("energy_density");
    vtkDataArray* weak = img->GetPointData()->GetArray("weak_energy_violation");
    ASSERT_TRUE(rho && weak);
    const double v = 0.5, R = 1, sigma = 4;
    double lowest = 0;
    for (vtkIdType id = 0; id < img->GetNumberOfPoints(); ++id) {
        double p[3];
        img->GetPoint(id, p);
        const double expected = alcubierreEulerianDensity(v, R, sigma, p[0], p[1], p[2]);  // eq. 19
        EXPECT_NEAR(rho->GetTuple1(id), expected, 1e-10 + 1e-9 * std::abs(expected)) << p[0] << "," << p[1];
        EXPECT_GE(weak->GetTuple1(id), -expected * (1 - 1e-9));
        lowest = std::min(lowest, rho->GetTuple1(id));
    }
    EXPECT_LT(lowest, -1e-3);  // the wall's negative energy is there to see
}

TEST(CurvatureCommand, TidesAlongARadialInfallAreMinusTwoMOverRCubedUntilTheHorizon) {
    const ScratchFolder dir("curvature-tides");
    const std::string csv = dir / "tides.csv", svg = dir / "tides.svg";
    const CommandResult r = runCommand(lightcone() + " curvature " + sourcePath("data/schwarzschild_infall.json") +
                                       " --tides " + csv + " --plot " + svg + " --proper-time 14 --samples 141");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // Falling from rest at infinity, r(tau)^(3/2) = 10^(3/2) - (3/2) sqrt(2M) tau: the horizon
    // r = 2M at tau = (2/3)(10^1.5 - 2^1.5)/sqrt(2) = 13.5737 (e.g. MTW eq. 25.38).
    const double horizonTau = 2.0 / 3 * (std::pow(10, 1.5) - std::pow(2, 1.5)) / std::sqrt(2.0);
    EXPECT_NE(r.output.find("the world line ends there"), std::string::npos) << r.output;
    const auto [header, table] = numericCsv(csv);
    EXPECT_EQ(header, "tau,t,x1,x2,x3,u_t,u_1,u_2,u_3,tidal_1,tidal_2,tidal_3,kretschmann");
    double lastTau = 0;
    int rows = 0;
    for (const std::vector<double>& c : table) {
        ASSERT_EQ(c.size(), 13u);
        const double rr = std::sqrt(c[2] * c[2] + c[3] * c[3] + c[4] * c[4]);
        EXPECT_NEAR(rr, std::pow(std::pow(10, 1.5) - 1.5 * std::sqrt(2.0) * c[0], 2.0 / 3), 1e-6 * rr);
        EXPECT_NEAR(c[9] / (-2 / std::pow(rr, 3)), 1, 1e-8);
        EXPECT_NEAR(c[10] / (1 / std::pow(rr, 3)), 1, 1e-8);
        EXPECT_NEAR(c[12] / (48 / std::pow(rr, 6)), 1, 1e-8);
        lastTau = c[0];
        ++rows;
    }
    EXPECT_GT(rows, 100);
    EXPECT_LT(lastTau, horizonTau);
    EXPECT_GT(lastTau, horizonTau - 0.2);  // one sample spacing (0.1) and the stop margin
    EXPECT_NE(fileBytes(svg).find("<svg"), std::string::npos);
}

// The slice drawn: the warp bubble's energy density vanishes on its axis of motion (the plot's
// centre, white) and is most negative in the wall at distance R across it (blue), the same above
// and below. The plot fills the left 82 % and top 92 % of the picture at 142 px per unit here.
TEST(CurvatureCommand, SliceImageShowsTheWarpWallWhereAlcubierreDensityPeaks) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "the slice is drawn through VTK's OpenGL (xvfb-run -a)";
    const ScratchFolder dir("curvature-image");
    const std::string png = dir / "warp.png";
    const CommandResult r = runCommand(lightcone() +
                                       " curvature --metric alcubierre --param v=0.5 --param sigma=4"
                                       " --quantity energy_density --observers normal --bounds -2.5,2.5,-2,2,0,0"
                                       " --dims 251,201,1 --quiet --image " +
                                       png);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const lc::io::ImageChannels image = lc::io::readImageRgb(png);
    ASSERT_EQ(image.width, 900);
    ASSERT_EQ(image.height, 700);
    auto pixel = [&](double x, double y) {  // y down from the top
        const std::size_t i =
            3 * (static_cast<std::size_t>(std::lround(y)) * 900 + static_cast<std::size_t>(std::lround(x)));
        return std::array<float, 3>{image.data[i], image.data[i + 1], image.data[i + 2]};
    };
    const double cx = 0.41 * 900, cy = 0.46 * 700;
    const double perUnit = (0.46 * 700) / (0.52 * 5.0 / ((0.82 * 900) / (0.92 * 700)));
    const auto centre = pixel(cx, cy), above = pixel(cx, cy - perUnit), below = pixel(cx, cy + perUnit);
    EXPECT_GT(std::min({centre[0], centre[1], centre[2]}), 0.9f) << "not white on the axis";
    for (const auto& wall : {above, below}) {
        EXPECT_GT(wall[2] - wall[0], 0.3f) << "not blue in the wall";
        EXPECT_LT(wall[0], 0.2f);
    }
}

// The time traveller's tides (data/godel_time_traveller.json, a = 1): the trace of the tidal
// tensor is R_ab u^a u^b = (u . u_dust)^2 / a^2 since Goedel's R_ab = u_a u_b / a^2 with the dust
// u_dust = d/dt (docs/PHYSICS.md section 13), and u . d/dt = g_ta u^a with the chart's
// g_tt = 1, g_tx = -y/(sqrt2 a), g_ty = x/(sqrt2 a) (section 1): at rest 1/a^2, moving gamma^2/a^2,
// along the whole trip through the closed timelike curves and back.
TEST(CurvatureCommand, TidesAlongTheTimeTravellerFollowItsSpeedThroughTheDust) {
    const ScratchFolder dir("curvature-traveller");
    const std::string csv = dir / "traveller.csv";
    const CommandResult r = runCommand(lightcone() + " curvature " + sourcePath("data/godel_time_traveller.json") +
                                       " --tides " + csv + " --object traveller --samples 300");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    double fastest = 1;
    int rows = 0;
    for (const std::vector<double>& c : numericCsv(csv).second) {
        ASSERT_EQ(c.size(), 13u);
        const double x = c[2], y = c[3];
        const double gamma = c[5] - y / std::sqrt(2.0) * c[6] + x / std::sqrt(2.0) * c[7];
        EXPECT_NEAR(c[9] + c[10] + c[11], gamma * gamma, 1e-9 * gamma * gamma) << "tau = " << c[0];
        EXPECT_NEAR(c[12], 3, 1e-9);  // homogeneous: the same Kretschmann scalar everywhere
        fastest = std::max(fastest, std::abs(gamma));
        ++rows;
    }
    EXPECT_EQ(rows, 300);
    EXPECT_GT(fastest, 1.5);  // the trip is fast: the tides are not the comoving observer's
    const CommandResult bad = runCommand(lightcone() + " curvature " + sourcePath("data/godel_time_traveller.json") +
                                         " --tides " + csv + " --object nobody");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("no object named 'nobody'"), std::string::npos) << bad.output;
}

TEST(CurvatureCommand, BadInputIsNamedAndNothingIsWritten) {
    const ScratchFolder dir("curvature-bad");
    const std::string out = dir / "field.vti";
    struct Case {
        std::string args, expected;
    };
    const std::vector<Case> cases{
        {"--metric kerr", "needs --at t,x,y,z, -o FIELD.vti, --image SLICE.png or --tides"},
        {"--metric kerr --bounds -1,1,-1,1,-1,1 --dims 5,5,5 --image " + dir / "s.png -o " + out, "exactly one axis"},
        {"--metric kerr --dims 0,10,1 -o " + out, "--dims"},
        {"--metric kerr --quantity curvature -o " + out, "curvature"},
        {"--metric kerr --param a=2 --at 0,5,0,0", "a"},
        {"--metric kerr --tides " + dir / "t.csv", "give a scene file"},
        {"--metric kerr --bounds 1,0,0,1,0,0 --dims 5,5,1 -o " + out, "lower bound of axis 1"},
        {"--metric kerr --bounds 0,1,0,1,0,0 --dims 5,1,1 -o " + out, "axis 2 has one point"},
        {"--metric kerr -o " + dir / "field.png", "-o"},
        {"--metric kerr --at 0,0,0,0", "not finite"},
        {"--metric kerr --dims 4096,4096,4 -o " + out, "lower the resolution"},
        {"--metric kerr --at nan,0,0,0", "--at"},
        {"--metric kerr --lambda 1e400 --at 0,5,0,0", "--lambda"},
    };
    for (const Case& c : cases) {
        const CommandResult r = runCommand(lightcone() + " curvature " + c.args);
        EXPECT_NE(r.exitCode, 0) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.args;
    }
}

// Without an X server VTK aborted the process (exit 134) after the whole grid was computed; the
// picture's need for a display is now said before any work, and the .vti alone needs none.
TEST(CurvatureCommand, ImageWithoutAnXDisplayIsRefusedBeforeTheWork) {
    const ScratchFolder dir("curvature-nodisplay");
    const std::string grid =
        " curvature --metric kerr --param a=0.9 --quantity kretschmann --bounds -3,3,-3,3,0,0 "
        "--dims 21,21,1 --quiet -o " +
        dir / "k.vti";
    CommandResult r = runCommand("env -u DISPLAY " + lightcone() + grid + " --image " + dir / "k.png");
    EXPECT_NE(r.exitCode, 0) << r.output;
    EXPECT_LT(r.exitCode, 128) << "a crash: " << r.output;
    EXPECT_NE(r.output.find("--image is drawn by VTK through GLX and needs an X display"), std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "k.vti"));
    r = runCommand("env -u DISPLAY " + lightcone() + grid);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "k.vti"));
}

}  // namespace
#endif
