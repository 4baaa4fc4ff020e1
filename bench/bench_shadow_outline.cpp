// SPDX-License-Identifier: BSD-3-Clause
// The shadow's whole outline (issue #50): lc::traceShadowOutline at 360 points on every core,
// its time against its worst error, relative to the analytic finite-distance shadow of Carter's
// observer (Grenzebach, Perlick & Lammerzahl 2014; tests/validation/carter_shadow_oracle.hpp),
// for three observers and three tolerances. Each ray's fate from the built-in Kerr's radial potential
// (core/analysis/radial_potential_fate), and, for comparison, traced: the same hole as a formula
// metric (data/metrics/kerr.json, the same chart), whose rays are integrated.
#include "bench_common.hpp"
#include "core/analysis/shadow.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/scene/frame_camera.hpp"
#include "core/spacetime/named_observer.hpp"
#include "readers/io/metric_file.hpp"
#include "tests/validation/carter_shadow_oracle.hpp"

#include <omp.h>

#include <string>

#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace lc;
using namespace lc::validation;

namespace {

struct Case {
    const char* name;
    double a, r, thetaDeg;
};

}  // namespace

int main(int argc, char** argv) {
    const int points = argc > 1 ? std::atoi(argv[1]) : 360;
    const std::string stepper = argc > 2 ? argv[2] : "auto";  // a scene's "stepper": auto traces edges with dopri87
    std::printf("# The shadow's outline, %d points, Carter's observer, stepper %s\n\nMachine: %s, %d threads.\n\n",
                points, stepper.c_str(), bench::machineName().c_str(), omp_get_max_threads());
    std::printf("| observer | fates | tolerance | s | worst relative error of the edge angle | solid angle (sr) |\n");
    std::printf("|---|---|---|---|---|---|\n");
    const Case cases[] = {{"a = 0.9, r = 10 M, 60 deg", 0.9, 10, 60},
                          {"a = 0.998, r = 3 M, 90 deg (inside the photon region)", 0.998, 3, 90},
                          {"a = 0.5, r = r+ + 0.05 M, 60 deg (a small cap of sky)", 0.5, 1.916025403784, 60}};
    const std::string formula = std::string(LIGHTCONE_SOURCE_DIR) + "/data/metrics/kerr.json";
    for (const bool traced : {false, true})
        for (const Case& c : cases)
            for (const double tolerance : {1e-6, 1e-8, 1e-10}) {
                if (traced && tolerance != 1e-10) continue;
                Scene s;
                const auto kerr = std::make_shared<KerrNewman>(1, c.a, 0);
                s.spacetime = traced ? SpacetimePtr(io::loadFormulaMetric(formula, {{"a", c.a}})) : SpacetimePtr(kerr);
                const KerrNewman& kn = *kerr;
                const double theta = c.thetaDeg * kPiV / 180;
                const KsPlacement at(kn, c.r, theta);
                s.observer = at.event;
                s.camera.forward = -at.basis[1].tail<3>();
                s.camera.up = -at.basis[2].tail<3>();
                s.observerVelocity = namedObserverVelocity(kn, s.observer, NamedObserver::Carter);
                setSceneStepper(s.settings, stepper);
                ShadowOutline o;
                const double seconds = bench::seconds([&] { o = traceShadowOutline(s, points, tolerance); });
                const CarterFrameBL carter(KerrNewmanBL{1, c.a, 0}, c.r, theta);
                const LocalFrame frame = observerFrame(s);
                const Vec3 right = (o.right - o.right.dot(o.inside) * o.inside).normalized();
                const AnalyticOutline want{carter,   at,    kn.metric(s.observer), frame,
                                           o.inside, right, right.cross(o.inside), carter.photonRegion()};
                double worst = 0;
                for (std::size_t k = 0; k < o.points.size(); k += 8) {  // every 8th point: the oracle is slow
                    const double expected = want.radiusAt(o.positionAngles[k]);
                    worst = std::max(worst, std::abs(o.radii[k] - expected) / expected);
                }
                std::printf("| %s | %s | %.0e | %.3g | %.1e | %.6f |\n", c.name,
                            traced ? "traced (kerr.json as a formula)" : "radial potential", tolerance, seconds, worst,
                            o.solidAngle);
                std::fflush(stdout);
            }
    return 0;
}
