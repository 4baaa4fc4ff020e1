// SPDX-License-Identifier: BSD-3-Clause
#include "core/analysis/disk_observables.hpp"

#include "core/accretion/thin_disk.hpp"
#include "core/render/post_render.hpp"

#include <cmath>
#include <limits>

namespace lc {
namespace {

constexpr double kPlanck = 6.62607015e-34, kBoltzmann = 1.380649e-23;

// The observed bolometric intensity of a disk pixel, I = g^4 F / pi, from the stored g^4 F / F_max.
double intensityOf(const Scene& scene, const PixelRecord& px) {
    const ThinDiskModel& m = *scene.disks[static_cast<std::size_t>(px.object)].model;
    return px.intensity * m.maxFlux() / kPi;
}

bool showsDisk(const Scene& scene, const PixelRecord& px) {
    return px.kind == PixelRecord::Disk && px.object >= 0 && static_cast<std::size_t>(px.object) < scene.disks.size();
}

}  // namespace

double pixelSolidAngle(const Camera& camera, int i, int j) {
    const double deg = kPi / 180;
    if (camera.projection == Camera::Projection::Panorama) {
        const double dAz = camera.fovXDeg * deg / camera.width, dEl = camera.fovYDeg * deg / camera.height;
        const double el = (0.5 - (j + 0.5) / camera.height) * camera.fovYDeg * deg;
        return 2 * std::cos(el) * std::sin(0.5 * dEl) * dAz;  // exact over the pixel's elevation band
    }
    // Screen rectangle [x0, x1] x [y0, y1] at unit distance: Omega = sum of +-atan(x y / sqrt(1 + x^2 + y^2)).
    const Vec2 tangents = camera.halfFieldTangents();
    const double tx = tangents.x(), ty = tangents.y();
    const double x0 = (2.0 * i / camera.width - 1) * tx, x1 = (2.0 * (i + 1) / camera.width - 1) * tx;
    const double y0 = (1 - 2.0 * (j + 1) / camera.height) * ty, y1 = (1 - 2.0 * j / camera.height) * ty;
    auto corner = [](double x, double y) { return std::atan(x * y / std::sqrt(1 + x * x + y * y)); };
    return corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0);
}

DiskObservables observeDisk(const Scene& scene, const RenderResult& result) {
    DiskObservables o;
    double weightedG = 0;
    for (int j = 0; j < result.height; ++j)
        for (int i = 0; i < result.width; ++i) {
            const PixelRecord& px = result.pixels[static_cast<std::size_t>(j) * result.width + i];
            if (!showsDisk(scene, px)) continue;
            const double f = intensityOf(scene, px) * pixelSolidAngle(scene.camera, i, j);
            const std::size_t order = static_cast<std::size_t>(std::clamp<int>(px.order, 0, 3));
            o.flux += f;
            weightedG += px.frequencyRatio * f;
            ++o.pixels[order];
            o.orderFlux[order] += f;
        }
    o.meanRedshift = o.flux > 0 ? weightedG / o.flux : std::numeric_limits<double>::quiet_NaN();
    return o;
}

std::vector<SpectrumBin> diskSpectrum(const Scene& scene, const RenderResult& result, int bins) {
    std::vector<SpectrumBin> out;
    if (scene.disks.empty() || bins < 2) return out;
    const double peakT = scene.disks.front().temperature;
    const double nuPeak = kBoltzmann * peakT / kPlanck;
    for (int b = 0; b < bins; ++b)
        out.push_back({nuPeak * 0.01 * std::pow(3000.0, static_cast<double>(b) / (bins - 1)), 0.0});
    for (int j = 0; j < result.height; ++j)
        for (int i = 0; i < result.width; ++i) {
            const PixelRecord& px = result.pixels[static_cast<std::size_t>(j) * result.width + i];
            if (!showsDisk(scene, px) || !(px.frequencyRatio > 0) || !(px.intensity > 0)) continue;
            const double g = px.frequencyRatio;
            const double T = diskLocalTemperature<double>(peakT, px.intensity, g);
            // I_nu,em integrates to the emitted F / pi = I / g^4: a Planck shape of that area;
            // observed I_nu(nu) = g^3 I_nu,em(nu / g).
            const double emitted = intensityOf(scene, px) / (g * g * g * g);
            const double weight = pixelSolidAngle(scene.camera, i, j) * g * g * g * emitted * 15 / std::pow(kPi, 4) *
                                  kPlanck / (kBoltzmann * T);
            for (SpectrumBin& bin : out) {
                const double x = kPlanck * bin.frequencyHz / (g * kBoltzmann * T);
                if (x < 700) bin.fluxDensity += weight * x * x * x / std::expm1(x);
            }
        }
    return out;
}

}  // namespace lc
