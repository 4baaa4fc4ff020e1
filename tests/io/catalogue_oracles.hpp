// SPDX-License-Identifier: BSD-3-Clause
// Measurements the catalogue tests (test_metric_catalogue*.cpp) make on a metric file as a user
// traces it: the shadow's critical impact parameter, a photon sphere found by tangent launches,
// the event where a ray crosses a surface. Each one only traces rays; the published closed forms
// they are compared with are typed in the tests.
#pragma once

#include "core/spacetime/integrator.hpp"
#include "core/spacetime/scattering.hpp"
#include "readers/io/metric_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>

namespace lc::catalogue_test {

inline const std::string kCatalogue = std::string(LIGHTCONE_SOURCE_DIR) + "/data/metrics/";

inline std::shared_ptr<const formula::FormulaMetric> catalogueMetric(const std::string& stem,
                                                                     const std::map<std::string, double>& values = {}) {
    return io::loadFormulaMetric(kCatalogue + stem + ".json", values);
}

inline TraceOptions accurateTrace() {
    TraceOptions opt;
    opt.stepper = StepperKind::Dopri87;
    opt.absTol = opt.relTol = 1e-11;
    return opt;
}

// One row of docs/METRICS.md's table: relative difference, or absolute where the published value is 0.
inline void report(const std::string& metric, const std::string& quantity, double published, double ours) {
    std::printf("| %s | %s | %.10g | %.10g | %.1e |\n", metric.c_str(), quantity.c_str(), published, ours,
                std::abs(ours - published) / (published == 0 ? 1 : std::abs(published)));
}

// Bisects a predicate that holds at `holds` and not at `fails` to `resolution` relative.
inline double bisectPredicate(const std::function<bool(double)>& predicate, double holds, double fails,
                              double resolution = 1e-9) {
    EXPECT_TRUE(predicate(holds)) << holds;
    EXPECT_FALSE(predicate(fails)) << fails;
    while (std::abs(fails - holds) > resolution * std::abs(holds)) {
        const double mid = 0.5 * (holds + fails);
        (predicate(mid) ? holds : fails) = mid;
    }
    return 0.5 * (holds + fails);
}

// A future-directed null ray at (r0, 0, 0) moving inwards with L/E = b exactly, for metrics whose
// rays do not come from infinity (a cosmological horizon, anti-de Sitter's boundary): p_t = 1,
// p_y = b/r0 (so (x p_y - y p_x)/p_t = b), p_x from the null condition, the root with k^x < 0.
inline PhasePoint inwardRay(const Spacetime& st, double r0, double b) {
    PhasePoint ray;
    ray.x = Vec4(0, r0, 0, 0);
    ray.p = Vec4(1, 0, b / r0, 0);
    const Mat4 gi = st.inverseMetric(ray.x);
    const double A = gi(1, 1), B = 2 * (gi(1, 0) * ray.p[0] + gi(1, 2) * ray.p[2]), C = ray.p.dot(gi * ray.p);
    const double disc = B * B - 4 * A * C;
    EXPECT_GE(disc, 0) << "no null ray with that impact parameter at " << r0;
    for (const double sign : {+1.0, -1.0}) {
        ray.p[1] = (-B + sign * std::sqrt(disc)) / (2 * A);
        const Vec4 k = gi * ray.p;
        if (k[1] < 0 && k[0] > 0) return ray;
    }
    ADD_FAILURE() << "no future-directed inward null ray at " << r0;
    return ray;
}

// The impact parameter L/E between rays that fall in and rays that turn back, for rays sent
// along +x in the equator from `distance`. `fallsIn` reads the end of the trace (default: stopped
// at the horizon), for metrics whose rays also stop elsewhere (a cosmological horizon).
// Metrics without a sky start rays inwards at radius `distance` instead (inwardRay).
inline double criticalImpact(const Spacetime& st, double captured, double escapes, double distance = 1e4,
                             const std::function<bool(const TraceResult&)>& fallsIn = {}) {
    TraceOptions opt = accurateTrace();
    if (!st.asymptoticallyFlat()) opt.maxAffine = 1e3;  // rays that turn back end at a horizon or go far out
    return bisectPredicate(
        [&](double b) {
            const PhasePoint start =
                st.asymptoticallyFlat() ? impactParameterRay(st, b, distance) : inwardRay(st, distance, b);
            const TraceResult r = traceGeodesic(st, start, opt);
            return fallsIn ? fallsIn(r) : r.reason == StopReason::Horizon;
        },
        captured, escapes);
}

// A future-directed null ray at x whose covariant spatial momentum is pSpatial (Lightcone's
// signature +,-,-,-: a ray moving along +x has p_x = -1 in flat space): p_t from the null
// condition, the root with k^t > 0 (k^t < 0 when `past`: the camera's rays).
inline PhasePoint nullRayAt(const Spacetime& st, const Vec4& x, const Vec3& pSpatial, bool past = false) {
    const Mat4 gi = st.inverseMetric(x);
    const Vec4 q(0, pSpatial.x(), pSpatial.y(), pSpatial.z());
    const double A = gi(0, 0), B = 2 * gi.row(0).dot(q), C = q.dot(gi * q);
    const double disc = B * B - 4 * A * C;
    EXPECT_GE(disc, 0) << "no null ray with that spatial momentum";
    for (const double sign : {+1.0, -1.0}) {
        PhasePoint ray{x, q};
        ray.p[0] = (-B + sign * std::sqrt(disc)) / (2 * A);
        if ((past ? -1 : 1) * (gi * ray.p)[0] > 0) return ray;
    }
    ADD_FAILURE() << "no null ray with that spatial momentum and time direction";
    return {x, q};
}

// Where a traced ray first crosses level(state) = 0 (a sign change from its start); nullopt if
// it stops first. The step that crosses is found by tracing; the crossing inside it by bisection
// to 1e-14 in affine parameter, each trial state traced afresh from the step's start (the
// integrator ends a trace exactly on its affine limit), so it is as accurate as the trace itself,
// not as the step's interpolant.
inline std::optional<PhasePoint> traceUntil(const Spacetime& st, const PhasePoint& start,
                                            const std::function<double(const PhasePoint&)>& level,
                                            TraceOptions opt = accurateTrace(), double maxAffine = 1e4) {
    opt.maxAffine = maxAffine;
    const double startSign = level(start) > 0 ? 1 : -1;
    std::optional<Segment> crossed;
    traceGeodesic(st, start, opt, [&](const Segment& s) {
        if (startSign * level(s.s1) > 0) return false;
        crossed = s;
        return true;
    });
    if (!crossed) return std::nullopt;
    const auto tracedTo = [&](double dl) {
        TraceOptions part = opt;
        part.maxAffine = dl;
        return traceGeodesic(st, crossed->s0, part).end;
    };
    double a = 0, b = crossed->l1 - crossed->l0;
    while (b - a > 1e-14 * std::max(1.0, std::abs(crossed->l1))) {
        const double mid = 0.5 * (a + b);
        (startSign * level(tracedTo(mid)) > 0 ? a : b) = mid;
    }
    return tracedTo(0.5 * (a + b));
}

inline double chartRadius(const PhasePoint& q) { return q.x.tail<3>().norm(); }
inline double cylinderRadius(const PhasePoint& q) { return std::hypot(q.x[1], q.x[2]); }

// The radius of a circular photon orbit's surface (a photon sphere, or a cylinder) by tangent
// launches: a null ray sent along +y from (radius, 0, 0) first moves towards larger r^2/f (the
// orbit sits at its extremum), so it leaves outwards on one side of the orbit and inwards on the
// other, whether the orbit is unstable (Schwarzschild's 3M) or stable (Melvin's). `radiusOf` labels
// the surfaces. The metric must be diagonal in its chart at the launch point, so p_y alone is
// tangent. Bisected to 1e-8 relative: a stable orbit's rays swing by twice their offset.
inline double photonOrbitByTangentLaunch(const Spacetime& st, double inside, double outside,
                                         const std::function<double(const PhasePoint&)>& radiusOf = chartRadius) {
    const auto movesOutwards = [&](double radius) {
        const PhasePoint start = nullRayAt(st, Vec4(0, radius, 0, 0), Vec3(0, -1, 0));
        const auto left = traceUntil(
            st, start, [&](const PhasePoint& q) { return std::abs(radiusOf(q) - radius) - 1e-9 * radius; },
            accurateTrace(), 1e3 * radius);
        return left && radiusOf(*left) > radius;  // never left: on the orbit, within its swing
    };
    const bool insideGoesOut = movesOutwards(inside);
    return bisectPredicate([&](double r) { return movesOutwards(r) == insideGoesOut; }, inside, outside, 1e-8);
}

}  // namespace lc::catalogue_test
