// SPDX-License-Identifier: BSD-3-Clause
// Metrics typed as text against the same metrics compiled from C++ (docs/METRICS.md): the time
// to prepare a formula (read, parse, differentiate, build the tape), the cost of one evaluation
// of Hamilton's equations, and whole camera rays traced through both, with how far their final
// directions differ. One thread; the machine is named in the output.
#include "bench_common.hpp"
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/scene/observer_ray.hpp"
#include "core/spacetime/integrator.hpp"
#include "readers/io/metric_file.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

using namespace lc;

namespace {

std::vector<Vec4> strongFieldPoints() {
    std::vector<Vec4> points;
    for (int i = 0; i < 256; ++i) {
        const double r = 3 + 27.0 * i / 255, th = 0.1 + 2.9 * ((i * 37) % 256) / 255.0, ph = 0.7 * i;
        points.emplace_back(0.0, r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th));
    }
    return points;
}

// Camera rays from an observer at rest at `eye` looking at the origin over a 40 x 20 degree field.
struct RayRun {
    double seconds = 0;
    std::vector<Vec4> ends;
    std::vector<StopReason> reasons;
};
RayRun traceRays(const Spacetime& st, const Vec4& eye, int n, double tolerance) {
    TraceOptions opt;
    opt.stepper = StepperKind::Dopri5;
    opt.absTol = opt.relTol = tolerance;
    opt.escapeRadius = escapeRadiusForRayFrom(eye);
    RayRun run;
    run.seconds = bench::seconds([&] {
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n / 2; ++j) {
                const double ax = (i + 0.5) / n - 0.5, ay = (j + 0.5) / (n / 2) - 0.5;
                const Vec3 dir = (-eye.tail<3>().normalized() + Vec3(0, 0.7 * ax, 0.35 * ay)).normalized();
                const PhasePoint start = staticObserverRay(st, eye, dir, false);
                const TraceResult r = traceGeodesic(st, start, opt);
                run.ends.push_back(r.end.p);
                run.reasons.push_back(r.reason);
            }
    });
    return run;
}

// Largest angle between the final spatial momenta of escaped rays in both runs.
double worstDirectionDifference(const RayRun& a, const RayRun& b, int& compared, int& differentStops) {
    double worst = 0;
    compared = differentStops = 0;
    for (std::size_t i = 0; i < a.ends.size(); ++i) {
        if (a.reasons[i] != b.reasons[i]) {
            ++differentStops;
            continue;
        }
        if (a.reasons[i] != StopReason::Escaped) continue;
        const Vec3 u = a.ends[i].tail<3>().normalized(), v = b.ends[i].tail<3>().normalized();
        worst = std::max(worst, (u - v).norm());
        ++compared;
    }
    return worst;
}

void compare(const char* label, const Spacetime& builtin, const std::string& file,
             const std::map<std::string, double>& values, const Vec4& eye) {
    std::vector<double> prepare;
    std::shared_ptr<const formula::FormulaMetric> formula;
    for (int i = 0; i < 21; ++i)
        prepare.push_back(bench::seconds([&] { formula = io::loadFormulaMetric(file, values); }));
    std::nth_element(prepare.begin(), prepare.begin() + 10, prepare.end());
    const auto points = strongFieldPoints();
    const Vec4 p(1.0, 0.3, -0.4, 0.2);
    const double flowBuiltin = bench::nsPerCall(
        points, [&](const Vec4& x) { return builtin.flow(x, p).dpdl(1); }, 0.3);
    const double flowFormula = bench::nsPerCall(
        points, [&](const Vec4& x) { return formula->flow(x, p).dpdl(1); }, 0.3);
    for (double tolerance : {1e-8, 1e-10}) {
        const RayRun a = traceRays(builtin, eye, 40, tolerance), b = traceRays(*formula, eye, 40, tolerance);
        int compared = 0, differentStops = 0;
        const double worst = worstDirectionDifference(a, b, compared, differentStops);
        const double rays = static_cast<double>(a.ends.size());
        std::printf(
            "| %s | %.0e | %.2f | %zu | %.0f | %.0f | %.2f | %.1f | %.1f | %.2f | %.1e (%d rays, %d stop apart) |\n",
            label, tolerance, 1e3 * prepare[10], formula->tapeInstructions(), flowBuiltin, flowFormula,
            flowFormula / flowBuiltin, 1e6 * a.seconds / rays, 1e6 * b.seconds / rays, b.seconds / a.seconds, worst,
            compared, differentStops);
    }
}

}  // namespace

int main() {
    std::printf(
        "# Formula metrics against the built-in C++ metrics\n\nMachine: %s, one thread. Camera rays: 40 x 20 "
        "from a static observer, dopri5. Direction difference: |unit final momentum (formula) - (built-in)| "
        "over rays that escape in both.\n\n",
        bench::machineName().c_str());
    std::printf(
        "| metric | tolerance | prepare ms | tape | flow ns built-in | flow ns formula | ratio | us/ray "
        "built-in | us/ray formula | ratio | direction difference |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    const std::string dir = LIGHTCONE_SOURCE_DIR "/data/metrics/";
    compare("Kerr a = 0.9", KerrNewman(1, 0.9, 0), dir + "kerr.json", {{"M", 1}, {"a", 0.9}}, Vec4(0, 30, 0, 3));
    compare("Schwarzschild", Schwarzschild(1), dir + "schwarzschild.json", {{"M", 1}}, Vec4(0, 30, 0, 3));
    compare("Alcubierre v = 0.5", Alcubierre(0.5, 1, 35), dir + "alcubierre.json",
            {{"v", 0.5}, {"R", 1}, {"sigma", 35}}, Vec4(0, 0, 0, 0));
    return 0;
}
