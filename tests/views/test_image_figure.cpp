// SPDX-License-Identifier: BSD-3-Clause
// The figure of a render (views/diagrams/image_figure.hpp, lightcone figure): its axes give the
// angles of the camera's own rays (lc::Camera::direction, the renderers' source) for inclined
// pinhole and panorama cameras; read back from the SVG, the image fills exactly the rectangle its
// degree ticks span; the redshift colour bar spans the static observer's closed-form blueshift of
// the sky, 1 / sqrt(1 - 2M/r0) (docs/PHYSICS.md); vtkLightconeImagePlot refuses what it cannot draw.
// Runs under Xvfb.
#include "core/render/special_relativity.hpp"
#include "image_figure.hpp"
#include "readers/io/scene_reader.hpp"
#include "svg_reader.hpp"
#include "vtkLightconeImagePlot.h"

#include <vtkImageData.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {

constexpr double kDeg = 180 / lc::kPi;

lc::Camera inclinedCamera(lc::Camera::Projection projection, double fovX, double fovY) {
    lc::Camera c;
    c.projection = projection;
    c.width = 96;
    c.height = 40;
    c.fovXDeg = fovX;
    c.fovYDeg = fovY;
    c.forward = lc::Vec3(0.8, -0.35, 0.3);  // not along a chart axis, tilted up
    c.up = lc::Vec3(0.1, 0, 1);
    return c;
}

// The angle of direction d right of forward and above it, as each projection measures them.
lc::Vec2 anglesOfRay(const lc::Camera& c, const lc::Vec3& d) {
    const lc::Camera::Axes a = c.axes();
    const double f = d.dot(a.forward), r = d.dot(a.right), u = d.dot(a.up);
    if (c.projection == lc::Camera::Projection::Pinhole) return lc::Vec2(std::atan2(r, f), std::atan2(u, f)) * kDeg;
    return lc::Vec2(std::atan2(r, f), std::atan2(u, std::hypot(f, r))) * kDeg;
}

TEST(ImageFigure, AxesGiveTheAnglesOfTheCamerasRaysForInclinedCameras) {
    for (const lc::Camera& cam : {inclinedCamera(lc::Camera::Projection::Pinhole, 70, 35),
                                  inclinedCamera(lc::Camera::Projection::Panorama, 300, 100)}) {
        SCOPED_TRACE(cam.projection == lc::Camera::Projection::Pinhole ? "pinhole" : "panorama");
        double worst = 0;
        for (int j = 0; j < cam.height; j += 3)
            for (int i = 0; i < cam.width; i += 5) {
                const lc::Vec2 p = lc::views::figurePoint(cam, i + 0.5, j + 0.5);
                const lc::Vec2 want = anglesOfRay(cam, cam.direction(i, j));
                worst = std::max({worst, std::abs(lc::views::figureAngleDegrees(cam, p.x()) - want.x()),
                                  std::abs(lc::views::figureAngleDegrees(cam, p.y()) - want.y())});
            }
        EXPECT_LT(worst, 1e-9);
        // Every tick sits where its label's angle is, inside the field.
        for (int axis = 0; axis < 2; ++axis) {
            const lc::views::FigureTicks t = lc::views::figureTicks(cam, axis);
            ASSERT_GE(t.positions.size(), 3u);
            ASSERT_LE(t.positions.size(), 9u);
            for (std::size_t k = 0; k < t.positions.size(); ++k) {
                EXPECT_NEAR(lc::views::figureAngleDegrees(cam, t.positions[k]), std::stod(t.labels[k]), 1e-9);
                EXPECT_LE(std::abs(std::stod(t.labels[k])), 0.5 * (axis == 0 ? cam.fovXDeg : cam.fovYDeg) + 1e-9);
            }
        }
    }
}

double tangentOfDegrees(double deg) { return std::tan(deg / kDeg); }

// A static observer at r0 = 20 M looking past a Schwarzschild hole, the camera turned off the hole.
const char* const kSchwarzschild = R"({
  "metric": {"name": "schwarzschild", "M": 1.0},
  "observer": {"position": [0, 20, 0, 0]},
  "camera": {"projection": "pinhole", "width": 64, "height": 32, "fov": [70, 35], "forward": [-1, 0.25, 0.1], "up": [0, 0, 1]},
  "sky": {"type": "checker", "cells": [36, 18]},
  "render": {"tolerance": 1e-8}
})";

