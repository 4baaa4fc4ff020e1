// SPDX-License-Identifier: BSD-3-Clause
// Closed-form CPU renderer for the Goedel universe (seed 001's "analytic" per-pixel path):
// the scene is moved so that the observer sits at the origin, where every null geodesic is
// known in closed form (docs/PHYSICS.md section 2); each pixel's ray is sampled along its affine
// parameter and the first sphere entry is refined with the Illinois method. No ODE.
#include "core/scene/frame_camera.hpp"
#include "core/godel/geodesic.hpp"
#include "core/godel/isometry.hpp"
#include "core/render/godel_lighting.hpp"
#include "core/metrics/godel.hpp"
#include "core/render/render.hpp"
#include "core/numerics/parallel.hpp"
#include "core/numerics/roots.hpp"

#include <atomic>
#include <chrono>
#include <omp.h>
#include <stdexcept>

namespace lc {
namespace {

struct SphereBounds {
    godel::Isometry observerToLocal;
    double rMin = 0, rMax = 0, zMin = 0, zMax = 0;
};

SphereBounds makeBounds(double a, const SphereObject& s, const godel::Isometry& toObserver) {
    const godel::Isometry toLocal = godel::Isometry::movingToOrigin(a, s.centre);
    SphereBounds b{toLocal.compose(toObserver.inverse()), 1e300, 0, 1e300, -1e300};
    const godel::Isometry fromLocal = toObserver.compose(toLocal.inverse());
    const int nLat = 24, nLon = 48;
    for (int i = 0; i <= nLat; ++i)
        for (int j = 0; j < nLon; ++j) {
            const double th = kPi * i / nLat, ph = 2 * kPi * j / nLon;
            const Vec4 local(0, s.radius * std::sin(th) * std::cos(ph), s.radius * std::sin(th) * std::sin(ph),
                             s.radius * std::cos(th));
            const Vec4 x = fromLocal.apply(local);
            const double r = std::hypot(x(1), x(2));
            b.rMin = std::min(b.rMin, r);
            b.rMax = std::max(b.rMax, r);
            b.zMin = std::min(b.zMin, x(3));
            b.zMax = std::max(b.zMax, x(3));
        }
    // Samples are 7.5 degrees apart: widen by a fifth of the radius (the map is smooth and close
    // to an isometry of flat space on the scale of the object). If the sphere contains the axis,
    // rMin is 0.
    const double margin = 0.2 * s.radius * (1 + b.rMax);
    b.rMin = std::max(0.0, b.rMin - margin);
    b.rMax += margin;
    b.zMin -= margin;
    b.zMax += margin;
    const Vec3 c = fromLocal.apply(Vec4::Zero()).tail<3>();
    if (std::hypot(c(0), c(1)) < s.radius + margin) b.rMin = 0;
    return b;
}

// Affine intervals in [0, limit] where the ray's z lies in [zMin, zMax] and its radius
// r = r_max |sin(w l)| is at least rMin, in increasing order.
std::vector<std::pair<double, double>> candidateIntervals(const godel::OriginGeodesic& ray, const SphereBounds& b,
                                                          double limit) {
    std::vector<std::pair<double, double>> out;
    double lo = 0, hi = limit;
    const double k3 = ray.k3();
    if (std::abs(k3) > 1e-300) {
        const double l1 = b.zMin / k3, l2 = b.zMax / k3;
        lo = std::max(lo, std::min(l1, l2));
        hi = std::min(hi, std::max(l1, l2));
    } else if (b.zMin > 0 || b.zMax < 0) {
        return out;
    }
    if (lo >= hi) return out;
    const double rmax = ray.rMax();
    if (rmax < b.rMin) return out;
    if (b.rMin <= 0 || ray.omega() <= 0) {
        out.emplace_back(lo, hi);
        return out;
    }
    // |sin(w l)| >= c on [m pi + s, (m+1) pi - s] / w, s = asin(c).
    const double w = ray.omega(), sgap = std::asin(std::min(1.0, b.rMin / rmax));
    for (long m = static_cast<long>(std::floor(lo * w / kPi)); m * kPi / w < hi; ++m) {
        const double a0 = std::max(lo, (m * kPi + sgap) / w), a1 = std::min(hi, ((m + 1) * kPi - sgap) / w);
        if (a0 < a1) out.emplace_back(a0, a1);
    }
    return out;
}

// The first sphere the ray enters within maxAffine, and where: each sphere is sampled every
// `step` only inside its candidate intervals, then the entry refined (firstEntry). Object -1:
// none. `samples` counts the evaluations.
std::pair<int, double> firstSphereHit(const godel::OriginGeodesic& ray, const std::vector<SphereObject>& spheres,
                                      const std::vector<SphereBounds>& bounds, double step, double maxAffine,
                                      long long& samples) {
    int hitObject = -1;
    double hitAffine = 0;
    for (std::size_t k = 0; k < spheres.size(); ++k) {
        const SphereBounds& b = bounds[k];
        const double R2 = spheres[k].radius * spheres[k].radius;
        auto F = [&](double l) { return b.observerToLocal.apply(ray.cartesian(l)).tail<3>().squaredNorm() - R2; };
        const double limit = hitObject < 0 ? maxAffine : hitAffine;  // only nearer hits matter
        for (const auto& [lo, hi] : candidateIntervals(ray, b, limit)) {
            double l0 = lo, f0 = F(l0);
            if (f0 <= 0 && l0 > 0) f0 = 1e-300;  // bounds are outside the object: numerical edge
            double found = -1;
            while (found < 0 && l0 < hi) {
                const double l1 = std::min(l0 + step, hi);
                const double f1 = F(l1);
                ++samples;
                if (f0 > 0) found = firstEntry(F, l0, l1, f0, f1);
                l0 = l1;
                f0 = f1;
            }
            if (found >= 0) {
                if (hitObject < 0 || found < hitAffine) {
                    hitObject = static_cast<int>(k);
                    hitAffine = found;
                }
                break;  // intervals are in increasing order
            }
        }
    }
    return {hitObject, hitAffine};
}

// A ray that met nothing before maxAffine, where it was then (its emission time: the past end).
void recordBackground(PixelRecord& px, double maxAffine, const Vec4& end) {
    px.kind = PixelRecord::Background;
    px.stopReason = static_cast<std::int8_t>(StopReason::MaxAffine);
    px.affine = static_cast<float>(maxAffine);
    px.emissionTime = static_cast<float>(end(0));
}

// A ray whose first event on a sphere is x (the observer's chart), at affine parameter `affine`:
// the sphere's texture coordinates there and the emission time.
void recordSphereHit(PixelRecord& px, const std::vector<SphereObject>& spheres, int object, double affine,
                     const Vec4& x) {
    const Vec3 l = spheres[static_cast<std::size_t>(object)].placement->toLocal(x);
    px.kind = PixelRecord::Object;
    px.stopReason = static_cast<std::int8_t>(StopReason::Hit);
    px.object = static_cast<std::int16_t>(object);
    px.u = static_cast<float>(0.5 + std::atan2(l(1), l(0)) / (2 * kPi));
    px.v = static_cast<float>(std::acos(std::clamp(l(2) / l.norm(), -1.0, 1.0)) / kPi);
    px.affine = static_cast<float>(affine);
    px.emissionTime = static_cast<float>(x(0));
    px.frequencyRatio = 1;  // static emitter and observer: no shift in Goedel (docs/PHYSICS.md section 5)
}

}  // namespace

RenderResult renderGodelClosedForm(const Scene& scene, const ProgressCallback& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto godelA = scene.spacetime->godelRadius();
    if (!godelA) throw std::invalid_argument("the closed-form renderer needs the 'godel' metric");
    requireStaticSpheres(scene, "the closed-form per-pixel renderer");
    const double a = *godelA;
    scene.camera.validate();
    const Vec4 u = scene.observerVelocity;
    if (u.tail<3>().norm() > 0)
        throw std::invalid_argument(
            "the closed-form renderer takes a static observer (moving observers: use method numeric)");

    // Observer to the origin; its static frame goes to the coordinate frame there.
    const godel::Isometry toObserver = godel::Isometry::observerToOrigin(a, scene.observer);
    const godel::Isometry back = toObserver.inverse();
    const LocalFrame frame = LocalFrame::staticObserver(*scene.spacetime, scene.observer);
    const Camera cam = frameCamera(scene.camera, *scene.spacetime, frame);
    std::array<Vec3, 3> axes;  // the observer's frame vectors, seen at the origin
    for (int i = 0; i < 3; ++i) axes[i] = toObserver.pushForward(scene.observer, frame.e[i + 1]).tail<3>();

    // Per sphere: the isometry from the observer's chart to the sphere's own frame, and the
    // range of r and z that the sphere covers in the observer's chart (from surface samples,
    // widened by a margin), so each ray is followed only where it can meet the sphere.
    std::vector<SphereBounds> bounds;
    for (const auto& s : scene.spheres) bounds.push_back(makeBounds(a, s, toObserver));

    double minRadius = 1e300;
    for (const auto& s : scene.spheres) minRadius = std::min(minRadius, s.radius);
    const double step = 0.5 * minRadius;
    const double maxAffine = scene.settings.trace.maxAffine;

    RenderResult out = blankResult(cam);
    const RowBand band = rowsToTrace(scene.settings, cam);
    std::atomic<int> rowsDone{0};
    const int threads = renderThreads(scene.settings);
    const GodelLighting lighting(a, scene, std::min(1, scene.settings.windings));

    FirstError errors;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int j = band.begin; j < band.end; ++j) {
        errors.run([&] {
            for (int i = 0; i < cam.width; ++i) {
                PixelRecord& px = out.pixels[static_cast<std::size_t>(j) * cam.width + i];
                const Vec3 n = cam.direction(i, j);
                const Vec3 d = (n(0) * axes[0] + n(1) * axes[1] + n(2) * axes[2]).normalized();
                const double sinPsi = std::hypot(d(0), d(1));
                const godel::OriginGeodesic ray =
                    godel::OriginGeodesic::nullFromDirection(a, d(2), sinPsi, std::atan2(d(1), d(0)), -1);
                auto eventAt = [&](double l) { return back.apply(ray.cartesian(l)); };
                long long samples = 0;  // a tiny sphere and a long ray pass 2^31
                const auto [hitObject, hitAffine] =
                    firstSphereHit(ray, scene.spheres, bounds, step, maxAffine, samples);
                px.steps = static_cast<float>(samples);
                if (hitObject < 0) {
                    recordBackground(px, maxAffine, eventAt(maxAffine));
                    continue;
                }
                const Vec4 x = eventAt(hitAffine);
                recordSphereHit(px, scene.spheres, hitObject, hitAffine, x);
                // The null condition checked on the closed-form state (the metric is the same function
                // in the observer's chart): rounding level when the closed form is right.
                px.drift = static_cast<float>(
                    std::abs(scene.spacetime->hamiltonian(ray.cartesian(hitAffine), ray.momentumCartesian(hitAffine))));
                if (lighting.active()) {
                    const Vec3 light = lighting.at(x, static_cast<std::size_t>(hitObject));
                    for (int c = 0; c < 3; ++c) px.light[c] = static_cast<float>(light(c));
                }
            }
            // Inside run(): a callback that throws (RenderCancelled) stops the other rows too.
            const int done = ++rowsDone;
            if (progress && omp_get_thread_num() == 0) progress(static_cast<double>(done) / band.rows());
        });
    }
    errors.rethrow();
    if (progress) progress(1.0);
    summarise(out, t0, band);  // steps here: closed-form samples per ray
    return out;
}

}  // namespace lc
