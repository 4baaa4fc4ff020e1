// SPDX-License-Identifier: BSD-3-Clause
#include "diagram_chart.hpp"

#include "core/render/photo_scene.hpp"
#include "readers/io/input_file.hpp"

#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPDFExporter.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotArea.h>
#include <vtkPlotLine.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSVGExporter.h>
#include <vtkTable.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace lc::views {
namespace {
namespace fs = std::filesystem;

std::string encodePng(vtkRenderWindow* win) {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(win);
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkNew<vtkPNGWriter> png;
    png->SetInputConnection(grab->GetOutputPort());
    png->WriteToMemoryOn();
    png->Write();
    vtkUnsignedCharArray* bytes = png->GetResult();
    if (!bytes || bytes->GetNumberOfValues() == 0)
        throw std::runtime_error("diagram: PNG encoding failed (is there an X display?)");
    return std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)),
                       static_cast<std::size_t>(bytes->GetNumberOfValues()));
}

// The GL2PS exporters write only to files: a private scratch folder, read back and removed, so
// the output itself goes through the atomic writer like every other file.
std::string encodeVector(vtkRenderWindow* win, const std::string& format, const std::string& title) {
    std::string scratch = (fs::temp_directory_path() / "lightcone-diagram-XXXXXX").string();
    if (!::mkdtemp(scratch.data()))
        throw std::runtime_error("diagram: cannot create a scratch folder in " + fs::temp_directory_path().string());
    const fs::path file = fs::path(scratch) / ("diagram" + format);
    std::string bytes;
    try {
        if (format == ".svg") {
            vtkNew<vtkSVGExporter> svg;
            svg->SetRenderWindow(win);
            svg->SetFileName(file.string().c_str());
            svg->SetTitle(title.c_str());
            svg->TextAsPathOff();  // keep labels searchable and editable
            svg->Write();
        } else {
            vtkNew<vtkPDFExporter> pdf;
            pdf->SetRenderWindow(win);
            pdf->SetFileName(file.string().c_str());
            pdf->SetTitle(title.c_str());
            pdf->Write();
        }
        bytes = lc::io::readInputFile(file.string(), lc::input::kSceneFileBytes);
    } catch (const std::exception& e) {
        std::error_code ec;
        fs::remove_all(scratch, ec);
        throw std::runtime_error(std::string("diagram: the exporter wrote no file (is there an X display?): ") +
                                 e.what());
    }
    std::error_code ec;
    fs::remove_all(scratch, ec);
    return bytes;
}

}  // namespace

const double kImageColours[8][3] = {{0.90, 0.62, 0.0}, {0.34, 0.71, 0.91}, {0.0, 0.62, 0.45},  {0.80, 0.47, 0.65},
                                    {0.84, 0.37, 0.0}, {0.0, 0.45, 0.70},  {0.94, 0.89, 0.26}, {0.5, 0.5, 0.5}};

DiagramChart::DiagramChart(int height) : DiagramChart(height, vtkSmartPointer<vtkChartXY>::New()) {}

DiagramChart::DiagramChart(int height, vtkSmartPointer<vtkChartXY> chart)
    : view_(vtkSmartPointer<vtkContextView>::New()), chart_(std::move(chart)) {
    view_->GetRenderWindow()->SetSize(height, height);
    view_->GetRenderer()->SetBackground(1, 1, 1);
    view_->GetScene()->AddItem(chart_);
    chart_->SetShowLegend(true);
    // Outside the plot area: vtkChartXY then widens its right border by the legend's width.
    vtkChartLegend* legend = chart_->GetLegend();
    legend->SetInline(false);
    legend->SetHorizontalAlignment(vtkChartLegend::RIGHT);
    legend->SetVerticalAlignment(vtkChartLegend::TOP);
}

vtkContextView* DiagramChart::view() const { return view_; }
vtkChartXY* DiagramChart::chart() const { return chart_; }

void DiagramChart::setAxis(int axis, double min, double max, const std::string& title) {
    vtkAxis* ax = chart_->GetAxis(axis);
    ax->SetBehavior(vtkAxis::FIXED);
    ax->SetRange(min, max);
    ax->SetTitle(title);
}

vtkPlot* DiagramChart::addTable(int plotType, const std::vector<std::vector<double>>& columns) {
    vtkNew<vtkTable> table;
    for (const auto& values : columns) {
        vtkNew<vtkDoubleArray> column;
        column->SetName(("c" + std::to_string(columns_++)).c_str());
        column->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
        for (std::size_t i = 0; i < values.size(); ++i) column->SetValue(static_cast<vtkIdType>(i), values[i]);
        table->AddColumn(column);
    }
    vtkPlot* plot = chart_->AddPlot(plotType);
    plot->SetInputData(table, 0, 1);
    return plot;
}

vtkPlot* DiagramChart::addCurve(const std::vector<double>& x, const std::vector<double>& y, const double rgb[3],
                                float width, const std::string& label, int lineType) {
    vtkPlot* plot = addTable(vtkChart::LINE, {x, y});
    plot->SetColor(rgb[0], rgb[1], rgb[2]);
    plot->SetWidth(width);
    plot->GetPen()->SetLineType(lineType);
    plot->SetLabel(label);
    plot->SetLegendVisibility(!label.empty());
    return plot;
}

