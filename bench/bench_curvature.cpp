// SPDX-License-Identifier: BSD-3-Clause
// The curvature volume of issue #44: Kerr (a = 0.9) Kretschmann on a 128^3 box on every core,
// beside the cost of one jet (g, dg, ddg from the tape), the curvature from it and the metric
// evaluation alone; and the error against the closed form (Henry 2000) on the grid.
#include "bench_common.hpp"
#include "core/curvature/curvature_field.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "tests/common/curvature_oracles.hpp"

#include <omp.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace lc;

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
}
