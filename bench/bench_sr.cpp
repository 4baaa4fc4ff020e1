// SPDX-License-Identifier: BSD-3-Clause
// Special-relativistic local ray tracing (seed 003) on the CPU: frame times of the exact
// local ray tracer against polygon distortion, and the Planck -> sRGB lookup table.
// Prints markdown tables.
#include "bench_common.hpp"
#include <cmath>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include "core/colour/blackbody.hpp"
#include "core/sr/photo_object.hpp"
#include "core/sr/renderer.hpp"

using namespace lc;
using namespace lc::sr;

namespace {

template <class F>
double bestSeconds(int reps, F&& f) {
    double best = 1e300;
    for (int i = 0; i < reps; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
}

// Seed 003 Fig. 10: cube of edge 5 approaching at 0.95 c. The observer is Fig. 7's position
// scaled by 5; the observation time puts the observer 4 units in front of the cube's centre
// in the cube's rest frame (1.5 in front of its face), so the front and top faces show.
SrScene cubeScene(int n) {
    SrScene s;
    SrObject o;
    o.mesh = makeCube(5.0, n);
    o.frame = MovingFrame(Vec3(0.0, 0.95, 0.0), Vec3::Zero());
    s.objects.push_back(o);
    s.lightPosition = Vec3(90.0, 0.0, 9.8) * 5.0;
    const double yObs = 22.3;
    s.observerTime = (yObs - 4.0 / o.frame.gamma()) / 0.95;
    return s;
}

ObserverCamera camera(const SrScene& s) {
    ObserverCamera c;
    c.position = Vec3(0.15, 22.3, 3.0);
    const Vec4 obs(s.observerTime, c.position.x(), c.position.y(), c.position.z());
    c.forward = apparentPosition(s.objects[0].frame, Vec3::Zero(), obs) - c.position;
    c.up = Vec3(0.0, 0.0, 1.0);
    c.fovYDeg = 25.0;
    c.width = 1280;
    c.height = 720;
    c.fovXDeg = 2 * std::atan(std::tan(0.5 * c.fovYDeg * kPi / 180) * c.width / c.height) * 180 / kPi;  // square pixels
    return c;
}

}  // namespace

int main() {
    std::printf("# bench_sr\n\nMachine: %s, %d OpenMP threads available\n\n", bench::machineName().c_str(),
                omp_get_max_threads());

    auto table = std::make_shared<const colour::BlackbodyTable>(1000.0, 60000.0, 2048);
    const SrRenderer renderer(table);

    std::printf("## Cube of edge 5 at 0.95 c, 1280x720 (seed 003 Fig. 10 / Table 1)\n\n");
    std::printf(
        "| triangles/face | triangles | hit px | LRT 1 thr [ms] | LRT 2 thr [ms] | brute force 2 thr [ms] | "
        "polygon vertex transform [ms] | polygon render 2 thr [ms] | px where polygon coverage differs |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (int n : {5, 10}) {
        const SrScene scene = cubeScene(n);
        const ObserverCamera cam = camera(scene);
        SrRenderOptions o;
        SrImage exact;
        o.threads = 1;
        const double t1 = bestSeconds(4, [&] { exact = renderer.render(scene, cam, o); });
        o.threads = 2;
        const double t2 = bestSeconds(6, [&] { exact = renderer.render(scene, cam, o); });
        double tb = -1.0;
        if (n == 5) {
            o.mode = SrRenderMode::BruteForce;
            tb = bestSeconds(1, [&] { renderer.render(scene, cam, o); });
        }
        const Vec4 obs(scene.observerTime, cam.position.x(), cam.position.y(), cam.position.z());
        std::vector<Vec3> app;
        const double tv = bestSeconds(
            20, [&] { app = apparentPositions(scene.objects[0].frame, scene.objects[0].mesh.positions, obs); });
        o.mode = SrRenderMode::PolygonDistortion;
        SrImage poly;
        const double tp = bestSeconds(6, [&] { poly = renderer.render(scene, cam, o); });
        int hits = 0, differ = 0;
        for (size_t i = 0; i < exact.object.size(); ++i) {
            hits += exact.object[i] >= 0;
            differ += (exact.object[i] >= 0) != (poly.object[i] >= 0);
        }
        char brute[32] = "-";
        if (tb >= 0) std::snprintf(brute, sizeof brute, "%.0f", 1e3 * tb);
        std::printf("| %d | %zu | %d | %.1f | %.1f | %s | %.4f | %.1f | %d |\n", 2 * n * n,
                    scene.objects[0].mesh.triangles.size(), hits, 1e3 * t1, 1e3 * t2, brute, 1e3 * tv, 1e3 * tp,
                    differ);
    }

    std::printf("\n## Planck -> sRGB lookup table (1000-26000 K, linear interpolation)\n\n");
    std::printf("| N | build [ms] | max abs error colour-only | max abs error reference-log | lookup [ns] |\n");
    std::printf("|---|---|---|---|---|\n");
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(1000.0, 26000.0);
    std::vector<double> temps(2000);
    for (double& t : temps) t = u(rng);
    std::vector<Vec3> exactCo, exactRef;
    for (double t : temps) {
        exactCo.push_back(colour::blackbodySrgb(t, colour::ToneMap::ColourOnly));
        exactRef.push_back(colour::blackbodySrgb(t, colour::ToneMap::ReferenceLog));
    }
    for (int N : {16, 64, 256, 1024, 4096}) {
        std::unique_ptr<colour::BlackbodyTable> t;
        const double tb = bestSeconds(3, [&] { t = std::make_unique<colour::BlackbodyTable>(1000.0, 26000.0, N); });
        double eCo = 0.0, eRef = 0.0;
        for (size_t i = 0; i < temps.size(); ++i) {
            eCo = std::max(eCo, (t->lookup(temps[i], colour::ToneMap::ColourOnly) - exactCo[i]).cwiseAbs().maxCoeff());
            eRef = std::max(eRef,
                            (t->lookup(temps[i], colour::ToneMap::ReferenceLog) - exactRef[i]).cwiseAbs().maxCoeff());
        }
        Vec3 sink = Vec3::Zero();
        const int reps = 1000000;
        const double tl = bestSeconds(3, [&] {
            for (int i = 0; i < reps; ++i) sink += t->lookup(1000.0 + 0.025 * i, colour::ToneMap::ColourOnly);
        });
        std::printf("| %d | %.2f | %.2e | %.2e | %.1f |%s\n", N, 1e3 * tb, eCo, eRef, 1e9 * tl / reps,
                    sink.sum() < 0 ? " " : "");
    }
    return 0;
}