TEST(ImageFigure, TheSvgImageFillsTheRectangleItsDegreeTicksSpanAndTheBarTheSkysBlueshift) {
    const lc::Scene scene = lc::io::parseScene(kSchwarzschild, "schwarzschild.json");
    const lc::ColouredImage image = lc::renderColouredImage(scene);
    lc::views::ImageFigure figure(scene, image, lc::views::FigureQuantity::Redshift, 400);
    // The sky's light: emitted at rest at infinity, received by the static observer at r0 with
    // g = 1 / sqrt(1 - 2M/r0) (gravitational blueshift), the largest g in the image.
    EXPECT_NEAR(figure.scaleMax(), 1 / std::sqrt(1 - 2.0 / 20), 1e-5);
    const lc::test::SvgDocument svg = lc::test::parseSvg(figure.encode(".svg"));
    ASSERT_EQ(svg.images.size(), 2u);  // the render, then the colour bar
    const lc::test::SvgImage& drawn = svg.images[0];
    const lc::test::SvgAxisMap x = lc::test::axisMap(svg, true, tangentOfDegrees);
    const lc::test::SvgAxisMap y = lc::test::axisMap(svg, false, tangentOfDegrees);
    const lc::Vec2 half = scene.camera.halfFieldTangents();
    const double tolX = 1.5 / x.pixelsPerUnit(), tolY = 1.5 / y.pixelsPerUnit();
    EXPECT_NEAR(x(drawn.x), -half.x(), tolX);
    EXPECT_NEAR(x(drawn.x + drawn.width), half.x(), tolX);
    EXPECT_NEAR(y(drawn.y), half.y(), tolY);  // page y grows downwards
    EXPECT_NEAR(y(drawn.y + drawn.height), -half.y(), tolY);
    bool caption = false, bar = false;
    for (const auto& t : svg.texts) {
        caption = caption || t.text.find("metric 'schwarzschild' (M = 1,") != std::string::npos;
        bar = bar || t.text == "g";
    }
    EXPECT_TRUE(caption);
    EXPECT_TRUE(bar);
    // PDF and PNG from the same chart.
    EXPECT_EQ(figure.encode(".pdf").substr(0, 5), "%PDF-");
    EXPECT_EQ(figure.encode(".png").substr(1, 3), "PNG");
}

TEST(ImageFigure, RefusesAnImageOfAnotherSize) {
    const lc::Scene scene = lc::io::parseScene(kSchwarzschild, "schwarzschild.json");
    lc::ColouredImage image;
    image.records.width = 10;
    image.records.height = 10;
    image.rgb.assign(300, 0.f);
    EXPECT_THROW(lc::views::ImageFigure(scene, image, lc::views::FigureQuantity::Image), std::invalid_argument);
    EXPECT_FALSE(lc::views::figureQuantityNamed("brightness").has_value());
}

TEST(vtkLightconeImagePlot, DrawsEightBitColoursOverItsExtentAndRefusesTheRest) {
    vtkNew<vtkLightconeImagePlot> plot;
    vtkNew<vtkImageData> grey;
    grey->SetDimensions(4, 3, 1);
    grey->AllocateScalars(VTK_FLOAT, 1);
    EXPECT_THROW(plot->SetImage(grey), std::invalid_argument);
    vtkNew<vtkImageData> rgb;
    rgb->SetDimensions(4, 3, 1);
    rgb->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    plot->SetImage(rgb);
    EXPECT_EQ(plot->GetImage(), rgb.Get());
    EXPECT_THROW(plot->SetExtent(1, 0, 0, 1), std::invalid_argument);
    EXPECT_THROW(plot->SetExtent(0, 1, 2, 2), std::invalid_argument);
    plot->SetExtent(-2, 3, -1, 4);
    double bounds[4];
    plot->GetBounds(bounds);
    EXPECT_EQ(bounds[0], -2);
    EXPECT_EQ(bounds[1], 3);
    EXPECT_EQ(bounds[2], -1);
    EXPECT_EQ(bounds[3], 4);
}

}  // namespace
