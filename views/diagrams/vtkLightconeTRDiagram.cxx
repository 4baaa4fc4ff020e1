// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeTRDiagram.h"

#include "core/godel/proper_time_world_line.hpp"
#include "core/metrics/godel.hpp"
#include "core/render/photo_scene.hpp"
#include "diagram_chart.hpp"

#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkObjectFactory.h>
#include <vtkPen.h>
#include <vtkPlotPoints.h>

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkLightconeTRDiagram);

namespace {
const double kGrey[3] = {0.75, 0.75, 0.75};
const double kRed[3] = {0.8, 0.1, 0.1};
const double kBlack[3] = {0.1, 0.1, 0.1};
const double kCtcPink[3] = {0.95, 0.75, 0.80};
constexpr int kSamplesPerWinding = 200;
}  // namespace

vtkLightconeTRDiagram::vtkLightconeTRDiagram() = default;
vtkLightconeTRDiagram::~vtkLightconeTRDiagram() = default;

void vtkLightconeTRDiagram::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "EmissionEvents: " << this->EmissionEvents << "\n";
}

void vtkLightconeTRDiagram::Curve::add(const lc::Vec4& event, double tObserver) {
    r.push_back(std::hypot(event(1), event(2)));
    t.push_back(event(0) + tObserver);
}

// r and t do not depend on the ray's azimuth: one ray per elevation, from the plane z = 0
// (reaches the horizon) towards the axis (r stays near 0, t falls as fast as the affine length
// grows). Each ends on its (Windings + 1)-th return to the axis, after every image of the
// windings drawn (winding n: omega lambda in [n pi, (n + 1) pi], core/godel/images.hpp).
std::vector<vtkLightconeTRDiagram::Curve> vtkLightconeTRDiagram::LightCone(double a) const {
    const int samples = kSamplesPerWinding * (this->Windings + 1);
    std::vector<Curve> cone;
    for (int k = 1; k <= this->FanRays; ++k) {
        const auto ray = lc::godel::OriginGeodesic::null(a, lc::kPi / 2 * k / this->FanRays, 0, -1);
        const double length = (this->Windings + 1) * lc::kPi / ray.omega();
        Curve c;
        for (int s = 0; s <= samples; ++s) c.add(ray.cartesian(length * s / samples), this->Scene.observer(0));
        cone.push_back(c);
    }
    return cone;
}

// Static spheres keep their distance from the observer (isometries commute with time
// translation); moving ones follow the world line their images are solved on.
vtkLightconeTRDiagram::Curve vtkLightconeTRDiagram::WorldLine(const lc::SphereObject& sphere,
                                                              const lc::godel::ObserverView& view, double t0, double t1,
                                                              int maxSamples) const {
    const double tObserver = this->Scene.observer(0);
    Curve c;
    if (!sphere.motion.moving()) {
        const lc::Vec4 centre = view.event(lc::Vec4(tObserver, sphere.centre(1), sphere.centre(2), sphere.centre(3)));
        for (double t : {t0, t1}) c.add(lc::Vec4(t - tObserver, centre(1), centre(2), centre(3)), tObserver);
        return c;
    }
    const lc::MovingCentre moving = lc::movingCentre(this->Scene, sphere, this->Windings);
    int samples = sphere.motion.kind == lc::Motion::Kind::ProperTime ? 2000 : kSamplesPerWinding * (this->Windings + 1);
    if (maxSamples > 0) samples = std::min(samples, maxSamples);
    for (int s = 0; s <= samples; ++s) {
        const double tau = moving.window.tauMin + (moving.window.tauMax - moving.window.tauMin) * s / samples;
        c.add(moving.line.position(tau), tObserver);
    }
    return c;
}