vtkPlot* DiagramChart::addSegments(const std::vector<double>& x, const std::vector<double>& y, const double rgb[3],
                                   float width, const std::string& label) {
    vtkPlot* plot = addCurve(x, y, rgb, width, label, vtkPen::SOLID_LINE);
    vtkPlotLine::SafeDownCast(plot)->PolyLineOff();
    return plot;
}

vtkPlot* DiagramChart::addMarkers(const std::vector<double>& x, const std::vector<double>& y, const double rgb[3],
                                  float size, const std::string& label, int markerStyle) {
    vtkPlot* plot = addTable(vtkChart::POINTS, {x, y});
    plot->SetColor(rgb[0], rgb[1], rgb[2]);
    auto* points = vtkPlotPoints::SafeDownCast(plot);
    points->SetMarkerStyle(markerStyle);
    points->SetMarkerSize(size);
    plot->SetLabel(label);
    plot->SetLegendVisibility(!label.empty());
    return plot;
}

vtkPlot* DiagramChart::addBand(double x0, double x1, double y0, double y1, const double rgb[3], double opacity,
                               const std::string& label) {
    // vtkPlotArea fills nothing with fewer than three x samples.
    vtkPlot* plot = addTable(vtkChart::AREA, {{x0, 0.5 * (x0 + x1), x1}, {y0, y0, y0}, {y1, y1, y1}});
    vtkTable* table = plot->GetInput();
    for (int i = 0; i < 3; ++i) plot->SetInputArray(i, table->GetColumn(i)->GetName());
    auto byte = [](double c) { return static_cast<unsigned char>(std::lround(255 * c)); };
    plot->SetColor(byte(rgb[0]), byte(rgb[1]), byte(rgb[2]), byte(opacity));
    plot->SetLabel(label);
    plot->SetLegendVisibility(!label.empty());
    return plot;
}

void DiagramChart::fitPlotAspect(double aspect) {
    vtkRenderWindow* win = view_->GetRenderWindow();
    win->SetOffScreenRendering(1);
    // The borders (axes, legend) do not depend on the window's width: one correction is
    // usually enough, the passes after it only absorb rounding.
    for (int pass = 0; pass < 4; ++pass) {
        win->Render();
        const int* p1 = chart_->GetPoint1();
        const int* p2 = chart_->GetPoint2();
        const int wanted = static_cast<int>(std::lround(aspect * (p2[1] - p1[1])));
        const int change = wanted - (p2[0] - p1[0]);
        if (change == 0) return;
        const int* size = win->GetSize();
        win->SetSize(std::max(size[0] + change, 1), size[1]);
    }
    win->Render();
}

std::string DiagramChart::encode(const std::string& format, const std::string& title, double aspect) {
    if (format != ".svg" && format != ".pdf" && format != ".png")
        throw std::invalid_argument("diagram: unknown format '" + format + "' (use .svg, .pdf or .png)");
    if (format == ".svg" && !svgAnchor_) {
        // VTK 9.1's SVG exporter attaches its <defs> (clip rectangles, embedded images) only when a
        // marker symbol was drawn: without one an r-phi diagram's clip-path and a figure's image
        // pointed at nothing. One invisible marker, inside the axes, makes every SVG complete.
        vtkAxis* x = chart_->GetAxis(vtkAxis::BOTTOM);
        vtkAxis* y = chart_->GetAxis(vtkAxis::LEFT);
        const double invisible[3] = {1, 1, 1};
        svgAnchor_ = addMarkers({0.5 * (x->GetMinimum() + x->GetMaximum())},
                                {0.5 * (y->GetMinimum() + y->GetMaximum())}, invisible, 1.0f, "", vtkPlotPoints::PLUS);
        svgAnchor_->SetColor(255, 255, 255, 0);
    }
    fitPlotAspect(aspect);
    vtkRenderWindow* win = view_->GetRenderWindow();
    return format == ".png" ? encodePng(win) : encodeVector(win, format, title);
}

std::vector<ObservedImage> observedImages(const Scene& scene, const godel::ObserverView& view,
                                          const SphereObject& sphere, int maxWinding) {
    std::vector<ObservedImage> out;
    // Moving centres: Image::event is already in the observer's chart.
    if (sphere.motion.moving()) {
        for (const auto& mi : imagesOfMovingCentre(scene, sphere, maxWinding))
            out.push_back({mi.image, mi.image.event});
        return out;
    }
    for (const auto& im : view.images(sphere.centre.tail<3>(), maxWinding).images)
        out.push_back({im, view.event(im.event)});
    return out;
}

float imagePathWidth(int winding) { return std::max(1.5f, 7.0f - 2.0f * static_cast<float>(winding)); }

std::string imageLabel(const std::string& object, const godel::Image& image) {
    char label[160];
    std::snprintf(label, sizeof label, "image of '%s': winding %d, %s, emitted t = %.3f", object.c_str(), image.winding,
                  godel::branchName(image.branch).c_str(), image.emissionTime);
    return label;
}

}  // namespace lc::views
