// SPDX-License-Identifier: BSD-3-Clause
// The curvature volume of issue #44: Kerr (a = 0.9) Kretschmann on a 128^3 box on every core,
// beside the cost of one jet (g, dg, ddg from the tape), the curvature from it and the metric
// evaluation alone; and the error against the closed form (Henry 2000) on the grid. Then the
// magnification per pixel (ray bundles): a Kerr render's time with and without them, and the
// point lens's worst magnification error against the weak-field formula, by tolerance.
#include "bench_common.hpp"
#include "core/curvature/curvature_field.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/render/render.hpp"
#include "core/scene/frame_camera.hpp"
#include "tests/common/curvature_oracles.hpp"

#include <omp.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace lc;

namespace {

Scene benchScene(SpacetimePtr st, const Vec4& observer, const Vec3& forward, double fovDeg, int width,
                 double tolerance) {
    Scene s;
    s.spacetime = std::move(st);
    s.observer = observer;
    s.camera.width = width;
    s.camera.height = width / 2;
    s.camera.fovXDeg = fovDeg;
    s.camera.fovYDeg = fovDeg / 2;
    s.camera.forward = forward;
    s.camera.up = Vec3(0, 0, 1);
    s.settings.method = RenderSettings::Method::Numeric;
    s.settings.progress = false;
    s.settings.trace.absTol = s.settings.trace.relTol = tolerance;
    return s;
}

// data/kerr.json's view (a = 0.9 from 30 M, 60 degrees wide) at 160 x 80, with and without
// bundles; the Schwarzschild point lens from 1e10 M (sky pixels 0.3 to 3.3 Einstein radii from
// it, clear of the ring) against mu = 1/(1 - (theta_E/theta)^4).
void magnificationTable() {
    std::printf(
        "\n| tolerance | Kerr render, s | with bundles, s | ratio | point lens: worst mu error, outer / inner "
        "image |\n|---|---|---|---|---|\n");
    for (double tol : {1e-6, 1e-8, 1e-10}) {
        Scene kerr =
            benchScene(std::make_shared<KerrNewman>(1.0, 0.9, 0.0), Vec4(0, 30, 0, 0), Vec3(-1, 0, 0), 60, 160, tol);
        const double plain = render(kerr).stats.seconds;
        kerr.settings.magnification = true;
        const double bundles = render(kerr).stats.seconds;
        const double D = 1e10, thetaE = std::sqrt(4 / D);
        Scene lens = benchScene(std::make_shared<Schwarzschild>(1.0), Vec4(0, -D, 0, 0),
                                Vec3(1, 0.9 * thetaE, -0.6 * thetaE), 8 * thetaE * 180 / kPi, 80, tol);
        lens.settings.magnification = true;
        const RenderResult r = render(lens);
        const Camera cam = frameCamera(lens);
        double outer = 0, inner = 0;
        for (int j = 0; j < cam.height; ++j)
            for (int i = 0; i < cam.width; ++i) {
                const Vec3 n = cam.direction(i, j);
                const double x = thetaE / std::atan2(n.cross(Vec3::UnitX()).norm(), n(0));
                if ((x > 1 / 1.3 && x < 1.6) || x > 3.3) continue;
                const double e = std::abs(
                    r.pixels[static_cast<std::size_t>(j * cam.width + i)].magnification * (1 - std::pow(x, 4)) - 1);
                (x > 1 ? inner : outer) = std::max(x > 1 ? inner : outer, e);
            }
        std::printf("| %.0e | %.2f | %.2f | %.1f | %.1e / %.1e |\n", tol, plain, bundles, bundles / plain, outer,
                    inner);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const int n = argc > 1 ? std::atoi(argv[1]) : 128;
    const double a = 0.9;
    const KerrNewman kerr(1.0, a, 0.0);
    const CurvatureProbe probe(kerr);
    std::vector<Vec4> points;
    for (int i = 0; i < 256; ++i) {
        const double r = 1.5 + 28.5 * i / 255, th = 0.1 + 2.9 * ((i * 37) % 256) / 255.0, ph = 0.7 * i;
        points.emplace_back(0.0, r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th));
    }
    std::printf("# Curvature of Kerr (a = 0.9)\n\nMachine: %s, %d threads for the volume, one for the rest.\n\n",
                bench::machineName().c_str(), omp_get_max_threads());
    std::printf("| part | ns per event (one thread) |\n|---|---|\n");
    std::printf("| metric g alone | %.0f |\n",
                bench::nsPerCall(points, [&](const Vec4& x) { return kerr.metric(x)(1, 2); }));
    std::printf("| g and dg (automatic differentiation, the tracer's) | %.0f |\n",
                bench::nsPerCall(points, [&](const Vec4& x) {
                    Mat4 g;
                    std::array<Mat4, 4> dg;
                    kerr.metricAndDerivatives(x, g, dg);
                    return dg[1](1, 2);
                }));
    std::printf("| jet: g, dg, ddg from the tape (%zu instructions) | %.0f |\n", probe.tapeInstructions(),
                bench::nsPerCall(points, [&](const Vec4& x) { return probe.jet(x).ddg[1][2](0, 3); }));
    std::printf("| jet and all curvature (Riemann, Ricci, Weyl, invariants) | %.0f |\n",
                bench::nsPerCall(points, [&](const Vec4& x) { return probe.at(x).kretschmann; }));

    ChartGrid grid;
    grid.dimensions = {n, n, n};
    grid.origin = Vec3(-10, -10, -10);
    grid.spacing = Vec3::Constant(20.0 / (n - 1));
    CurvatureField field;
    const double s = bench::seconds([&] {
        field = sampleCurvatureField(kerr, grid, {CurvatureQuantity::Kretschmann}, {}, [](double) { return true; });
    });
    double worst = 0;
    for (std::size_t i = 0; i < grid.points(); ++i) {
        const double K = field.values[0][i];
        if (!std::isfinite(K)) continue;
        const Vec3 p =
            grid.origin + grid.spacing.cwiseProduct(Vec3(static_cast<double>(i % n), static_cast<double>((i / n) % n),
                                                         static_cast<double>(i / (n * n))));
        const double r = kerrSchildRadius(p(0), p(1), p(2), a);
        const double exact = test::kerrNewmanKretschmann(1.0, a, 0.0, r, p(2) / r);
        if (std::abs(exact) > 1e-12) worst = std::max(worst, std::abs(K - exact) / std::abs(exact));
    }
    std::printf(
        "\n| volume | points | seconds | us per point | singular points | worst relative error vs closed form |\n"
        "|---|---|---|---|---|---|\n| Kretschmann %d^3, box [-10, 10]^3 M | %zu | %.2f | %.2f | %zu | %.1e |\n",
        n, grid.points(), s, 1e6 * s / static_cast<double>(grid.points()), field.singularPoints, worst);
    magnificationTable();
}
