// Closed-form CPU renderer for the Goedel universe (seed 001's "analytic" per-pixel path):
// the scene is moved so that the observer sits at the origin, where every null geodesic is
// known in closed form (PHYSICS.md section 2); each pixel's ray is sampled along its affine
// parameter and the first sphere entry is refined with the Illinois method. No ODE.
#include "core/frame.hpp"
#include "core/godel/geodesic.hpp"
#include "core/godel/isometry.hpp"
#include "core/metrics/godel.hpp"
#include "core/render.hpp"
#include "core/roots.hpp"

#include <atomic>
#include <chrono>
#include <omp.h>
#include <stdexcept>

namespace lc {

RenderResult renderGodelClosedForm(const Scene& scene, const ProgressCallback& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto* godelChart = dynamic_cast<const GodelCartesian*>(scene.spacetime.get());
    if (!godelChart) throw std::invalid_argument("the closed-form renderer needs the 'godel' metric");
    const double a = godelChart->a();
    const Camera& cam = scene.camera;
    cam.validate();
    const Vec4 u = scene.observerVelocity;
    if (u.tail<3>().norm() > 0)
        throw std::invalid_argument("the closed-form renderer takes a static observer (moving observers: use method numeric)");

    // Observer to the origin; its static frame goes to the coordinate frame there.
    const godel::Isometry toObserver = godel::Isometry::movingToOrigin(a, scene.observer);
    const godel::Isometry back = toObserver.inverse();
    const LocalFrame frame = LocalFrame::staticObserver(*godelChart, scene.observer);
    std::array<Vec3, 3> axes;  // the observer's frame vectors, seen at the origin
    for (int i = 0; i < 3; ++i) axes[i] = toObserver.pushForward(scene.observer, frame.e[i + 1]).tail<3>();

    double minRadius = 1e300;
    for (const auto& s : scene.spheres) minRadius = std::min(minRadius, s.radius);
    const double step = 0.5 * minRadius;
    const double maxAffine = scene.settings.trace.maxAffine;

    RenderResult out;
    out.width = cam.width;
    out.height = cam.height;
    out.pixels.resize(static_cast<std::size_t>(cam.width) * cam.height);
    std::atomic<int> rowsDone{0};
    const int threads = scene.settings.threads > 0 ? scene.settings.threads : omp_get_max_threads();

#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int j = 0; j < cam.height; ++j) {
        for (int i = 0; i < cam.width; ++i) {
            PixelRecord& px = out.pixels[static_cast<std::size_t>(j) * cam.width + i];
            const Vec3 n = cam.direction(i, j);
            const Vec3 d = (n(0) * axes[0] + n(1) * axes[1] + n(2) * axes[2]).normalized();
            const double sinPsi = std::hypot(d(0), d(1));
            const godel::OriginGeodesic ray =
                godel::OriginGeodesic::nullFromDirection(a, d(2), sinPsi, std::atan2(d(1), d(0)), -1);
            auto eventAt = [&](double l) { return back.apply(ray.cartesian(l)); };
            int hitObject = -1;
            double hitAffine = 0;
            double l0 = 0;
            std::vector<double> f0(scene.spheres.size());
            const Vec4 x0 = eventAt(0);
            for (std::size_t k = 0; k < scene.spheres.size(); ++k)
                f0[k] = scene.spheres[k].placement->toLocal(x0).squaredNorm() - scene.spheres[k].radius * scene.spheres[k].radius;
            int samples = 0;
            while (hitObject < 0 && l0 < maxAffine) {
                const double l1 = std::min(l0 + step, maxAffine);
                const Vec4 x1 = eventAt(l1);
                ++samples;
                for (std::size_t k = 0; k < scene.spheres.size(); ++k) {
                    const SphereObject& s = scene.spheres[k];
                    auto F = [&](double l) { return s.placement->toLocal(eventAt(l)).squaredNorm() - s.radius * s.radius; };
                    const double f1 = s.placement->toLocal(x1).squaredNorm() - s.radius * s.radius;
                    if (f0[k] > 0) {
                        const double l = firstEntry(F, l0, l1, f0[k], f1);
                        if (l >= 0 && (hitObject < 0 || l < hitAffine)) {
                            hitObject = static_cast<int>(k);
                            hitAffine = l;
                        }
                    }
                    f0[k] = f1;
                }
                l0 = l1;
            }
            px.steps = static_cast<float>(samples);
            if (hitObject < 0) {
                px.kind = PixelRecord::Background;
                px.stopReason = static_cast<std::int8_t>(StopReason::MaxAffine);
                px.affine = static_cast<float>(maxAffine);
                px.emissionTime = static_cast<float>(eventAt(maxAffine)(0));
                continue;
            }
            const SphereObject& s = scene.spheres[static_cast<std::size_t>(hitObject)];
            const Vec4 x = eventAt(hitAffine);
            const Vec3 l = s.placement->toLocal(x);
            px.kind = PixelRecord::Object;
            px.stopReason = static_cast<std::int8_t>(StopReason::Hit);
            px.object = static_cast<std::int16_t>(hitObject);
            px.u = static_cast<float>(0.5 + std::atan2(l(1), l(0)) / (2 * kPi));
            px.v = static_cast<float>(std::acos(std::clamp(l(2) / l.norm(), -1.0, 1.0)) / kPi);
            px.affine = static_cast<float>(hitAffine);
            px.emissionTime = static_cast<float>(x(0));
            px.frequencyRatio = 1;  // static emitter and observer: no shift in Goedel (PHYSICS.md section 5)
        }
        const int done = ++rowsDone;
        if (progress && omp_get_thread_num() == 0) progress(static_cast<double>(done) / cam.height);
    }
    if (progress) progress(1.0);
    double samples = 0;
    for (const auto& px : out.pixels) {
        out.stats.hits += px.kind == PixelRecord::Object;
        ++out.stats.stopCounts[static_cast<std::size_t>(px.stopReason)];
        samples += px.steps;
    }
    out.stats.rays = out.pixels.size();
    out.stats.meanSteps = samples / std::max<std::size_t>(1, out.stats.rays);
    out.stats.worstDrift = 0;  // exact null geodesics
    out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

RenderResult render(const Scene& scene, const ProgressCallback& progress) {
    return scene.settings.method == RenderSettings::Method::ClosedForm ? renderGodelClosedForm(scene, progress)
                                                                       : renderNumeric(scene, progress);
}

}  // namespace lc
