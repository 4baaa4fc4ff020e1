// SPDX-License-Identifier: BSD-3-Clause
#include "core/render/error_estimate.hpp"

#include "core/numerics/parallel.hpp"
#include "core/render/render.hpp"
#include "core/scene/frame_camera.hpp"

#include <algorithm>
#include <cmath>

namespace lc {
namespace {

// Where the light came from, as the renderer looks up the sky: the contravariant spatial tangent.
Vec3 escapeDirection(const Spacetime& st, const PhasePoint& q) {
    return (st.inverseMetric(q.x) * q.p).tail<3>().normalized();
}

}  // namespace

double RenderErrorEstimate::medianPixels() const {
    if (errorPixels.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::vector<double> sorted = errorPixels;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    return sorted[sorted.size() / 2];
}

double RenderErrorEstimate::maxPixels() const {
    if (errorPixels.empty()) return std::numeric_limits<double>::quiet_NaN();
    return *std::max_element(errorPixels.begin(), errorPixels.end());
}

bool escapeDirectionsUnsettled(const Scene& scene) {
    return scene.spacetime->asymptoticallyFlat() && resolveMethod(scene) == RenderSettings::Method::Numeric &&
           traceOptionsFor(scene).escapeAngle > kPi;
}

RenderErrorEstimate estimateRenderError(const Scene& scene, int perSide) {
    RenderErrorEstimate e;
    if (!scene.spacetime->asymptoticallyFlat() || resolveMethod(scene) != RenderSettings::Method::Numeric) return e;
    const Spacetime& st = *scene.spacetime;
    const LocalFrame frame = observerFrame(scene);
    const Camera cam = frameCamera(scene.camera, st, frame);
    const TraceOptions opt = traceOptionsFor(scene);
    if (opt.stepper == StepperKind::RK4) return e;  // fixed steps: no tolerance to tighten
    // The directions compared would differ by the bending still ahead, not by the tracer's error.
    if (escapeDirectionsUnsettled(scene)) return e;
    TraceOptions tighter = opt;
    tighter.absTol = std::max(opt.absTol / 100, 1e-15);
    tighter.relTol = std::max(opt.relTol / 100, 1e-15);
    tighter.escapeAngle = opt.escapeAngle / 100;
    e.tighterTolerance = tighter.relTol;
    const double pixel = std::min(cam.fovXDeg / cam.width, cam.fovYDeg / cam.height) * kPi / 180;
    std::vector<double> errors(static_cast<std::size_t>(perSide * perSide), -1);
    FirstError error;
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < perSide * perSide; ++k)
        error.run([&] {
            const int i = (2 * (k % perSide) + 1) * cam.width / (2 * perSide);
            const int j = (2 * (k / perSide) + 1) * cam.height / (2 * perSide);
            PhasePoint start{scene.observer, frame.pastNullMomentum(st, cam.direction(i, j))};
            start.p /= std::max(std::abs(start.p(0)), 1e-6 * start.p.norm());  // as the renderer scales
            const TraceResult a = traceGeodesic(st, start, opt), b = traceGeodesic(st, start, tighter);
            if (a.reason != StopReason::Escaped || b.reason != StopReason::Escaped) return;
            const Vec3 da = escapeDirection(st, a.end), db = escapeDirection(st, b.end);
            errors[static_cast<std::size_t>(k)] = std::atan2(da.cross(db).norm(), da.dot(db)) / pixel;
        });
    error.rethrow();
    for (int k = 0; k < perSide * perSide; ++k)
        if (errors[static_cast<std::size_t>(k)] >= 0) {
            e.pixels.push_back({(2 * (k % perSide) + 1) * cam.width / (2 * perSide),
                                (2 * (k / perSide) + 1) * cam.height / (2 * perSide)});
            e.errorPixels.push_back(errors[static_cast<std::size_t>(k)]);
        }
    return e;
}

}  // namespace lc
