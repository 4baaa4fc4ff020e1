// SPDX-License-Identifier: BSD-3-Clause
// What the CPU renderers share (blank results, thread count, statistics, the static-spheres
// check) and the choice of method: resolveMethod picks, render() dispatches to numeric.cpp,
// closed_form.cpp or per_vertex.cpp.
#include "core/render/render.hpp"

#include "core/render/error_estimate.hpp"

#include "core/metrics/godel.hpp"

#include <algorithm>
#include <chrono>
#include <omp.h>
#include <stdexcept>

namespace lc {

RenderResult blankResult(const Camera& cam) {
    RenderResult out;
    out.width = cam.width;
    out.height = cam.height;
    out.pixels.resize(static_cast<std::size_t>(cam.width) * cam.height);
    return out;
}

int renderThreads(const RenderSettings& s) { return s.threads > 0 ? s.threads : omp_get_max_threads(); }

RowBand rowsToTrace(const RenderSettings& s, const Camera& cam) {
    const RowBand band{s.rowBegin, s.rowEnd < 0 ? cam.height : s.rowEnd};
    if (band.begin < 0 || band.end > cam.height || band.begin >= band.end)
        throw std::invalid_argument("rows " + std::to_string(s.rowBegin) + " to " + std::to_string(s.rowEnd) +
                                    " are not a band of the image's " + std::to_string(cam.height) + " rows");
    return band;
}

void summarise(RenderResult& out, std::chrono::steady_clock::time_point t0) {
    summarise(out, t0, RowBand{0, out.height});
}

void summarise(RenderResult& out, std::chrono::steady_clock::time_point t0, const RowBand& band) {
    RenderStats& stats = out.stats;
    double steps = 0;
    const auto first = out.pixels.begin() + static_cast<std::ptrdiff_t>(band.begin) * out.width;
    const auto last = out.pixels.begin() + static_cast<std::ptrdiff_t>(band.end) * out.width;
    for (auto it = first; it != last; ++it) {
        const PixelRecord& px = *it;
        stats.worstDrift = std::max(stats.worstDrift, static_cast<double>(px.drift));
        stats.hits += px.kind == PixelRecord::Object;
        ++stats.stopCounts[static_cast<std::size_t>(px.stopReason)];
        steps += px.steps;
    }
    stats.rays = static_cast<std::size_t>(last - first);
    stats.meanSteps = steps / std::max<std::size_t>(1, stats.rays);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void requireStaticSpheres(const Scene& scene, const std::string& who) {
    if (!scene.meshes.empty())
        throw std::invalid_argument(who + " draws spheres only; mesh '" + scene.meshes[0].name +
                                    "' needs method per_vertex (Goedel) or a minkowski scene");
    for (const auto& s : scene.spheres)
        if (s.motion.moving())
            throw std::invalid_argument(who + " draws objects at rest; sphere '" + s.name +
                                        "' moves (use method per_vertex)");
}

RenderSettings::Method parseRenderMethod(const std::string& name) {
    using M = RenderSettings::Method;
    if (name == "auto") return M::Auto;
    if (name == "numeric") return M::Numeric;
    if (name == "closed_form") return M::ClosedForm;
    if (name == "per_vertex") return M::PerVertex;
    throw std::invalid_argument("unknown render method '" + name +
                                "' (expected auto, numeric, closed_form or per_vertex)");
}

std::string renderMethodName(RenderSettings::Method m) {
    switch (m) {
        case RenderSettings::Method::Auto: return "auto";
        case RenderSettings::Method::Numeric: return "numeric";
        case RenderSettings::Method::ClosedForm: return "closed_form";
        case RenderSettings::Method::PerVertex: return "per_vertex";
    }
    return "?";
}

const std::vector<std::string>& pixelKindNames() {
    static const std::vector<std::string> names{"background", "object", "sky", "horizon", "failed", "disk"};
    static_assert(PixelRecord::Disk == 5, "one name per PixelRecord::Kind, in code order");
    return names;
}

RenderSettings::Method resolveMethod(const Scene& scene) {
    using M = RenderSettings::Method;
    if (scene.settings.method != M::Auto) return scene.settings.method;
    if (scene.settings.magnification) return M::Numeric;  // the bundles ride on the numeric tracer's steps
    const bool godel = scene.spacetime->godelRadius().has_value();
    if (!godel || scene.observerVelocity.tail<3>().norm() > 0) return M::Numeric;
    bool perVertex = !scene.meshes.empty();  // meshes and moving bodies: photo-objects per vertex
    for (const auto& s : scene.spheres) perVertex = perVertex || s.motion.moving();
    return perVertex ? M::PerVertex : M::ClosedForm;
}

RenderResult render(const Scene& scene, const ProgressCallback& progress,
                    const std::vector<PhotoSceneObject>* prebuiltPhotoScene) {
    const RenderSettings::Method method = resolveMethod(scene);
    if (scene.settings.magnification && method != RenderSettings::Method::Numeric)
        throw std::invalid_argument(
            "render.magnification (--magnification): the magnification comes from the numeric tracer's ray bundles; "
            "use method "
            "\"numeric\" (or \"auto\")");
    switch (method) {
        case RenderSettings::Method::ClosedForm: return renderGodelClosedForm(scene, progress);
        case RenderSettings::Method::PerVertex:
            return renderGodelPerVertex(scene, scene.settings.meshLatitudes, scene.settings.meshLongitudes, nullptr,
                                        progress, prebuiltPhotoScene);
        default: {
            RenderResult result = renderNumeric(scene, progress);
            // The estimate on the rendering thread (not a GUI's), for whole images only (a band
            // of one frame rendered by several processes gets none).
            const RenderSettings& rows = scene.settings;
            if (rows.rowBegin == 0 && (rows.rowEnd < 0 || rows.rowEnd >= scene.camera.height)) {
                const RenderErrorEstimate e = estimateRenderError(scene);
                RenderStats& s = result.stats;
                s.errorRays = static_cast<int>(e.errorPixels.size());
                if (s.errorRays > 0) {
                    s.errorMaxPixels = e.maxPixels();
                    s.errorMedianPixels = e.medianPixels();
                    s.errorTighterTolerance = e.tighterTolerance;
                }
            }
            return result;
        }
    }
}

}  // namespace lc
