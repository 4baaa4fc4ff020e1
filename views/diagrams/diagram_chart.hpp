// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the Goedel diagrams (vtkLightconeRPhiDiagram, vtkLightconeTRDiagram) draw with: a
// vtkChartXY alone in its own context view (item 0 of the scene: the workbench takes it over),
// its legend outside the plot area to the right so that it never covers data, curves, markers
// and bands from coordinate lists, and the encoding to SVG, PDF or PNG with the plot area at a
// fixed aspect ratio.
#include "core/godel/images.hpp"
#include "core/scene/scene.hpp"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkChartXY;
class vtkContextView;
class vtkPlot;

namespace lc::views {

// Distinct colours for the image paths (colour-blind safe, Okabe-Ito); image k of a diagram
// takes colour k % 8 in both diagrams.
extern const double kImageColours[8][3];

class DiagramChart {
public:
    // A window `height` px high (the legend widens it when encoded).
    explicit DiagramChart(int height);
    // Into a chart of a subclass (a vtkChartHistogram2D's colour bar as its legend).
    DiagramChart(int height, vtkSmartPointer<vtkChartXY> chart);
    vtkContextView* view() const;
    vtkChartXY* chart() const;

    // A fixed axis range: the diagrams place their data in known units.
    void setAxis(int axis, double min, double max, const std::string& title);
    // label "" keeps the plot out of the legend.
    vtkPlot* addCurve(const std::vector<double>& x, const std::vector<double>& y, const double rgb[3], float width,
                      const std::string& label, int lineType);
    // Line segments between the pairs of points (x[0], y[0])-(x[1], y[1]), (x[2], y[2])-...: many
    // curves in one plot, one draw call.
    vtkPlot* addSegments(const std::vector<double>& x, const std::vector<double>& y, const double rgb[3], float width,
                         const std::string& label);
    vtkPlot* addMarkers(const std::vector<double>& x, const std::vector<double>& y, const double rgb[3], float size,
                        const std::string& label, int markerStyle);
    // The rectangle [x0, x1] x [y0, y1] filled with rgb at `opacity`.
    vtkPlot* addBand(double x0, double x1, double y0, double y1, const double rgb[3], double opacity,
                     const std::string& label);

    // ".svg", ".pdf" or ".png" with the plot area's width / height at `aspect`; needs an X
    // display (Xvfb). `title` names the SVG and PDF document.
    std::string encode(const std::string& format, const std::string& title, double aspect);

private:
    // Renders offscreen and widens the window until the plot area has the aspect (to the
    // pixel); the legend's column is what the window gains over its height.
    void fitPlotAspect(double aspect);
    vtkPlot* addTable(int plotType, const std::vector<std::vector<double>>& columns);

    vtkSmartPointer<vtkContextView> view_;
    vtkSmartPointer<vtkChartXY> chart_;
    int columns_ = 0;
    vtkPlot* svgAnchor_ = nullptr;  // the invisible marker SVG export needs (encode), owned by chart_  // column names
                                    // are unique within the chart
};

// The images of one sphere of the scene with their emission events in the observer's chart
// (observer at the origin): static spheres through godel::ObserverView::images, as `lightcone
// images` solves them, moving ones (free fall, world line) through lc::imagesOfMovingCentre.
// Image::emissionTime stays in the scene's chart, as both report it.
struct ObservedImage {
    godel::Image image;
    Vec4 emission = Vec4::Zero();  // (t, X, Y, z) in the observer's chart
};
std::vector<ObservedImage> observedImages(const Scene& scene, const godel::ObserverView& view,
                                          const SphereObject& sphere, int maxWinding);

// Later windings retrace earlier paths closely: earlier ones are drawn wider so that every path
// stays visible underneath.
float imagePathWidth(int winding);
// What an image path of the highlighted object gains over imagePathWidth(), and the colour of the
// other objects' paths (lighter than every kImageColours entry).
constexpr float kHighlightExtraWidth = 3.0f;
constexpr double kDimmedImageColour[3] = {0.82, 0.82, 0.82};

// "image of 'NAME': winding N, BRANCH, emitted t = T": the legend entry of one image path.
std::string imageLabel(const std::string& object, const godel::Image& image);

}  // namespace lc::views
