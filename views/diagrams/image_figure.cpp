// SPDX-License-Identifier: BSD-3-Clause
#include "image_figure.hpp"

#include "diagram_chart.hpp"
#include "vtkLightconeImagePlot.h"

#include "core/render/render.hpp"
#include "readers/io/image_io.hpp"

#include <vtkAxis.h>
#include <vtkChartHistogram2D.h>
#include <vtkChartLegend.h>
#include <vtkColorLegend.h>
#include <vtkColorTransferFunction.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace lc::views {
namespace {

std::string shortNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

// The scalar a pixel shows, NaN where it has none (background, horizon, a failed ray).
double pixelValue(const PixelRecord& p, FigureQuantity quantity) {
    const bool emitter = p.kind == PixelRecord::Object || p.kind == PixelRecord::Disk;
    if (quantity == FigureQuantity::Redshift)
        return emitter || p.kind == PixelRecord::Sky ? double(p.frequencyRatio)
                                                     : std::numeric_limits<double>::quiet_NaN();
    return emitter ? double(p.emissionTime) : std::numeric_limits<double>::quiet_NaN();
}

// Redshift: red below g = 1, white at 1, blue above (diverging); emission time: a viridis ramp.
vtkSmartPointer<vtkColorTransferFunction> colourMap(FigureQuantity quantity, double lo, double hi) {
    auto map = vtkSmartPointer<vtkColorTransferFunction>::New();
    if (quantity == FigureQuantity::Redshift) {
        map->AddRGBPoint(lo, 0.70, 0.02, 0.15);
        map->AddRGBPoint(1.0, 0.97, 0.97, 0.97);
        map->AddRGBPoint(hi, 0.02, 0.19, 0.58);
    } else {
        const double ramp[5][3] = {{0.267, 0.005, 0.329},
                                   {0.231, 0.322, 0.545},
                                   {0.129, 0.569, 0.549},
                                   {0.369, 0.788, 0.384},
                                   {0.993, 0.906, 0.144}};
        for (int k = 0; k < 5; ++k) map->AddRGBPoint(lo + (hi - lo) * k / 4.0, ramp[k][0], ramp[k][1], ramp[k][2]);
    }
    return map;
}

}  // namespace

std::optional<FigureQuantity> figureQuantityNamed(const std::string& name) {
    if (name == "image") return FigureQuantity::Image;
    if (name == "redshift") return FigureQuantity::Redshift;
    if (name == "emission-time") return FigureQuantity::EmissionTime;
    return std::nullopt;
}

std::string figureQuantityName(FigureQuantity quantity) {
    switch (quantity) {
        case FigureQuantity::Redshift: return "redshift";
        case FigureQuantity::EmissionTime: return "emission-time";
        default: return "image";
    }
}

Vec2 figurePoint(const Camera& camera, double x, double y) {
    const Eigen::Vector2d s = screenCoordinates(x, y, double(camera.width), double(camera.height));
    if (camera.projection == Camera::Projection::Pinhole) {
        const Vec2 t = camera.halfFieldTangents();
        return Vec2(s.x() * t.x(), s.y() * t.y());
    }
    return Vec2(s.x() * 0.5 * camera.fovXDeg, s.y() * 0.5 * camera.fovYDeg);
}

double figureAngleDegrees(const Camera& camera, double c) {
    return camera.projection == Camera::Projection::Pinhole ? std::atan(c) * 180 / kPi : c;
}

FigureTicks figureTicks(const Camera& camera, int axis) {
    const double half = 0.5 * (axis == 0 ? camera.fovXDeg : camera.fovYDeg);
    double step = 90;
    for (double candidate : {1.0, 2.0, 5.0, 10.0, 15.0, 30.0, 45.0, 90.0})
        if (2 * half / candidate <= 8) {
            step = candidate;
            break;
        }
    FigureTicks ticks;
    for (double k = std::ceil(-half / step); k * step <= half + 1e-9; ++k) {
        const double angle = k * step;
        ticks.positions.push_back(camera.projection == Camera::Projection::Pinhole ? std::tan(angle * kPi / 180)
                                                                                   : angle);
        ticks.labels.push_back(shortNumber(angle == 0 ? 0.0 : angle));
    }
    return ticks;
}

std::string figureCaption(const Scene& scene, FigureQuantity quantity) {
    std::string text = "metric '" + scene.spacetime->name() + "'";
    std::string params;
    for (const auto& [key, value] : scene.spacetime->parameters())
        params += (params.empty() ? "" : ", ") + key + " = " + shortNumber(value);
    if (!params.empty()) text += " (" + params + ")";
    const Vec4& o = scene.observer;
    text += "; observer at (t, x, y, z) = (" + shortNumber(o(0)) + ", " + shortNumber(o(1)) + ", " + shortNumber(o(2)) +
            ", " + shortNumber(o(3)) + ")";
    if (scene.observerVelocity.tail<3>().norm() > 0) {
        const Vec4& u = scene.observerVelocity;
        text += " moving with u = (" + shortNumber(u(0)) + ", " + shortNumber(u(1)) + ", " + shortNumber(u(2)) + ", " +
                shortNumber(u(3)) + ")";
    } else {
        text += ", static";
    }
    const Camera& c = scene.camera;
    text += "\n" + std::string(c.projection == Camera::Projection::Pinhole ? "pinhole" : "panorama") + " " +
            shortNumber(c.fovXDeg) + " x " + shortNumber(c.fovYDeg) + " deg, " + std::to_string(c.width) + " x " +
            std::to_string(c.height) + " px; " + renderMethodName(resolveMethod(scene)) + ", tolerance " +
            shortNumber(scene.settings.trace.relTol);
    if (scene.spacetime->godelRadius()) text += ", windings " + std::to_string(scene.settings.windings);
    if (quantity == FigureQuantity::Redshift) text += "; colours: g = nu_observed / nu_emitted";
    if (quantity == FigureQuantity::EmissionTime) text += "; colours: coordinate time of emission";
    return text;
}

