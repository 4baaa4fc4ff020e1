// SPDX-License-Identifier: BSD-3-Clause
// The Goedel image three ways (seed 001's comparison: 605 s numeric, 41 s analytic per pixel,
// 4.1 ms per vertex on 2009 hardware): a 1024x512 panorama of one sphere with 2 and with 6
// visible images, rendered by numeric integration per pixel, closed-form geodesics per pixel,
// and the inverse problem per vertex (CPU raster). Time and difference to the closed form.
#include "bench_common.hpp"
#include "bench_scenes.hpp"
#include "core/godel/images.hpp"
#include "core/scene/godel_placement.hpp"
#include "core/metrics/godel.hpp"
#include "core/render/render.hpp"

#include <omp.h>

#include <cstdio>

using namespace lc;

namespace {

Scene makeScene(int windings) {
    Scene s = bench::godelBallPanorama(Vec4(0, 1.0, 0.0, 0.5), 0.25, windings);
    s.settings.trace.absTol = s.settings.trace.relTol = 1e-8;
    return s;
}

struct Diff {
    std::size_t coverage = 0, objects = 0;
};
Diff compare(const RenderResult& ref, const RenderResult& r) {
    Diff d;
    for (std::size_t n = 0; n < ref.pixels.size(); ++n) {
        d.objects += ref.pixels[n].kind == PixelRecord::Object;
        d.coverage += ref.pixels[n].kind != r.pixels[n].kind;
    }
    return d;
}

}  // namespace

int main() {
    std::printf("# Goedel image three ways, 1024x512 panorama, one sphere (r = 1, z = 0.5, R = 0.25)\n\n");
    std::printf("Machine: %s, %d hardware threads; numeric = dopri5 at tolerance 1e-8.\n\n",
                bench::machineName().c_str(), omp_get_num_procs());
    std::printf(
        "| windings | visible images | method | threads | time | vs closed form: pixels differing / object pixels |\n");
    std::printf("|---|---|---|---|---|---|\n");
    for (int windings : {0, 2}) {
        Scene s = makeScene(windings);
        const godel::ImageSolver solver(1.0);
        godel::ImageOptions io;
        io.maxWinding = windings;
        const std::size_t images = solver.solve(s.spheres[0].centre.tail<3>(), io).images.size();
        for (int threads : {1, 2}) {
            s.settings.threads = threads;
            const RenderResult closed = renderGodelClosedForm(s);
            double vertexSeconds = 0;
            const RenderResult vertex = renderGodelPerVertex(s, 100, 200, &vertexSeconds);
            const Diff dv = compare(closed, vertex);
            std::printf("| %d | %zu | closed form per pixel | %d | %.2f s | reference (%zu object pixels) |\n",
                        windings, images, threads, closed.stats.seconds, dv.objects);
            std::printf(
                "| %d | %zu | per vertex (19802 vertices; vertex images %.1f ms) | %d | %.1f ms | %zu / %zu |\n",
                windings, images, 1e3 * vertexSeconds, threads, 1e3 * vertex.stats.seconds, dv.coverage, dv.objects);
            if (threads == 2) {
                const RenderResult numeric = renderNumeric(s);
                const Diff dn = compare(closed, numeric);
                std::printf("| %d | %zu | numeric per pixel | %d | %.2f s | %zu / %zu |\n", windings, images, threads,
                            numeric.stats.seconds, dn.coverage, dn.objects);
            }
        }
    }
    return 0;
}
