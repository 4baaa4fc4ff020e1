// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a telescope measures of an accretion disk, from a render's per-pixel data (no tracing):
// the observed bolometric flux F_obs = sum I dOmega with I = g^4 F(r) / pi (Mdot = M = 1, as
// GYOTO's Page-Thorne quantity), its flux-weighted mean redshift, and the spectrum
// F_nu = sum g^3 I_nu,em(nu / g) dOmega of the Page-Thorne black bodies (docs/PHYSICS.md section 12).
#include "core/render/render.hpp"

#include <array>
#include <vector>

namespace lc {

// The solid angle (sr) of pixel (i, j): exact for the pinhole (the area of its screen rectangle
// seen from the eye) and the panorama (cos(elevation) d azimuth d elevation).
double pixelSolidAngle(const Camera& camera, int i, int j);

struct DiskObservables {
    double flux = 0;          // sum of I dOmega, units of Mdot / M^2 (G = c = 1)
    double meanRedshift = 0;  // sum g I dOmega / flux; NaN when no pixel shows the disk
    // Pixels and flux by image order: 0 direct, 1 secondary, 2 tertiary, 3 higher.
    std::array<std::size_t, 4> pixels{};
    std::array<double, 4> orderFlux{};
    // The share of the flux in secondary and higher images (0 without flux).
    double higherOrderFraction() const { return flux > 0 ? (flux - orderFlux[0]) / flux : 0.0; }
};
DiskObservables observeDisk(const Scene& scene, const RenderResult& result);

struct SpectrumBin {
    double frequencyHz = 0;
    double fluxDensity = 0;  // F_nu, units of Mdot / M^2 per Hz
};
// The observed spectrum at `bins` frequencies spaced evenly in log nu, from 0.01 to 30 k T_peak / h
// (T_peak: the disk's hottest local temperature, its `temperature`).
std::vector<SpectrumBin> diskSpectrum(const Scene& scene, const RenderResult& result, int bins = 80);

}  // namespace lc
