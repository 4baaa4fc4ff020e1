// SPDX-License-Identifier: BSD-3-Clause
#include "core/curvature/jacobi_map.hpp"

#include "core/curvature/ray_bundle.hpp"

#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace lc {
namespace {

namespace odeint = boost::numeric::odeint;
// x, p, then two deviation vectors (dx, dp) each.
using JacobiState = std::array<double, 24>;

Vec4 part(const JacobiState& s, int offset) { return Vec4(s[offset], s[offset + 1], s[offset + 2], s[offset + 3]); }
void put(JacobiState& s, int offset, const Vec4& v) {
    for (int i = 0; i < 4; ++i) s[static_cast<std::size_t>(offset + i)] = v(i);
}

// Hamilton's equations for H = 1/2 p g^-1 p and their linearisation along the ray
// (linearisedHamiltonFlow) for the two deviations.
struct JacobiFlow {
    const CurvatureProbe& probe;
    void operator()(const JacobiState& s, JacobiState& ds, double /*affine*/) const {
        const MetricJet jet = probe.jet(part(s, 0));
        const RayTerms terms(jet, part(s, 4));
        put(ds, 0, terms.v);
        put(ds, 4, Vec4(0.5 * terms.A.transpose() * terms.v));
        const Mat8 M = linearisedHamiltonFlow(jet, terms);
        for (int d = 8; d < 24; d += 8) {
            const Eigen::Map<const Eigen::Matrix<double, 8, 1>> deviation(s.data() + d);
            Eigen::Map<Eigen::Matrix<double, 8, 1>>(ds.data() + d) = M * deviation;
        }
    }
};

// Two unit vectors completing the unit `axis` to a right-handed orthonormal basis: the first along
// z x axis (y x axis when the axis is near z), the second axis x first.
std::pair<Vec3, Vec3> axesAround(const Vec3& axis) {
    const Vec3 first = (std::abs(axis(2)) < 0.9 ? Vec3::UnitZ() : Vec3::UnitY()).cross(axis).normalized();
    return {first, axis.cross(first)};
}

double side(const SourcePlane& plane, const JacobiState& s) {
    return plane.normal.dot(Vec3(s[1], s[2], s[3]) - plane.point);
}

}  // namespace

JacobiRayResult traceJacobiRay(const Spacetime& spacetime, const LocalFrame& observer, const Vec3& direction,
                               const SourcePlane& plane, const JacobiRayOptions& options) {
    const CurvatureProbe probe(spacetime);
    const Vec3 n = direction.normalized();
    const auto [s1, s2] = axesAround(n);
    const Mat4 g = spacetime.metric(observer.x);

    JacobiState s{};
    put(s, 0, observer.x);
    put(s, 4, pastNullMomentumAlong<double>(n, observer.e, g));
    const DeviationPair turns = viewTurns(g, observer, s1, s2);  // dx = 0, dp = g (s_a . e)
    put(s, 12, turns.block<4, 1>(4, 0));
    put(s, 20, turns.block<4, 1>(4, 1));

    JacobiRayResult r;
    const JacobiFlow flow{probe};
    auto stepper =
        odeint::make_dense_output(options.tolerance, options.tolerance, odeint::runge_kutta_dopri5<JacobiState>());
    const double start = side(plane, s);
    stepper.initialize(s, 0.0, 1e-2);
    JacobiState at = s;
    while (r.steps < options.maxSteps && stepper.current_time() < options.maxAffine) {
        stepper.do_step(std::ref(flow));
        ++r.steps;
        if (std::signbit(side(plane, stepper.current_state())) == std::signbit(start)) continue;
        // Crossed within the last step: bisect on the dense output for the crossing affine.
        double lo = stepper.previous_time(), hi = stepper.current_time();
        for (int i = 0; i < 200 && hi - lo > 1e-14 * std::max(1.0, std::abs(hi)); ++i) {
            const double mid = 0.5 * (lo + hi);
            stepper.calc_state(mid, at);
            (std::signbit(side(plane, at)) == std::signbit(start) ? lo : hi) = mid;
        }
        stepper.calc_state(hi, at);
        r.reached = true;
        r.affine = hi;
        break;
    }
    if (!r.reached) {
        at = stepper.current_state();
        r.affine = stepper.current_time();
    }
    r.x = part(at, 0);
    r.p = part(at, 4);
    // Each deviation moved along the ray onto the plane: dx - (normal.dx / normal.v) v, then its
    // components along two orthonormal axes of the plane.
    const Vec4 v = spacetime.inverseMetric(r.x) * r.p;
    const Vec3 vs = v.tail<3>();
    // The plane's axes as the screen's seen through it: a plane facing the other way (its normal
    // towards the observer) mirrors one, so that an unlensed image keeps det D > 0.
    const Vec3 facing = (plane.normal.dot(n) < 0 ? Vec3(-plane.normal) : plane.normal).normalized();
    const auto [a1, a2] = axesAround(facing);
    r.screenAxes[0] = a1;
    r.screenAxes[1] = a2;
    for (int c = 0; c < 2; ++c) {
        const Vec3 dx = part(at, 8 + 8 * c).tail<3>();
        const Vec3 onPlane = dx - (plane.normal.dot(dx) / plane.normal.dot(vs)) * vs;
        r.map(0, c) = a1.dot(onPlane);
        r.map(1, c) = a2.dot(onPlane);
    }
    return r;
}

}  // namespace lc