void vtkLightconeTRDiagram::Draw(lc::views::DiagramChart& chart, double a, const lc::godel::ObserverView& view) {
    this->EmissionEvents = 0;
    const double tObserver = this->Scene.observer(0);
    chart.chart()->SetTitle("Goedel universe, t-r diagram of the observer (a = " + std::to_string(a).substr(0, 4) +
                            ")");

    // Everything but the world lines sets the time range (a free fall's world line runs on
    // long before its first image).
    const std::vector<Curve> cone = this->LightCone(a);
    double tMin = tObserver - (cone.empty() ? lc::godelAffineLengthForWindings(a, this->Windings) : 0.0);
    for (const auto& c : cone) tMin = std::min(tMin, *std::min_element(c.t.begin(), c.t.end()));
    double rMax = 2.5 * a;
    std::vector<std::vector<lc::views::ObservedImage>> images;
    for (std::size_t i = 0; i < this->Scene.spheres.size(); ++i) {
        const lc::SphereObject& s = this->Scene.spheres[i];
        images.push_back(this->DrawnOneByOne(i) ? lc::views::observedImages(this->Scene, view, s, this->Windings)
                                                : std::vector<lc::views::ObservedImage>{});
        for (const auto& seen : images.back()) tMin = std::min(tMin, seen.emission(0) + tObserver);
        if (!s.motion.moving()) rMax = std::max(rMax, 1.1 * this->WorldLine(s, view, 0, 0).r.front());
    }
    // A traveller's whole trip is shown: into the closed-timelike band and back, earlier in t.
    double tMax = tObserver;
    for (const auto& s : this->Scene.spheres)
        if (s.motion.kind == lc::Motion::Kind::ProperTime)
            for (const lc::Vec4& e : s.motion.properTimeLine->sampled(400)) {
                const lc::Vec4 o = view.event(e);
                tMin = std::min(tMin, o(0) + tObserver);
                tMax = std::max(tMax, o(0) + tObserver);
                rMax = std::max(rMax, 1.1 * std::hypot(o(1), o(2)));
            }
    const double margin = 0.04 * (tMax - tMin);
    const double t0 = tMin - margin, t1 = tMax + margin;
    chart.setAxis(vtkAxis::BOTTOM, 0, rMax, "r (observer's chart: distance from the observer's axis)");
    chart.setAxis(vtkAxis::LEFT, t0, t1, "t (coordinate time)");

    // Beyond the horizon the circles of constant t, r are closed timelike curves (g_phiphi > 0).
    chart.addBand(2 * a, rMax, t0, t1, kCtcPink, 0.45, "closed timelike circles (r > 2a)");
    for (std::size_t k = 0; k < cone.size(); ++k)
        chart.addCurve(cone[k].r, cone[k].t, kGrey, 1.0f,
                       k == 0 ? "observer's past light cone (one ray per elevation)" : "", vtkPen::SOLID_LINE);
    chart.addCurve({2 * a, 2 * a}, {t0, t1}, kRed, 2.0f, "Goedel horizon r = 2a", vtkPen::DASH_LINE);
    chart.addMarkers({0.0}, {tObserver}, kRed, 10.0f, "observation event (r = 0)", vtkPlotPoints::CIRCLE);

    std::vector<std::vector<double>> summaryR, summaryT;  // crowded scenes: the other world lines together
    for (std::size_t i = 0; i < this->Scene.spheres.size(); ++i) {
        const lc::SphereObject& s = this->Scene.spheres[i];
        if (!this->DrawnOneByOne(i)) {
            Curve line = this->WorldLine(s, view, t0, t1, 16);
            summaryR.push_back(std::move(line.r));
            summaryT.push_back(std::move(line.t));
            continue;
        }
        const Curve line = this->WorldLine(s, view, t0, t1);
        chart.addCurve(line.r, line.t, kBlack, 2.0f, "world line of '" + s.name + "'", vtkPen::SOLID_LINE);
        Curve events;
        for (const auto& seen : images[i]) {
            const auto ray = seen.image.ray(a);
            Curve path;
            const int n = 400;
            for (int k = 0; k <= n; ++k) path.add(ray.cartesian(seen.image.lambda * k / n), tObserver);
            this->AddImagePath(chart, path.r, path.t, static_cast<int>(i), seen.image);
            events.add(seen.emission, tObserver);
        }
        if (events.r.empty()) continue;
        chart.addMarkers(events.r, events.t, kBlack, 9.0f, "emission events of '" + s.name + "'",
                         vtkPlotPoints::DIAMOND);
        this->EmissionEvents += static_cast<int>(events.r.size());
    }
    this->AddSummarisedObjects(chart, summaryR, summaryT, "world lines");
}
