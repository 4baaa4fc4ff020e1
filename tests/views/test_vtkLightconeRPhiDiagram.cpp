// SPDX-License-Identifier: BSD-3-Clause
// The exported r-phi diagram: the horizon circle and one light path per image, where the
// number of images of a point in the plane z = 0 is exactly two per winding (docs/PHYSICS.md
// section 3). Runs under Xvfb.
#include "readers/io/scene_reader.hpp"
#include "diagram_checks.hpp"
#include "vtkLightconeRPhiDiagram.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(RPhiDiagram, SvgHasHorizonCircleAndTwoImagePathsPerWinding) {
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    vtkNew<vtkLightconeRPhiDiagram> diagram;
    diagram->SetScene(scene);
    diagram->SetWindings(2);
    diagram->SetFanRays(8);
    diagram->Build();
    EXPECT_EQ(diagram->GetNumberOfImagePaths(), 6);
    const std::string svgPath = (std::filesystem::temp_directory_path() / "lightcone_diagram_test.svg").string();
    diagram->Write(svgPath);
    const std::string svg = slurp(svgPath);
    // Every clip path the drawing uses is defined (VTK 9.1 left <defs> out of marker-less charts).
    ASSERT_NE(svg.find("clip-path=\"url(#vtkClipRect1)\""), std::string::npos);
    EXPECT_NE(svg.find("<clipPath id=\"vtkClipRect1\""), std::string::npos);

    // Legend: the horizon and six image labels, windings 0..2 on both branches.
    EXPECT_NE(svg.find("Goedel horizon r = 2a"), std::string::npos);
    for (int n = 0; n <= 2; ++n)
        for (const char* b : {"outbound", "inbound"})
            EXPECT_NE(svg.find("winding " + std::to_string(n) + ", " + b), std::string::npos) << n << b;

    // The horizon is the dashed red polyline (the first one; the second is its legend swatch),
    // written in chart units: its vertices lie on a circle of radius 2a = 2.
    // (Plain string search: std::regex recurses per character and overflows the stack on this
    // long attribute under AddressSanitizer.)
    std::string points;
    for (std::size_t at = svg.find("<polyline stroke=\"#cc1919\""); at != std::string::npos && points.empty();
         at = svg.find("<polyline stroke=\"#cc1919\"", at + 1)) {
        const std::string tag = svg.substr(at, svg.find('>', at) - at);
        const std::size_t p = tag.find("points=\"");
        if (tag.find("stroke-dasharray") != std::string::npos && p != std::string::npos)
            points = tag.substr(p + 8, tag.find('"', p + 8) - (p + 8));
    }
    ASSERT_FALSE(points.empty()) << "no dashed red polyline (the horizon) in the SVG";
    std::vector<std::pair<double, double>> pts;
    std::stringstream ps(points);
    std::string token;
    while (ps >> token) {
        const auto comma = token.find(',');
        pts.emplace_back(std::stod(token.substr(0, comma)), std::stod(token.substr(comma + 1)));
    }
    ASSERT_GT(pts.size(), 100u);
    pts.pop_back();  // the closing vertex repeats the first
    double cx = 0, cy = 0;
    for (auto [x, y] : pts) cx += x / pts.size(), cy += y / pts.size();
    double rmin = 1e9, rmax = 0;
    for (auto [x, y] : pts) {
        const double r = std::hypot(x - cx, y - cy);
        rmin = std::min(rmin, r);
        rmax = std::max(rmax, r);
    }
    EXPECT_NEAR(rmin, 2.0, 2e-3);  // SVG keeps about six digits
    EXPECT_NEAR(rmax, 2.0, 2e-3);
    std::filesystem::remove(svgPath);
}

// data/godel_many_images.json's legend (twelve images) once covered the horizon: now it stands
// right of the plot area, and the plot keeps equal scales on both axes.
TEST(RPhiDiagram, LegendStaysOutsideTheSquarePlotArea) {
    vtkNew<vtkLightconeRPhiDiagram> diagram;
    diagram->SetScene(lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/godel_many_images.json"));
    diagram->SetWindings(5);
    diagram->SetFanRays(8);
    diagram->Build();
    const lc::test::SvgDocument svg = lc::test::parseSvg(diagram->Encode(".svg"));
    const lc::test::SvgRect plot = lc::test::plotArea(diagram, svg.height);
    EXPECT_NEAR(plot.width, plot.height, 1.0);
    EXPECT_GT(lc::test::legendLeft(diagram), plot.x + plot.width);
    const auto entries = lc::test::legendTexts(svg, {"image of", "Goedel horizon"});
    EXPECT_EQ(entries.size(), 12u + 1u);
    for (const auto& t : entries) EXPECT_GT(t.x, plot.x + plot.width) << t.text;

    // Equal aspect: the same pixels per unit across and up (to the labels' whole pixels), and
    // the horizon circle r = 2a inside the plot area.
    const lc::test::SvgAxisMap x = lc::test::axisMap(svg, true), y = lc::test::axisMap(svg, false);
    EXPECT_NEAR(x.pixelsPerUnit() / y.pixelsPerUnit(), 1.0, 0.005);
    for (double v : {-2.0, 2.0}) {
        const double px = (v - x.offset) / x.scale, py = (v - y.offset) / y.scale;
        EXPECT_TRUE(plot.contains(px, py)) << v << " at " << px << ", " << py;
    }
}

TEST(RPhiDiagram, RejectsNonGodelScenesAndUnknownFormats) {
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/kerr.json");
    vtkNew<vtkLightconeRPhiDiagram> diagram;
    EXPECT_THROW(diagram->SetScene(scene), std::invalid_argument);
    diagram->SetScene(lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json"));
    EXPECT_THROW(diagram->Write("/tmp/x.bmpx"), std::invalid_argument);
}

}  // namespace
