// SPDX-License-Identifier: BSD-3-Clause
// Where one Kerr step's time goes: the metric, its inverse, the exact gradient (automatic
// differentiation), the right-hand side of Hamilton's equations, and one accepted dopri5 step
// of the tracer, in ns per call on one thread (issue: "profile one Kerr step").
#include "bench_common.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/spacetime/frame.hpp"
#include "core/spacetime/integrator.hpp"

#include <cstdio>
#include <vector>

using namespace lc;

namespace {

// ns per call of f over `points`, repeated until at least 0.2 s have passed.

}  // namespace

int main() {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    std::vector<Vec4> points;
    for (int i = 0; i < 256; ++i) {  // r from 3 M to 30 M, all latitudes
        const double r = 3 + 27.0 * i / 255, th = 0.1 + 2.9 * ((i * 37) % 256) / 255.0, ph = 0.7 * i;
        points.emplace_back(0.0, r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th));
    }
    const Vec4 p(1.0, 0.3, -0.4, 0.2);
    std::printf("# One Kerr (a = 0.9) step: where the time goes\n\nMachine: %s, one thread.\n\n",
                bench::machineName().c_str());
    std::printf("| part | ns per call |\n|---|---|\n");
    std::printf("| metric g | %.0f |\n", bench::nsPerCall(points, [&](const Vec4& x) { return kerr.metric(x)(1, 2); }));
    std::printf("| inverse metric | %.0f |\n",
                bench::nsPerCall(points, [&](const Vec4& x) { return kerr.inverseMetric(x)(1, 2); }));
    std::printf("| g and dg (automatic differentiation) | %.0f |\n", bench::nsPerCall(points, [&](const Vec4& x) {
                    Mat4 g;
                    std::array<Mat4, 4> dg;
                    kerr.metricAndDerivatives(x, g, dg);
                    return dg[1](1, 2);
                }));
    std::printf("| Hamilton's equations (flow) | %.0f |\n",
                bench::nsPerCall(points, [&](const Vec4& x) { return kerr.flow(x, p).dpdl(1); }));
    std::printf("| stop tests after a step (boundary, H) | %.0f |\n", bench::nsPerCall(points, [&](const Vec4& x) {
                    return kerr.hamiltonian(x, p) + static_cast<double>(kerr.boundary(x));
                }));

    // A whole ray from r = 30 M (a camera ray that reaches the strong field), per accepted step.
    TraceOptions opt;
    opt.absTol = opt.relTol = 1e-10;
    const Vec4 x0(0, 0, -30, 0);
    const LocalFrame frame = LocalFrame::staticObserver(kerr, x0);
    const PhasePoint start{x0, frame.pastNullMomentum(kerr, Vec3(0.2, 1, 0.1).normalized())};
    TraceResult r;
    const int rays = 200;
    const double s = bench::seconds([&] {
        for (int i = 0; i < rays; ++i) r = traceGeodesic(kerr, start, opt);
    });
    std::printf("| dopri5 step, tolerance 1e-10, accepted (incl. rejected tries) | %.0f |\n",
                1e9 * s / (rays * static_cast<double>(r.steps)));
    std::printf("\nThat ray: %zu accepted steps, %zu rejected, stop: %s.\n", r.steps, r.rejected,
                stopReasonName(r.reason).c_str());
    return 0;
}
