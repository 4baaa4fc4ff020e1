// SPDX-License-Identifier: BSD-3-Clause
// Speed against error of the generic Hamiltonian tracer, per stepper and tolerance:
//  - Schwarzschild deflection at b = 10 against the exact value (docs/PHYSICS.md section 7);
//  - Goedel null rays over three windings against the closed form (docs/PHYSICS.md section 2).
// Prints markdown tables; times are wall clock for a batch of rays, 1 and 2 threads.
#include "bench_common.hpp"
#include "core/spacetime/frame.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/spacetime/scattering.hpp"

#include <omp.h>

#include <cstdio>
#include <vector>

using namespace lc;

namespace {

Vec4 godelClosedForm(double psi, double phi0, double l) {  // a = 1, past-directed, signed radius
    const double k3 = std::cos(psi), w = std::sqrt(1 + k3 * k3) / 2;
    const double Phi = std::atan(std::sqrt(2 / (1 + k3 * k3)) * std::tan(w * l)) + kPi * std::floor(w * l / kPi + 0.5);
    const double r = 2 * std::sin(psi) / std::sqrt(1 + k3 * k3) * std::sin(w * l), phi = phi0 - Phi;
    return Vec4(-(2 * kSqrt2 * Phi - l), r * std::cos(phi), r * std::sin(phi), k3 * l);
}

struct Row {
    double error = 0, steps = 0, us1 = 0, us2 = 0;
};

// Runs `rays` independent rays with 1 and 2 threads; `one(i, err, steps)` traces ray i.
template <class F>
Row measure(int rays, F&& one) {
    Row row;
    std::vector<double> err(rays), steps(rays);
    for (int threads : {1, 2}) {
        const double s = bench::seconds([&] {
#pragma omp parallel for num_threads(threads) schedule(dynamic)
            for (int i = 0; i < rays; ++i) one(i, err[i], steps[i]);
        });
        (threads == 1 ? row.us1 : row.us2) = 1e6 * s / rays;
    }
    for (int i = 0; i < rays; ++i) {
        row.error = std::max(row.error, err[i]);
        row.steps += steps[i] / rays;
    }
    return row;
}

}  // namespace

int main() {
    std::printf("# Generic tracer: speed against error\n\nMachine: %s, %d hardware threads.\n\n",
                bench::machineName().c_str(), omp_get_num_procs());
    const std::vector<double> tolerances{1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
    const std::vector<std::string> adaptive{"cash_karp54", "dopri5", "dopri87", "bulirsch_stoer"};

    const Schwarzschild bh(1.0);
    const double exact = 0.5903957876058273;
    std::printf("## Schwarzschild deflection, b = 10 M (exact 0.5903957876058273), start and end at 10^6 M\n\n");
    std::printf(
        "| stepper | tolerance | abs. error | steps/ray | us/ray (1 thread) | us/ray (2 threads) "
        "|\n|---|---|---|---|---|---|\n");
    const PhasePoint start = impactParameterRay(bh, 10, 1e6);
    for (const auto& name : adaptive)
        for (double tol : tolerances) {
            TraceOptions o;
            o.stepper = parseStepper(name);
            o.absTol = o.relTol = tol;
            o.initialStep = 1;
            o.escapeRadius = 1e6;
            o.maxAffine = 1e8;
            const Row row = measure(256, [&](int, double& e, double& n) {
                const DeflectionResult d = measureDeflection(bh, start, o);
                e = std::abs(d.deflection - exact);
                n = static_cast<double>(d.trace.steps);
            });
            std::printf("| %s | %.0e | %.2e | %.0f | %.1f | %.1f |\n", name.c_str(), tol, row.error, row.steps, row.us1,
                        row.us2);
        }

    std::printf("\n## Goedel null rays, three windings, a = 1 (error: max |x - x_closed form| at every step)\n\n");
    std::printf(
        "| stepper | tolerance / step | max abs. error | steps/ray | us/ray (1 thread) | us/ray (2 threads) "
        "|\n|---|---|---|---|---|---|\n");
    const GodelCartesian godel(1.0);
    const LocalFrame frame = LocalFrame::staticObserver(godel, Vec4::Zero());
    const int rays = 256;
    auto godelRay = [&](const TraceOptions& base, int i, double& e, double& n) {
        const double psi = 0.2 + 2.7 * i / (rays - 1), phi0 = 0.1 * i;
        const Vec3 dir(std::sin(psi) * std::cos(phi0), std::sin(psi) * std::sin(phi0), std::cos(psi));
        TraceOptions o = base;
        o.maxAffine = 3 * kPi / (std::sqrt(1 + std::cos(psi) * std::cos(psi)) / 2);
        double worst = 0;
        const TraceResult r =
            traceGeodesic(godel, {Vec4::Zero(), frame.pastNullMomentum(godel, dir)}, o, [&](const Segment& s) {
                worst = std::max(worst, (s.s1.x - godelClosedForm(psi, phi0, s.l1)).cwiseAbs().maxCoeff());
                return false;
            });
        e = worst;
        n = static_cast<double>(r.steps);
    };
    for (double h : {0.1, 0.03, 0.01, 0.003}) {
        TraceOptions o;
        o.stepper = StepperKind::RK4;
        o.initialStep = h;
        const Row row = measure(rays, [&](int i, double& e, double& n) { godelRay(o, i, e, n); });
        std::printf("| rk4 | h = %g | %.2e | %.0f | %.1f | %.1f |\n", h, row.error, row.steps, row.us1, row.us2);
    }
    for (const auto& name : adaptive)
        for (double tol : tolerances) {
            TraceOptions o;
            o.stepper = parseStepper(name);
            o.absTol = o.relTol = tol;
            o.initialStep = 1e-2;
            const Row row = measure(rays, [&](int i, double& e, double& n) { godelRay(o, i, e, n); });
            std::printf("| %s | %.0e | %.2e | %.0f | %.1f | %.1f |\n", name.c_str(), tol, row.error, row.steps, row.us1,
                        row.us2);
        }
    return 0;
}
