// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeRPhiDiagram.h"

#include "core/godel/proper_time_world_line.hpp"

#include "core/godel/isometry.hpp"
#include "diagram_chart.hpp"

#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkObjectFactory.h>
#include <vtkPen.h>

vtkStandardNewMacro(vtkLightconeRPhiDiagram);

vtkLightconeRPhiDiagram::vtkLightconeRPhiDiagram() = default;
vtkLightconeRPhiDiagram::~vtkLightconeRPhiDiagram() = default;

void vtkLightconeRPhiDiagram::PrintSelf(ostream& os, vtkIndent indent) { this->Superclass::PrintSelf(os, indent); }

void vtkLightconeRPhiDiagram::Draw(lc::views::DiagramChart& chart, double a, const lc::godel::ObserverView& view) {
    chart.chart()->SetTitle("Goedel universe, r-phi plane of the observer (a = " + std::to_string(a).substr(0, 4) +
                            ")");
    const double extent = 2.3 * a;
    // The observer's chart (godel::Isometry::observerToOrigin): x and y along the camera frame's
    // e1 and e2, so the diagram faces as the image does.
    chart.setAxis(vtkAxis::BOTTOM, -extent, extent, "x = r cos(phi) (along the observer's e1)");
    chart.setAxis(vtkAxis::LEFT, -extent, extent, "y = r sin(phi) (along e2)");

    // Fan of light rays in the plane z = 0 (k3 = 0): closed curves through the observer that
    // touch the horizon. One winding retraces the same curve.
    const double grey[3] = {0.75, 0.75, 0.75};
    for (int k = 0; k < this->FanRays; ++k) {
        const double phi0 = 2 * lc::kPi * k / this->FanRays;
        const auto ray = lc::godel::OriginGeodesic::null(a, lc::kPi / 2, phi0, -1);
        std::vector<double> x, y;
        for (int s = 0; s <= 200; ++s) {
            const lc::Vec4 p = ray.cartesian(2 * lc::kPi * a * s / 200);
            x.push_back(p(1));
            y.push_back(p(2));
        }
        chart.addCurve(x, y, grey, 1.0f, k == 0 ? "light rays from the observer (z = 0)" : "", vtkPen::SOLID_LINE);
    }

    // The horizon r = 2a.
    {
        std::vector<double> x, y;
        for (int s = 0; s <= 360; ++s) {
            x.push_back(2 * a * std::cos(lc::kPi * s / 180));
            y.push_back(2 * a * std::sin(lc::kPi * s / 180));
        }
        const double red[3] = {0.8, 0.1, 0.1};
        chart.addCurve(x, y, red, 2.0f, "Goedel horizon r = 2a", vtkPen::DASH_LINE);
    }

    // Objects (outline of the equatorial circle of each sphere in its own frame) and the light
    // path of every image of its centre; crowded scenes draw the other outlines together.
    std::vector<std::vector<double>> summaryX, summaryY;
    for (std::size_t i = 0; i < this->Scene.spheres.size(); ++i) {
        const lc::SphereObject& s = this->Scene.spheres[i];
        const lc::godel::Isometry fromCentre = lc::godel::Isometry::movingOriginTo(a, s.centre);
        std::vector<double> x, y;
        for (int k = 0; k <= 72; ++k) {
            const double th = 2 * lc::kPi * k / 72;
            const lc::Vec4 w = fromCentre.apply(lc::Vec4(0, s.radius * std::cos(th), s.radius * std::sin(th), 0));
            const lc::Vec4 o = view.event(w);
            x.push_back(o(1));
            y.push_back(o(2));
        }
        if (!this->DrawnOneByOne(i)) {
            summaryX.push_back(std::move(x));
            summaryY.push_back(std::move(y));
            continue;
        }
        const double black[3] = {0.1, 0.1, 0.1};
        chart.addCurve(x, y, black, 2.0f, "object '" + s.name + "'", vtkPen::SOLID_LINE);
        // A traveller's trip (world line by proper time) projected on the observer's plane.
        if (s.motion.kind == lc::Motion::Kind::ProperTime) {
            std::vector<double> tx, ty;
            for (const lc::Vec4& e : s.motion.properTimeLine->sampled(2000)) {
                const lc::Vec4 o = view.event(e);
                tx.push_back(o(1));
                ty.push_back(o(2));
            }
            const double violet[3] = {0.45, 0.1, 0.6};
            chart.addCurve(tx, ty, violet, 1.5f, "trip of '" + s.name + "' (projection)", vtkPen::DOT_LINE);
        }

        for (const auto& seen : lc::views::observedImages(this->Scene, view, s, this->Windings)) {
            const lc::godel::Image& im = seen.image;
            const auto ray = im.ray(a);
            std::vector<double> px, py;
            const int n = 400;
            for (int k = 0; k <= n; ++k) {
                const lc::Vec4 p = ray.cartesian(im.lambda * k / n);
                px.push_back(p(1));
                py.push_back(p(2));
            }
            this->AddImagePath(chart, px, py, static_cast<int>(i), im);
        }
    }
    this->AddSummarisedObjects(chart, summaryX, summaryY, "outlines");
}