ImageFigure::ImageFigure(const Scene& scene, const ColouredImage& image, FigureQuantity quantity, int height)
    : scaleMin_(std::numeric_limits<double>::quiet_NaN()), scaleMax_(std::numeric_limits<double>::quiet_NaN()) {
    const Camera& cam = scene.camera;
    const RenderResult& r = image.records;
    if (r.width != cam.width || r.height != cam.height || image.rgb.size() != 3u * cam.width * cam.height)
        throw std::invalid_argument("figure: the image is " + std::to_string(r.width) + " x " +
                                    std::to_string(r.height) + " px, the scene's camera " + std::to_string(cam.width) +
                                    " x " + std::to_string(cam.height));
    auto chart = vtkSmartPointer<vtkChartHistogram2D>::New();  // its legend is a colour bar
    chart_ = std::make_unique<DiagramChart>(height, chart);
    aspect_ = double(cam.width) / cam.height;

    // The pixels' colours: the render's, or the quantity's through its colour map.
    std::vector<double> values;
    vtkSmartPointer<vtkColorTransferFunction> map;
    if (quantity != FigureQuantity::Image) {
        values.reserve(r.pixels.size());
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const PixelRecord& p : r.pixels) {
            values.push_back(pixelValue(p, quantity));
            if (std::isfinite(values.back())) {
                lo = std::min(lo, values.back());
                hi = std::max(hi, values.back());
            }
        }
        if (!(lo <= hi)) lo = hi = quantity == FigureQuantity::Redshift ? 1.0 : 0.0;  // nothing to colour
        if (quantity == FigureQuantity::Redshift) {                                   // white stays at g = 1
            lo = std::min(lo, 1 - 1e-3);
            hi = std::max(hi, 1 + 1e-3);
        } else if (hi - lo < 1e-12) {
            lo -= 0.5;
            hi += 0.5;
        }
        scaleMin_ = lo;
        scaleMax_ = hi;
        map = colourMap(quantity, lo, hi);
    }
    vtkNew<vtkImageData> pixels;
    pixels->SetDimensions(cam.width, cam.height, 1);
    pixels->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* out = static_cast<unsigned char*>(pixels->GetScalarPointer());
    auto byte = [](double c) { return static_cast<unsigned char>(std::lround(255 * std::clamp(c, 0.0, 1.0))); };
    for (int j = 0; j < cam.height; ++j)
        for (int i = 0; i < cam.width; ++i) {
            const std::size_t k = std::size_t(j) * cam.width + i;
            unsigned char* px =
                out + 3 * (std::size_t(cam.height - 1 - j) * cam.width + i);  // VTK: row 0 at the bottom
            if (quantity == FigureQuantity::Image) {
                for (int c = 0; c < 3; ++c) px[c] = byte(io::srgbEncode(image.rgb[3 * k + c]));
            } else if (std::isfinite(values[k])) {
                double rgb[3];
                map->GetColor(values[k], rgb);
                for (int c = 0; c < 3; ++c) px[c] = byte(rgb[c]);
            } else {
                px[0] = px[1] = px[2] = 80;  // no value: dark grey
            }
        }
    vtkNew<vtkLightconeImagePlot> plot;
    plot->SetImage(pixels);
    const Vec2 topLeft = figurePoint(cam, 0, 0), bottomRight = figurePoint(cam, cam.width, cam.height);
    plot->SetExtent(topLeft.x(), bottomRight.x(), bottomRight.y(), topLeft.y());
    chart->AddPlot(plot);
    const bool pinhole = cam.projection == Camera::Projection::Pinhole;
    chart_->setAxis(
        vtkAxis::BOTTOM, topLeft.x(), bottomRight.x(),
        pinhole ? "angle right of forward, in the forward-right plane (deg)" : "azimuth right of forward (deg)");
    chart_->setAxis(vtkAxis::LEFT, bottomRight.y(), topLeft.y(),
                    pinhole ? "angle above forward, in the forward-up plane (deg)" : "elevation (deg)");
    for (int axis = 0; axis < 2; ++axis) {
        const FigureTicks t = figureTicks(cam, axis);
        vtkNew<vtkDoubleArray> positions;
        vtkNew<vtkStringArray> labels;
        for (std::size_t k = 0; k < t.positions.size(); ++k) {
            positions->InsertNextValue(t.positions[k]);
            labels->InsertNextValue(t.labels[k]);
        }
        chart->GetAxis(axis == 0 ? vtkAxis::BOTTOM : vtkAxis::LEFT)->SetCustomTickPositions(positions, labels);
    }
    chart->SetTitle(figureCaption(scene, quantity));
    chart->GetTitleProperties()->SetFontSize(13);
    if (map) {
        chart->SetTransferFunction(map);
        if (auto* bar = vtkColorLegend::SafeDownCast(chart->GetLegend()))
            bar->SetTitle(quantity == FigureQuantity::Redshift ? "g" : "t emitted");
        chart->SetShowLegend(true);
    } else {
        chart->SetShowLegend(false);
    }
}

ImageFigure::~ImageFigure() = default;

std::string ImageFigure::encode(const std::string& format) {
    return chart_->encode(format, "Lightcone figure", aspect_);
}

vtkChartXY* ImageFigure::chart() const { return chart_->chart(); }

}  // namespace lc::views
