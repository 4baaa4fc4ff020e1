// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A render as a figure for a paper (lightcone figure, the workbench's File > Export figure): the
// image on angular axes in degrees, a colour bar for a scalar quantity (redshift, emission time)
// and a caption with the scene's parameters, encoded as SVG, PDF or PNG (a VTK chart, as the
// diagrams: needs an X display). Axes: a panorama's azimuth right of forward and elevation; a
// pinhole's tangent-plane coordinates (d.right / d.forward, d.up / d.forward), ticked at the tangents
// of round angles, i.e. the angle of the direction's projection on the forward-right (forward-up)
// plane.
#include "core/render/special_relativity.hpp"
#include "core/scene/scene.hpp"

#include <vtkSmartPointer.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

class vtkChartXY;

namespace lc::views {

class DiagramChart;

enum class FigureQuantity { Image, Redshift, EmissionTime };
// "image", "redshift", "emission-time"; nullopt for another name.
std::optional<FigureQuantity> figureQuantityNamed(const std::string& name);
std::string figureQuantityName(FigureQuantity quantity);

// The figure coordinates of the continuous image point (x, y) (pixels, row 0 at the top, as
// Camera::directionAt takes them): a panorama's (angle right of forward, elevation) in degrees, a
// pinhole's tangent-plane coordinates.
Vec2 figurePoint(const Camera& camera, double x, double y);
// The angle in degrees that figure coordinate `c` stands for: c itself (panorama) or atan(c) (pinhole).
double figureAngleDegrees(const Camera& camera, double c);

// Ticks at round angles (1, 2, 5, 10, 15, 30, 45 or 90 degrees apart, about six over the field).
struct FigureTicks {
    std::vector<double> positions;  // figure coordinates
    std::vector<std::string> labels;
};
FigureTicks figureTicks(const Camera& camera, int axis);  // 0: x, 1: y

// "Kerr (M = 1, a = 0.9); observer at (t, x, y, z) = (0, 20, 0, 0), pinhole 70 x 35 deg, 160 x 80
// px; numeric, tolerance 1e-10" and what the colours show.
std::string figureCaption(const Scene& scene, FigureQuantity quantity);

class ImageFigure {
public:
    // Throws std::invalid_argument where the image is not the scene's size.
    ImageFigure(const Scene& scene, const ColouredImage& image, FigureQuantity quantity, int height = 700);
    ~ImageFigure();
    // ".svg", ".pdf" or ".png", the plot area at the image's aspect ratio on the axes.
    std::string encode(const std::string& format);
    vtkChartXY* chart() const;
    // The colour bar's range (scalar quantities; NaN for the image).
    double scaleMin() const { return scaleMin_; }
    double scaleMax() const { return scaleMax_; }

private:
    std::unique_ptr<DiagramChart> chart_;
    double aspect_ = 1;
    double scaleMin_, scaleMax_;
};

}  // namespace lc::views
