// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The figures of a finished render that say how far to trust it: method and accuracy settings,
// time and speed, the worst null-condition drift |H|, why the rays stopped, and a disk's flux.
// `lightcone render` prints these lines and the workbench's accuracy panel shows the same ones.
#include "core/render/render.hpp"
#include "core/scene/scene.hpp"

#include <string>
#include <vector>

namespace lc::cli {

struct RenderReport {
    std::string what;               // "rendered SOURCE: 320x160, kerr, dopri5 tol 1.0e-10"
    std::string time;               // "time 1.234 s (41000 rays/s), mean 210.3 steps/ray"
    std::string drift;              // "worst null-condition drift |H| = 1.2e-11" (or why there is none)
    std::string stops;              // "object pixels 1234; stops: escaped=... horizon=..."
    std::string error;              // numeric renders with a sky: the estimated error in pixels
    std::vector<std::string> disk;  // a disk's pixels by image order and its flux; empty without one
    std::string warning;            // rk4 whose fixed step took more steps than an adaptive stepper would

    std::vector<std::string> lines() const;
    // The same without the time: what the --data file's header keeps ("lightcone:report"), equal
    // for equal renders (Python's Render.save writes the command line's bytes).
    std::vector<std::string> figures() const;
};

RenderReport renderReport(const Scene& scene, const RenderResult& result, bool polygonDistortion = false);

// Before a numeric render with rk4: its steps are the fixed TraceOptions::initialStep, whatever
// the tolerance, so a ray that must travel far takes tens of thousands of them (issue #47). The
// warning names the step, the steps a ray crossing the scene needs at least, and the cure; empty
// for every other stepper and method.
std::string fixedStepWarning(const Scene& scene);
// The same on stderr, once (rank 0 under mpirun), when there is one.
void warnAboutFixedSteps(const Scene& scene);

}  // namespace lc::cli
