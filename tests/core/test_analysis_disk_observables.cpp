// SPDX-License-Identifier: BSD-3-Clause
// A disk's observed flux, mean redshift and spectrum from per-pixel data (core/analysis/
// disk_observables) against independent integrals: the pixel solid angles against the whole
// field's, and a far face-on disk against (2 / D^2) int g(r)^4 F(r) r dr with BPT's g of a ring seen
// from the axis (light bending and the b(r) mapping are O(M / r) = 0.1 % there).
#include "core/accretion/thin_disk.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/analysis/disk_observables.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace lc;

namespace {

TEST(DiskObservables, PixelSolidAnglesAddUpToTheField) {
    Camera pinhole;
    pinhole.width = 40;
    pinhole.height = 30;
    pinhole.fovXDeg = 70;
    pinhole.fovYDeg = 50;
    double sum = 0;
    for (int j = 0; j < 30; ++j)
        for (int i = 0; i < 40; ++i) sum += pixelSolidAngle(pinhole, i, j);
    const double tx = std::tan(35 * kPi / 180), ty = std::tan(25 * kPi / 180);
    EXPECT_NEAR(sum, 4 * std::atan(tx * ty / std::sqrt(1 + tx * tx + ty * ty)), 1e-12);
    Camera sphere;
    sphere.projection = Camera::Projection::Panorama;
    sphere.width = 36;
    sphere.height = 17;
    sphere.fovXDeg = 360;
    sphere.fovYDeg = 180;
    sum = 0;
    for (int j = 0; j < 17; ++j)
        for (int i = 0; i < 36; ++i) sum += pixelSolidAngle(sphere, i, j);
    EXPECT_NEAR(sum, 4 * kPi, 1e-12);
}

struct FarFaceOn {
    Scene scene;
    RenderResult result;
};

FarFaceOn farFaceOnDisk(double a) {
    FarFaceOn f;
    Scene& s = f.scene;
    const double D = 1e7;
    s.spacetime = std::make_shared<KerrNewman>(1.0, a, 0.0);
    s.observer = Vec4(0, 0, 0, D);
    s.camera.width = s.camera.height = 301;
    s.camera.fovXDeg = s.camera.fovYDeg = 2 * std::atan(2050 / D) * 180 / kPi;
    s.camera.forward = Vec3(0, 0, -1);
    s.camera.up = Vec3(1, 0, 0);
    DiskObject d;
    d.model = std::make_shared<ThinDiskModel>(s.spacetime, 1000, 2000, true);
    d.temperature = 6000;
    s.disks.push_back(d);
    s.settings.trace.relTol = s.settings.trace.absTol = 1e-9;
    s.settings.progress = false;
    f.result = render(s);
    return f;
}

TEST(DiskObservables, FarFaceOnFluxIsTheIntegralOverTheDisk) {
    const double a = 0.7, D = 1e7;
    const FarFaceOn f = farFaceOnDisk(a);
    const ThinDiskModel& m = *f.scene.disks[0].model;
    const double gttObserver = 1 - 2 * D / (D * D + a * a);
    auto g = [&](double r) {
        const double r32 = std::pow(r, 1.5);
        return std::sqrt(1 - 3 / r + 2 * a / r32) / (1 + a / r32) / std::sqrt(gttObserver);
    };
    const double expected = 2 / (D * D) *
                            boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                                [&](double r) { return std::pow(g(r), 4) * m.flux(r) * r; }, 1000, 2000, 8);
    const DiskObservables o = observeDisk(f.scene, f.result);
    EXPECT_NEAR(o.flux, expected, 0.01 * expected);  // pixel edges of the rings: 0.3 % at 301 x 301
    EXPECT_EQ(o.pixels[1] + o.pixels[2] + o.pixels[3], 0u);
    // Flux-weighted g: the same integral with one more g.
    const double weighted = 2 / (D * D) *
                            boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                                [&](double r) { return std::pow(g(r), 5) * m.flux(r) * r; }, 1000, 2000, 8);
    EXPECT_NEAR(o.meanRedshift, weighted / expected, 2e-5);

    // The spectrum integrates to the bolometric flux (bins 0.01 to 30 k T_peak / h hold it all).
    const std::vector<SpectrumBin> spectrum = diskSpectrum(f.scene, f.result, 200);
    double integral = 0;
    for (std::size_t k = 1; k < spectrum.size(); ++k)
        integral += 0.5 * (spectrum[k].fluxDensity + spectrum[k - 1].fluxDensity) *
                    (spectrum[k].frequencyHz - spectrum[k - 1].frequencyHz);
    EXPECT_NEAR(integral, o.flux, 0.01 * o.flux);
}

TEST(DiskObservables, NoDiskMeansNoFluxAndAnUndefinedRedshift) {
    Scene s;
    s.spacetime = std::make_shared<KerrNewman>(1.0, 0.0, 0.0);
    RenderResult r;
    r.width = r.height = 2;
    r.pixels.resize(4);
    const DiskObservables o = observeDisk(s, r);
    EXPECT_EQ(o.flux, 0);
    EXPECT_TRUE(std::isnan(o.meanRedshift));
    EXPECT_TRUE(diskSpectrum(s, r).empty());
}

}  // namespace
