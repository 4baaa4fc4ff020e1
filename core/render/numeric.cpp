// SPDX-License-Identifier: BSD-3-Clause
// The numeric path, for every metric (seed 000 section 4): per pixel the past-directed null
// geodesic is integrated (traceGeodesic) and each accepted step's dense-output segment is
// intersected with the spheres.
#include "core/render/render.hpp"

#include "core/accretion/thin_disk.hpp"
#include "core/curvature/ray_bundle.hpp"
#include "core/render/post_render.hpp"
#include "core/scene/sky.hpp"

#include "core/scene/frame_camera.hpp"
#include "core/render/godel_lighting.hpp"
#include "core/metrics/godel.hpp"
#include "core/numerics/parallel.hpp"
#include "core/numerics/roots.hpp"

#include <atomic>
#include <optional>
#include <chrono>
#include <omp.h>

namespace lc {
namespace {

// What a ray hit first, found inside one accepted integration step.
struct Hit {
    int object = -1;
    bool disk = false;  // object indexes Scene::disks
    double affine = 0;
    PhasePoint state;
    int planeCrossings = 0;  // equatorial-plane crossings before the hit (a disk image's order)
};

double sphereFunction(const SphereObject& s, const Vec4& x) {
    return s.placement->toLocal(x).squaredNorm() - s.radius * s.radius;
}

// Earliest entry into any sphere within the segment; grazing rays that enter and leave within
// one step are caught by firstEntry (steps held to radius / 2 near a sphere: traceOptionsFor).
bool intersectSegment(const std::vector<SphereObject>& spheres, const Segment& seg, Hit& hit) {
    hit.object = -1;
    for (std::size_t k = 0; k < spheres.size(); ++k) {
        const SphereObject& s = spheres[k];
        const double f0 = sphereFunction(s, seg.s0.x);
        if (f0 <= 0) continue;
        auto f = [&](double l) { return sphereFunction(s, seg.at(l).x); };
        const double l = firstEntry(f, seg.l0, seg.l1, f0, sphereFunction(s, seg.s1.x));
        if (l < 0) continue;
        if (hit.object < 0 || l < hit.affine) {
            hit.object = static_cast<int>(k);
            hit.affine = l;
            hit.state = seg.at(l);
        }
    }
    return hit.object >= 0;
}

// The first crossing of the equatorial plane z = 0 inside the segment that lands on a disk;
// crossings that miss every disk (inside the inner edge, beyond the outer) are counted.
bool intersectDisks(const std::vector<DiskObject>& disks, const Segment& seg, Hit& hit) {
    const double z0 = seg.s0.x(3), z1 = seg.s1.x(3);
    if (z0 == 0 || !((z0 > 0) != (z1 > 0) || z1 == 0)) return false;
    const double sign = z0 > 0 ? 1 : -1;
    auto f = [&](double l) { return sign * seg.at(l).x(3); };
    const double l = illinoisRoot(f, seg.l0, seg.l1, sign * z0, sign * z1, 1e-13);
    const PhasePoint q = seg.at(l);
    for (std::size_t k = 0; k < disks.size(); ++k) {
        const ThinDiskModel& m = *disks[k].model;
        const double r = m.radiusAt(q.x);
        if (r >= m.innerRadius() && r <= m.outerRadius()) {
            hit.object = static_cast<int>(k);
            hit.disk = true;
            hit.affine = l;
            hit.state = q;
            return true;
        }
    }
    ++hit.planeCrossings;
    return false;
}

void recordSphereHit(const Spacetime& st, const SphereObject& s, const Hit& hit, double scale,
                     const GodelLighting* lighting, PixelRecord& px) {
    const Vec3 l = s.placement->toLocal(hit.state.x);
    px.kind = PixelRecord::Object;
    px.u = static_cast<float>(0.5 + std::atan2(l(1), l(0)) / (2 * kPi));
    px.v = static_cast<float>(std::acos(std::clamp(l(2) / l.norm(), -1.0, 1.0)) / kPi);
    px.affine = static_cast<float>(hit.affine);
    px.emissionTime = static_cast<float>(hit.state.x(0));
    // Static emitter u = d/dt / sqrt(g_tt); the observer measures g(k, e0) = -1.
    const double gtt = st.metric(hit.state.x)(0, 0);
    px.frequencyRatio = gtt > 0 ? static_cast<float>(-scale * std::sqrt(gtt) / hit.state.p(0)) : 0.f;
    if (lighting) {
        const Vec3 light = lighting->at(hit.state.x, static_cast<std::size_t>(hit.object));
        for (int c = 0; c < 3; ++c) px.light[c] = static_cast<float>(light(c));
    }
}

// The disk's matter moves on its circular orbit: g from its 4-velocity (the observer measures
// g(k, e0) = -1 on the unscaled momentum, -scale on the traced one).
void recordDiskHit(const DiskObject& d, const Hit& hit, double scale, PixelRecord& px) {
    const ThinDiskModel& m = *d.model;
    const Vec4& x = hit.state.x;
    const double r = m.radiusAt(x);
    const double g = m.redshift(x, hit.state.p, -scale);
    px.kind = PixelRecord::Disk;
    px.u = static_cast<float>(wrapToUnit(std::atan2(x(2), x(1)) / (2 * kPi)));  // the chart azimuth
    px.v = static_cast<float>((r - m.innerRadius()) / (m.outerRadius() - m.innerRadius()));
    px.affine = static_cast<float>(hit.affine);
    px.emissionTime = static_cast<float>(x(0));
    px.frequencyRatio = static_cast<float>(g);
    px.diskRadius = static_cast<float>(r);
    px.intensity = static_cast<float>(g * g * g * g * m.flux(r) / m.maxFlux());
    px.order = static_cast<std::int8_t>(std::min(hit.planeCrossings, 127));
}

// A ray's bundle at its end, read as the image element's lensing: for a source at infinity (sky)
// or on the thin-lens plane through the hit (objects, disks); other pixels have no source.
void recordLensing(const Spacetime& st, const RayBundle& bundle, const TraceResult& r, const Hit& hit,
                   const Vec4& observer, PixelRecord& px) {
    Eigen::Matrix2d A;
    if (r.reason == StopReason::Hit) {
        const Vec4 v = st.inverseMetric(hit.state.x) * hit.state.p;
        A = sourcePlaneMap(bundle, v, hit.state.x.tail<3>() - observer.tail<3>());
    } else if (r.reason == StopReason::Escaped) {
        A = escapeDirectionMap(bundle, st.inverseMetric(r.end.x) * r.end.p);
    } else {
        return;
    }
    const LensingDistortion d = LensingDistortion::of(A);
    px.magnification = static_cast<float>(d.magnification);
    px.shear = static_cast<float>(d.shear);
    px.rotation = static_cast<float>(d.rotation);
}

Vec3 skyDirection(const Spacetime& st, const PhasePoint& q) {
    // Direction the light came from: the spatial part of the contravariant tangent.
    const Vec4 k = st.inverseMetric(q.x) * q.p;
    return k.tail<3>().normalized();
}

}  // namespace

TraceOptions traceOptionsFor(const Scene& scene) {
    TraceOptions opt = scene.settings.trace;
    double extent = 0;
    for (const auto& s : scene.spheres) {
        // A grazing ray cannot cross a sphere inside one step: near a translated (round in the
        // chart) sphere by the distance rule of TraceOptions::balls, elsewhere by radius / 2.
        if (dynamic_cast<const TranslationPlacement*>(s.placement.get())) {
            opt.balls.push_back({-s.placement->toLocal(Vec4::Zero()), s.radius});
        } else {
            const double cap = 0.5 * s.radius;
            opt.maxStep = opt.maxStep > 0 ? std::min(opt.maxStep, cap) : cap;
        }
        extent = std::max(extent, s.centre.tail<3>().norm() + s.radius);
    }
    for (const auto& d : scene.disks) {
        extent = std::max(extent, d.model->chartRadius(d.model->outerRadius()));
    }
    // Beyond every object an outgoing ray can only meet the sky.
    if (opt.escapeRadius <= 0) opt.escapeRadius = extent;
    // A bundle's direction map settles later than its direction (TraceOptions::escapeLever).
    if (scene.settings.magnification) opt.escapeLever = bundleEscapeLever(*scene.spacetime, scene.observer);
    // The sky is looked up in the escape direction: a hundredth of a pixel is enough.
    if (opt.escapeAngle <= 0) {
        const Camera& cam = scene.camera;
        const double pixel = std::min(cam.fovXDeg / cam.width, cam.fovYDeg / cam.height) * kPi / 180;
        opt.escapeAngle = std::clamp(0.01 * pixel, 1e-15, 1e-2);
    }
    return opt;
}

void toSkyUv(const Vec3& d, float& u, float& v) {
    const Vec2 uv = skyUv(d);
    u = static_cast<float>(uv(0));
    v = static_cast<float>(uv(1));
}

namespace {

// Whether a ray's step meets a sphere or a disk of the scene; hit is the nearer one (the smaller
// affine length) when it meets both.
bool firstHitIn(const Scene& scene, const Segment& seg, Hit& hit) {
    if (!scene.spheres.empty() && intersectSegment(scene.spheres, seg, hit)) {
        Hit diskHit = hit;
        if (!scene.disks.empty() && intersectDisks(scene.disks, seg, diskHit) && diskHit.affine < hit.affine)
            hit = diskHit;
        return true;
    }
    return !scene.disks.empty() && intersectDisks(scene.disks, seg, hit);
}

}  // namespace

RenderResult renderNumeric(const Scene& scene, const ProgressCallback& progress) {
    const auto t0 = std::chrono::steady_clock::now();
    const Spacetime& st = *scene.spacetime;
    scene.camera.validate();
    const LocalFrame frame = observerFrame(scene);
    const Camera cam = frameCamera(scene.camera, st, frame);
    requireStaticSpheres(scene, "the numeric ray tracer");

    const TraceOptions opt = traceOptionsFor(scene);

    RenderResult out = blankResult(cam);
    out.lensing = scene.settings.magnification;
    const RowBand band = rowsToTrace(scene.settings, cam);
    std::atomic<int> rowsDone{0};
    const int threads = renderThreads(scene.settings);
    // Lighting needs the light's rays to the surface: closed form in Goedel, none elsewhere yet.
    const auto godelA = st.godelRadius();
    const std::unique_ptr<GodelLighting> lighting =
        godelA && !scene.lights.empty()
            ? std::make_unique<GodelLighting>(*godelA, scene, std::min(1, scene.settings.windings))
            : nullptr;

    // Magnification: every ray carries a bundle, its equations from the metric's exact jet.
    const std::unique_ptr<CurvatureProbe> probe =
        scene.settings.magnification ? std::make_unique<CurvatureProbe>(st) : nullptr;
    const Mat4 gObserver = st.metric(scene.observer);
    const double bundles = bundleTolerance(opt);
    const Camera::Axes screen = cam.axes();

    FirstError errors;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int j = band.begin; j < band.end; ++j) {
        errors.run([&] {
            for (int i = 0; i < cam.width; ++i) {
                PixelRecord& px = out.pixels[static_cast<std::size_t>(j) * cam.width + i];
                const Vec3 n = cam.direction(i, j);
                PhasePoint start{scene.observer, frame.pastNullMomentum(st, n)};
                // Affine limits and tolerances assume momenta of order one; a fast observer's
                // rays carry energies from 1/(2 gamma) to 2 gamma. Rescale to |p_t| = 1 (a null
                // ray's path does not depend on the scale) and remember the factor for the
                // frequency ratio, which the observer measures on the unscaled momentum.
                const double pt = std::abs(start.p(0));
                const double scale = pt > 1e-6 * start.p.norm() ? 1 / pt : 1 / start.p.norm();
                start.p *= scale;
                std::optional<RayBundle> bundle;
                if (probe)
                    bundle.emplace(RayBundle::alongView(*probe, frame, gObserver, start, n, screen.right, screen.up,
                                                        scale, bundles));
                Hit hit;
                const TraceResult r = traceGeodesic(st, start, opt, [&](const Segment& seg) {
                    const bool stop = firstHitIn(scene, seg, hit);
                    if (bundle) bundle->advance(seg, stop ? hit.affine : seg.l1);
                    return stop;
                });
                px.stopReason = static_cast<std::int8_t>(r.reason);
                px.drift = static_cast<float>(r.maxHamiltonianDrift);
                px.steps = static_cast<float>(r.steps);
                px.affine = static_cast<float>(r.affine);
                px.emissionTime = static_cast<float>(r.end.x(0));
                switch (r.reason) {
                    case StopReason::Hit:
                        if (hit.disk)
                            recordDiskHit(scene.disks[static_cast<std::size_t>(hit.object)], hit, scale, px);
                        else
                            recordSphereHit(st, scene.spheres[static_cast<std::size_t>(hit.object)], hit, scale,
                                            lighting.get(), px);
                        px.object = static_cast<std::int16_t>(hit.object);
                        break;
                    case StopReason::Escaped:
                    case StopReason::OtherEnd: {  // this side's sky or the far side's (end 1)
                        const bool farSide = r.reason == StopReason::OtherEnd;
                        px.kind = PixelRecord::Sky;
                        px.end = farSide ? 1 : 0;
                        toSkyUv(farSide ? st.otherEndDirection(r.end) : skyDirection(st, r.end), px.u, px.v);
                        // Light from a source at rest far away: nu_obs / nu_inf = (-p.u_obs) / (-p_t),
                        // p_t taken where the ray left (conserved all along in a stationary metric).
                        px.frequencyRatio = static_cast<float>(-scale / r.end.p(0));
                        break;
                    }
                    case StopReason::Horizon:
                        px.kind = PixelRecord::Horizon;
                        px.frequencyRatio = 0;  // no light comes out of a horizon
                        break;
                    case StopReason::MaxAffine: px.kind = PixelRecord::Background; break;
                    default: px.kind = PixelRecord::Failed; break;
                }
                if (bundle) recordLensing(st, *bundle, r, hit, scene.observer, px);
            }
            // Inside run(): a callback that throws (RenderCancelled) stops the other rows too.
            const int done = ++rowsDone;
            if (progress && omp_get_thread_num() == 0) progress(static_cast<double>(done) / band.rows());
        });
    }
    errors.rethrow();
    if (progress) progress(1.0);

    summarise(out, t0, band);
    return out;
}

}  // namespace lc
