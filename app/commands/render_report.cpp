// SPDX-License-Identifier: BSD-3-Clause
#include "app/commands/render_report.hpp"

#include "app/distributed/distributed_tasks.hpp"
#include "core/analysis/disk_observables.hpp"
#include "core/render/error_estimate.hpp"
#include "core/render/special_relativity.hpp"

#include <cmath>
#include <cstdio>

namespace lc::cli {
namespace {

template <typename... Args>
std::string format(const char* pattern, Args... args) {
    char buf[512];
    std::snprintf(buf, sizeof buf, pattern, args...);
    return buf;
}

// Above this many steps a ray, rk4's fixed step is the render's cost.
constexpr double kFixedStepWarningSteps = 1e4;

// The numeric tracer with rk4: steps of TraceOptions::initialStep, no tolerance.
bool tracesWithFixedSteps(const Scene& scene) {
    return scene.settings.trace.stepper == StepperKind::RK4 && !isSrScene(scene) &&
           resolveMethod(scene) == RenderSettings::Method::Numeric;
}

}  // namespace

void warnAboutFixedSteps(const Scene& scene) {
    if (const std::string w = fixedStepWarning(scene); !w.empty() && dist::Processes::current().root())
        std::fprintf(stderr, "%s\n", w.c_str());
}

std::string fixedStepWarning(const Scene& scene) {
    if (!tracesWithFixedSteps(scene)) return "";
    const double h = scene.settings.trace.initialStep;
    // A ray from the observer out past the origin's distance at least; escaping rays go further.
    const double distance = scene.observer.tail<3>().norm();
    return format(
        "warning: rk4 takes fixed steps of %.3g in the affine parameter and does not use the tolerance: a ray "
        "leaving the observer at r = %.3g takes %.0f steps at the very least, and its error is not controlled; "
        "--stepper auto (dopri5) sets the steps from --tolerance",
        h, distance, std::ceil(distance / h));
}

std::vector<std::string> RenderReport::lines() const {
    std::vector<std::string> out{what, time};
    if (!drift.empty()) out.push_back(drift);
    if (!error.empty()) out.push_back(error);
    out.push_back(stops);
    out.insert(out.end(), disk.begin(), disk.end());
    if (!warning.empty()) out.push_back(warning);
    return out;
}

std::vector<std::string> RenderReport::figures() const {
    std::vector<std::string> out = lines();
    out.erase(out.begin() + 1);  // the time
    return out;
}

RenderReport renderReport(const Scene& scene, const RenderResult& result, bool polygonDistortion) {
    RenderReport r;
    const RenderStats& s = result.stats;
    const RenderSettings::Method method = resolveMethod(scene);
    const bool specialRelativity = isSrScene(scene);
    if (specialRelativity)
        r.what = format("rendered %s: %dx%d, special relativity, %s with Doppler and searchlight", scene.source.c_str(),
                        result.width, result.height, polygonDistortion ? "polygon distortion" : "local ray tracing");
    else if (method != RenderSettings::Method::Numeric)
        r.what = format("rendered %s: %dx%d, %s, method %s (closed-form geodesics, no ODE)", scene.source.c_str(),
                        result.width, result.height, scene.spacetime->name().c_str(), renderMethodName(method).c_str());
    else if (scene.settings.trace.stepper == StepperKind::RK4)  // no tolerance: say the step it used
        r.what = format("rendered %s: %dx%d, %s, rk4 fixed step %.3g (no tolerance)", scene.source.c_str(),
                        result.width, result.height, scene.spacetime->name().c_str(), scene.settings.trace.initialStep);
    else
        r.what =
            format("rendered %s: %dx%d, %s, %s tol %.1e", scene.source.c_str(), result.width, result.height,
                   scene.spacetime->name().c_str(),
                   ((scene.settings.autoStepper ? "auto: " : "") + stepperName(scene.settings.trace.stepper)).c_str(),
                   scene.settings.trace.relTol);
    r.time = s.rays > 0
                 ? format("time %.3f s (%.0f rays/s), mean %.1f steps/ray", s.seconds, s.rays / s.seconds, s.meanSteps)
                 : format("time %.3f s", s.seconds);
    if (!specialRelativity && method == RenderSettings::Method::PerVertex)
        r.drift = "vertex images from the inverse problem (exact null geodesics; no drift to report)";
    else if (!specialRelativity)
        r.drift = format("worst null-condition drift |H| = %.3e", s.worstDrift);
    // Adaptive steppers need 10^2-10^3 steps a ray on the shipped scenes (docs/PERFORMANCE.md).
    if (tracesWithFixedSteps(scene) && s.meanSteps > kFixedStepWarningSteps)
        r.warning = format(
            "warning: rk4 took %.0f steps a ray at its fixed step %.3g and its error is not controlled; "
            "an adaptive stepper sets its steps from the tolerance in far fewer (--stepper auto)",
            s.meanSteps, scene.settings.trace.initialStep);
    if (s.errorRays > 0)  // computed by lc::render with the image (core/render/error_estimate)
        r.error = format(
            "estimated error: escape directions within %.2g px (median %.2g px) on %d sampled "
            "sky rays traced again at tolerance %.1e",
            s.errorMaxPixels, s.errorMedianPixels, s.errorRays, s.errorTighterTolerance);
    else if (escapeDirectionsUnsettled(scene))
        r.error = format(
            "estimated error: escape directions not estimated: escape_angle %.3g rad (above pi) stops each ray "
            "once its fate (sky or horizon) is known, before its direction settles",
            traceOptionsFor(scene).escapeAngle);
    r.stops = format("object pixels %zu; stops:", s.hits);
    for (std::size_t k = 0; k < s.stopCounts.size(); ++k)
        if (s.stopCounts[k])
            r.stops += format(" %s=%zu", stopReasonName(static_cast<StopReason>(k)).c_str(), s.stopCounts[k]);
    if (!scene.disks.empty()) {  // the disk's images by order (0 direct, 1 secondary, ...) and its flux
        const DiskObservables d = observeDisk(scene, result);
        r.disk.push_back(format("disk pixels by image order: direct %zu, secondary %zu, tertiary %zu, higher %zu",
                                d.pixels[0], d.pixels[1], d.pixels[2], d.pixels[3]));
        // No disk light in the image (out of view, seen edge-on from its plane, hidden): say so,
        // not a mean g of NaN.
        if (d.flux > 0 && std::isfinite(d.meanRedshift))
            r.disk.push_back(
                format("disk observed flux %.6e Mdot/M^2 (secondary and higher images %.3f %%), "
                       "flux-weighted mean redshift g %.6f",
                       d.flux, 100 * d.higherOrderFraction(), d.meanRedshift));
        else
            r.disk.push_back(
                "disk observed flux 0 Mdot/M^2: no light of the disk reaches the image (out of view, "
                "seen from its plane or hidden), so no mean redshift g");
    }
    return r;
}

}  // namespace lc::cli
