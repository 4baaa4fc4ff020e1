// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a picked pixel shows, for the linked views: one line describing its record, and (Goedel,
// static observer) the light path behind it in closed form, in the observer's chart as the r-phi
// diagram draws it.
#include "core/render/render.hpp"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace lc::gui {

// True when lightPath() can draw the scene's rays: the 'godel' metric and a static observer.
bool hasClosedFormLightPaths(const lc::Scene& scene);

// The past-directed ray from the observer through pixel (i, j), the same ray as
// lc::renderGodelClosedForm traces, sampled on [0, affine] (samples + 1 events), in the
// observer's chart (observer at the origin). Throws std::invalid_argument unless
// hasClosedFormLightPaths(scene).
std::vector<lc::Vec4> lightPath(const lc::Scene& scene, int i, int j, double affine, int samples = 400);
// The same for the ray leaving along `direction` (the camera's frame, e.g. a SelectedRay's).
std::vector<lc::Vec4> lightPathAlong(const lc::Scene& scene, const lc::Vec3& direction, double affine,
                                     int samples = 400);
// The observer's light ray in the plane z = 0 of its chart (a fan ray of the r-phi diagram) that
// passes closest to the diagram point (x, y): its direction (the camera's frame), the affine
// length at the closest point (within the first loop, 0 <= affine < 2 pi a) and the distance
// there. Of two rays through the point (inside the horizon one meets it going out, another coming
// back) the one with the smaller affine length. Same preconditions as lightPath().
struct PlanarRayHit {
    lc::Vec3 direction = lc::Vec3::UnitX();
    double phi0 = 0;  // azimuth of the direction in the observer's chart
    double affine = 0;
    double distance = 0;
};
PlanarRayHit nearestPlanarRay(const lc::Scene& scene, double x, double y);

// Why a finished render shows none of the scene's objects (empty when it shows one, or the scene
// has none): every one beyond the observer's Goedel horizon, every one inside a black hole's
// horizon, or none in the field of view.
std::string whyNoObjectIsSeen(const lc::Scene& scene, const lc::RenderResult& result);
// The pixel a viewing direction (observer frame components) falls on through the camera in that
// frame (lc::frameCamera); (-1, -1) outside the image.
std::pair<int, int> pixelOfDirection(const lc::Camera& camera, const lc::Vec3& direction);
// The observer's local axes e1, e2, e3 (the camera's frame) as vectors of the observer's chart.
std::array<lc::Vec3, 3> cameraAxes(const lc::Scene& scene);
// Observer's chart -> the scene's chart (Goedel).
lc::Vec4 observerChartToWorld(const lc::Scene& scene, const lc::Vec4& x);

// "pixel (i, j): object 'ball' | emitted at t = ... | affine depth ... | nu_obs/nu_em = ..."
std::string describePixel(const lc::Scene& scene, const lc::PixelRecord& p, int i, int j);

}  // namespace lc::gui
