// SPDX-License-Identifier: BSD-3-Clause
#include "core/analysis/point_source_images.hpp"

#include "core/curvature/ray_bundle.hpp"
#include "core/numerics/parallel.hpp"
#include "core/render/render.hpp"
#include "core/scene/frame_camera.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <tuple>

namespace lc {

double PointSourceImages::totalMagnification() const {
    double sum = 0;
    for (const PointSourceImage& im : images) sum += std::abs(im.magnification);
    return sum;
}

double PointSourceImages::signedMagnification() const {
    double sum = 0;
    for (const PointSourceImage& im : images) sum += im.magnification;
    return sum;
}

namespace {

// One camera ray with its bundle, to where it escapes.
struct BundledRay {
    bool escaped = false;
    Vec3 escape = Vec3::Zero();  // chart direction
    Eigen::Matrix2d map;         // A on (a1, a2)
    Vec3 s1, s2;                 // the image's axes (frame)
    Vec3 a1, a2;                 // the source's axes (chart), a1 along the transported s1
};

class BundledTracer {
public:
    explicit BundledTracer(const Scene& scene)
        : st_(*scene.spacetime),
          frame_(observerFrame(scene)),
          screen_(frameCamera(scene).axes()),
          probe_(st_),
          g_(st_.metric(scene.observer)),
          options_(traceOptionsFor(scene)) {
        // Images are asked of the sky: objects do not block them here.
        options_.balls.clear();
        options_.escapeRadius = 0;
        options_.escapeLever = bundleEscapeLever(st_, scene.observer);
        // The direction settled far below the tolerance images are found to.
        options_.escapeAngle = 1e-3 * (options_.absTol + options_.relTol);
        bundleTolerance_ = bundleTolerance(options_);
    }

    Vec3 escapeOnly(const Vec3& n) const {
        const TraceResult r = traceGeodesic(st_, start(n), options_);
        return r.reason == StopReason::Escaped ? velocityDirection(r.end) : Vec3::Zero();
    }

    BundledRay withBundle(const Vec3& n) const {
        BundledRay out;
        const PhasePoint q = start(n);
        RayBundle bundle =
            RayBundle::alongView(probe_, frame_, g_, q, n, screen_.right, screen_.up, 1, bundleTolerance_);
        std::tie(out.s1, out.s2) = bundle.screen();
        const TraceResult r = traceGeodesic(st_, q, options_, [&](const Segment& seg) {
            bundle.advance(seg, seg.l1);
            return false;
        });
        if (r.reason != StopReason::Escaped) return out;
        const Vec4 v = st_.inverseMetric(r.end.x) * r.end.p;
        out.escaped = true;
        out.escape = v.tail<3>().normalized();
        out.map = escapeDirectionMap(bundle, v);
        std::tie(out.a1, out.a2) = sourceAxes(out.escape, bundle);
        return out;
    }

private:
    PhasePoint start(const Vec3& n) const { return {frame_.x, frame_.pastNullMomentum(st_, n)}; }
    Vec3 velocityDirection(const PhasePoint& q) const { return (st_.inverseMetric(q.x) * q.p).tail<3>().normalized(); }

