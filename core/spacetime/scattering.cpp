// SPDX-License-Identifier: BSD-3-Clause
#include "core/spacetime/scattering.hpp"

#include <stdexcept>

namespace lc {
namespace {

// Future-directed p_t for p = (p_t, -1, 0, 0) at x: the null condition is a quadratic in p_t.
double nullEnergy(const Spacetime& st, const Vec4& x) {
    const Mat4 gi = st.inverseMetric(x);
    const double A = gi(0, 0), B = -2 * gi(0, 1), C = gi(1, 1);
    const double disc = B * B - 4 * A * C;
    if (!(disc >= 0) || A == 0) throw std::runtime_error("no null ray along +x at the start event");
    for (double sgn : {+1.0, -1.0}) {
        const double pt = (-B + sgn * std::sqrt(disc)) / (2 * A);
        const double kt = gi(0, 0) * pt - gi(0, 1);  // k^t = g^{t mu} p_mu
        if (kt > 0 && pt > 0) return pt;
    }
    throw std::runtime_error("no future-directed null ray along +x at the start event");
}

Vec3 travelDirection(const Vec4& p) { return -p.tail<3>().normalized(); }

}  // namespace

PhasePoint impactParameterRay(const Spacetime& st, double b, double distance) {
    PhasePoint q;
    q.x = Vec4(0, -distance, b, 0);
    double pt = 1;
    for (int it = 0; it < 50; ++it) {
        pt = nullEnergy(st, q.x);
        const double y = b * pt;
        if (std::abs(y - q.x(2)) <= 1e-16 * std::abs(b)) break;
        q.x(2) = y;
    }
    q.p = Vec4(pt, -1, 0, 0);
    return q;
}

DeflectionResult measureDeflection(const Spacetime& st, const PhasePoint& start, const TraceOptions& opt) {
    DeflectionResult out;
    out.impact = (start.x(1) * start.p(2) - start.x(2) * start.p(1)) / start.p(0);
    Vec3 previous = travelDirection(start.p);
    // Signed turning about the initial orbital normal: the covariant direction can wiggle
    // (chart terms), and only the signed sum gives the net planar deflection.
    Vec3 normal = start.x.tail<3>().cross(previous);
    normal = normal.norm() > 0 ? normal.normalized() : Vec3(0, 0, 1);
    double turned = 0;
    out.trace = traceGeodesic(st, start, opt, [&](const Segment& seg) {
        const Vec3 d = travelDirection(seg.s1.p);
        turned += std::atan2(previous.cross(d).dot(normal), previous.dot(d));
        previous = d;
        return false;
    });
    const Vec3 d0 = travelDirection(start.p), d1 = travelDirection(out.trace.end.p);
    out.deflection = std::abs(turned);
    out.angleBetween = std::atan2(d0.cross(d1).norm(), d0.dot(d1));
    return out;
}

}  // namespace lc
