// SPDX-License-Identifier: BSD-3-Clause
// Goedel closed forms against numeric integration, and the throughput of the image solvers.
// Prints markdown tables. Not a test.
#include "bench_common.hpp"
#include "core/godel/geodesic.hpp"
#include "core/godel/images.hpp"
#include "core/godel/photo_object.hpp"
#include "core/spacetime/integrator.hpp"
#include "core/metrics/godel.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace lc;
using namespace lc::godel;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

volatile double sink = 0;

using Uniform = std::uniform_real_distribution<double>;

// 1. Rays to three windings (the end point): the closed form against each stepper of the tracer.
void benchRays(double a, std::mt19937& rng, Uniform& u) {
    const int nRays = 64;
    std::vector<OriginGeodesic> rays;
    std::vector<double> lend;
    for (int i = 0; i < nRays; ++i) {
        rays.push_back(OriginGeodesic::null(a, kPi * (0.05 + 0.9 * u(rng)), 2 * kPi * u(rng), -1));
        lend.push_back(3.2 * kPi / rays.back().omega());  // a bit over three loops
    }
    double closedRate = 0;
    {
        const int reps = 20000;
        const auto t0 = Clock::now();
        for (int r = 0; r < reps; ++r)
            for (int i = 0; i < nRays; ++i) sink = sink + rays[i].cartesian(lend[i] * (1 + 1e-9 * r))(1);
        const double dt = seconds(t0);
        std::printf("## Rays to 3 windings (end point), %d null rays\n\n", nRays);
        closedRate = reps * nRays / dt;
        std::printf(
            "| method | tolerance | max error vs closed form | steps/ray | rays/s | closed form faster by |\n"
            "|---|---|---|---|---|---|\n");
        std::printf("| closed form | - | ~1e-15 (rounding) | 1 | %.3g | 1 |\n", closedRate);
    }
    const GodelCartesian st(a);
    for (const char* name : {"dopri5", "cash_karp54", "dopri87", "bulirsch_stoer", "rk4"}) {
        const StepperKind kind = parseStepper(name);
        const std::vector<double> tols =
            kind == StepperKind::RK4 ? std::vector<double>{0.05, 0.01, 0.002} : std::vector<double>{1e-6, 1e-9, 1e-12};
        for (double tol : tols) {
            TraceOptions opt;
            opt.stepper = kind;
            if (kind == StepperKind::RK4) {
                opt.initialStep = tol;
            } else {
                opt.absTol = opt.relTol = tol;
            }
            opt.maxSteps = 10000000;
            opt.constraintTolerance = 1.0;
            double maxErr = 0, steps = 0;
            const auto t0 = Clock::now();
            for (int i = 0; i < nRays; ++i) {
                opt.maxAffine = lend[i];
                PhasePoint s;
                s.p = rays[i].momentumCartesian(0);
                const TraceResult r = traceGeodesic(st, s, opt);
                maxErr = std::max(maxErr, (r.end.x - rays[i].cartesian(lend[i])).cwiseAbs().maxCoeff());
                steps += r.steps;
            }
            const double dt = seconds(t0);
            std::printf("| %s | %s%g | %.2e | %.0f | %.3g | %.3g |\n", name, kind == StepperKind::RK4 ? "h=" : "", tol,
                        maxErr, steps / nRays, nRays / dt, closedRate / (nRays / dt));
        }
    }
}

// 2. Image solves of random static points inside the horizon, on 1 and 2 threads.
void benchImageSolves(double a, std::mt19937& rng, Uniform& u) {
    std::printf("\n## Image solves (static point, windings 0..2 = 6 images, observer at the origin)\n\n");
    std::printf("| threads | points | images | solves/s (points) | images/s |\n|---|---|---|---|---|\n");
    const int nPts = 200000;
    std::vector<Vec3> pts(nPts);
    for (auto& p : pts) {
        const double r = 2 * a * 0.95 * std::sqrt(u(rng)), ph = 2 * kPi * u(rng);
        p = Vec3(r * std::cos(ph), r * std::sin(ph), (u(rng) - 0.5) * 2.0);
    }
    const ImageSolver solver(a);
    for (int threads : {1, 2}) {
        long images = 0;
        const auto t0 = Clock::now();
#pragma omp parallel for num_threads(threads) reduction(+ : images) schedule(dynamic, 1024)
        for (int i = 0; i < nPts; ++i) {
            ImageOptions io;
            io.maxWinding = 2;
            images += long(solver.solve(pts[i], io).images.size());
        }
        const double dt = seconds(t0);
        std::printf("| %d | %d | %ld | %.3g | %.3g |\n", threads, nPts, images, nPts / dt, images / dt);
    }
}

// 3. The photo-object of a 100k-vertex sphere, on 1 and 2 threads.
void benchPhotoObject(double a) {
    std::printf("\n## Photo-object: vertex images of a sphere (windings 0..2 = 6 images per vertex)\n\n");
    std::printf("| threads | vertices | vertex-images | seconds | vertex-images/s |\n|---|---|---|---|---|\n");
    const Mesh sphere = uvSphere(0.4, 251, 400);  // 250*400 + 2 = 100002 vertices
    const PhotoObjectBuilder builder(a, Vec4(0, 0.1, -0.2, 0));
    for (int threads : {1, 2}) {
        PhotoObjectOptions o;
        o.maxWinding = 2;
        o.threads = threads;
        const auto t0 = Clock::now();
        const PhotoObject po = builder.build(sphere, Vec4(0, 0.9, 0.4, 0.2), o);
        const double dt = seconds(t0);
        long vi = 0;
        for (const PhotoLayer& L : po.layers)
            for (const VertexImage& v : L.vertices) vi += v.valid;
        std::printf("| %d | %zu | %ld | %.3f | %.3g |\n", threads, sphere.vertices.size(), vi, dt, vi / dt);
    }
}

}  // namespace

int main() {
    const double a = 1.0;
    std::printf("# Goedel closed forms vs numeric integration\n\nMachine: %s, %d OpenMP threads available\n\n",
                bench::machineName().c_str(),
#ifdef _OPENMP
                omp_get_max_threads()
#else
                1
#endif
    );
    std::mt19937 rng(1);  // one stream for the rays and then the points, as the tables were made
    Uniform u(0, 1);
    benchRays(a, rng, u);
    benchImageSolves(a, rng, u);
    benchPhotoObject(a);
    return sink == 12345.678 ? 1 : 0;
}