    const Spacetime& st_;
    LocalFrame frame_;
    Camera::Axes screen_;
    CurvatureProbe probe_;
    Mat4 g_;
    TraceOptions options_;
    double bundleTolerance_ = 1e-5;
};

double angleBetween(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

// Newton's method on the image direction: the source's offset from the escape direction, on the
// source's axes, taken back to the image through A^-1, the step halved until the ray escapes nearer
// the source (near a critical curve a full step would cross it into another image's basin).
// Nullopt when no step gets nearer, or the rays leave the sky.
std::optional<PointSourceImage> refine(const BundledTracer& tracer, Vec3 n, const Vec3& source, double tolerance) {
    BundledRay ray = tracer.withBundle(n);
    if (!ray.escaped) return std::nullopt;
    double miss = angleBetween(ray.escape, source);
    for (int iteration = 0; iteration < 40; ++iteration) {
        if (miss <= tolerance) return PointSourceImage{n, LensingDistortion::of(ray.map).magnification, miss};
        // The source seen from the escape direction: tangent-plane components along a1, a2 of the
        // rotation taking one to the other (exact for any angle below pi).
        const Vec3 towards = (source - source.dot(ray.escape) * ray.escape).normalized() * miss;
        const Eigen::Vector2d offset(ray.a1.dot(towards), ray.a2.dot(towards));
        if (!(std::abs(ray.map.determinant()) > 1e-300)) return std::nullopt;
        Eigen::Vector2d turn = ray.map.inverse() * offset;
        if (turn.norm() > 0.1) turn *= 0.1 / turn.norm();  // a tenth of a radian at most
        bool nearer = false;
        for (int halving = 0; halving < 30 && !nearer; ++halving, turn *= 0.5) {
            const Vec3 tried = (n + turn(0) * ray.s1 + turn(1) * ray.s2).normalized();
            const BundledRay next = tracer.withBundle(tried);
            if (!next.escaped) continue;
            const double nextMiss = angleBetween(next.escape, source);
            if (nextMiss < miss) {
                n = tried;
                ray = next;
                miss = nextMiss;
                nearer = true;
            }
        }
        if (!nearer) break;
    }
    return miss <= tolerance ? std::optional<PointSourceImage>(
                                   PointSourceImage{n, LensingDistortion::of(ray.map).magnification, miss})
                             : std::nullopt;
}

}  // namespace

PointSourceImages findPointSourceImages(const Scene& scene, const Vec3& source, const PointSourceOptions& options) {
    if (!scene.spacetime->asymptoticallyFlat())
        throw std::invalid_argument("a point source at infinity needs an asymptotically flat metric; " +
                                    scene.spacetime->name() + " is not");
    if (!(source.norm() > 0) || !source.allFinite())
        throw std::invalid_argument("the point source's direction must be a finite, non-zero vector");
    const Vec3 s = source.normalized();
    const BundledTracer tracer(scene);
    // Escape directions are good to about the tracer's tolerance per step: no image is asked closer.
    const TraceOptions& trace = scene.settings.trace;
    const double tolerance = std::max(options.angleTolerance, 10 * (trace.absTol + trace.relTol));
    const Camera cam = frameCamera(scene);
    const int columns = std::max(options.seedColumns, 4), rows = std::max(columns / 2, 2);
    // The seeds' escape directions' angles from the source, on both cores.
    std::vector<double> miss(static_cast<std::size_t>(columns * rows), kPi);
    std::vector<Vec3> directions(miss.size());
    const int threads = renderThreads(scene.settings);
    FirstError errors;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int j = 0; j < rows; ++j)
        errors.run([&] {
            for (int i = 0; i < columns; ++i) {
                const std::size_t k = static_cast<std::size_t>(j * columns + i);
                directions[k] = cam.directionAt((i + 0.5) * cam.width / columns, (j + 0.5) * cam.height / rows);
                const Vec3 escape = tracer.escapeOnly(directions[k]);
                if (escape.squaredNorm() > 0) miss[k] = angleBetween(escape, s);
            }
        });
    errors.rethrow();
    // Local minima of the miss over the grid (8 neighbours) are the basins of the images.
    std::vector<std::size_t> seeds;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const std::size_t k = static_cast<std::size_t>(j * columns + i);
            if (miss[k] >= kPi) continue;
            bool least = true;
            for (int dj = -1; dj <= 1 && least; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const int ii = i + di, jj = j + dj;
                    if ((di || dj) && ii >= 0 && jj >= 0 && ii < columns && jj < rows &&
                        miss[static_cast<std::size_t>(jj * columns + ii)] < miss[k])
                        least = false;
                }
            if (least) seeds.push_back(k);
        }
    std::vector<std::optional<PointSourceImage>> refined(seeds.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int k = 0; k < static_cast<int>(seeds.size()); ++k)
        errors.run([&] {
            refined[static_cast<std::size_t>(k)] =
                refine(tracer, directions[seeds[static_cast<std::size_t>(k)]], s, tolerance);
        });
    errors.rethrow();
    PointSourceImages out;
    // Seeds of one basin converge to one image, as far apart as the tolerance allows (its angle
    // through A^-1, large only beside a critical curve): the nearest convergence is kept.
    const double sameImage = std::max(1e-9, 1e3 * tolerance);
    for (const auto& im : refined) {
        if (!im) continue;
        double x = 0, y = 0;
        if (!cam.project(im->direction, x, y) || x < 0 || y < 0 || x > cam.width || y > cam.height) continue;
        const auto same = std::find_if(out.images.begin(), out.images.end(), [&](const PointSourceImage& other) {
            return angleBetween(other.direction, im->direction) < sameImage;
        });
        if (same == out.images.end())
            out.images.push_back(*im);
        else if (im->residual < same->residual)
            *same = *im;
    }
    std::sort(out.images.begin(), out.images.end(), [](const PointSourceImage& a, const PointSourceImage& b) {
        return std::abs(a.magnification) > std::abs(b.magnification);
    });
    return out;
}

}  // namespace lc
