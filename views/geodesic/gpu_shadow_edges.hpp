// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The shadow's edges found by the GPU tracer (vtkLightconeNumericImageRenderer), for
// lc::measureShadow's geometry: each chord is rendered as a strip of pixels along its great
// circle (a panorama strip from the axis to its antipode: shadows larger than a hemisphere too),
// the strip narrowed to the two pixels around the first escaping ray, and rendered again.
// So `lc::measureShadow(scene, lc::views::gpuShadowEdges(scene))` measures on the GPU what
// `lc::measureShadow(scene)` bisects on the CPU. Single precision limits it: the viewing direction
// is built in floats (about 1e-7 rad), and the tracer integrates in floats.
#include "core/analysis/shadow.hpp"

namespace lc::views {

struct GpuShadowEdgeOptions {
    int stripPixels = 512;         // pixels per strip
    int passes = 4;                // strips per edge (each narrows the bracket about stripPixels / 2 times)
    double finestAngle = 2e-7;     // rad: no narrower strip (float resolution of a direction)
    double horizonEpsilon = 1e-4;  // the tracer's boundary margin (vtkLightconeNumericImageRenderer)
    double tolerance = 1e-7;       // the tracer's float error tolerance
    int maxSteps = 20000;          // the tighter tolerance takes more steps from far away
};

// Needs an X display (xvfb-run); throws what the GPU tracer's SetScene throws, and from the finder
// when a chord's axis does not fall in.
ShadowEdgeFinder gpuShadowEdges(const Scene& scene, const GpuShadowEdgeOptions& options = {});

}  // namespace lc::views
