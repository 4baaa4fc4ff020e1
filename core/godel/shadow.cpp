// SPDX-License-Identifier: BSD-3-Clause
#include "core/godel/shadow.hpp"

#include <cmath>

namespace lc::godel {

std::string lightStatusName(LightStatus s) {
    switch (s) {
        case LightStatus::Lit: return "lit";
        case LightStatus::Shadowed: return "shadowed";
        case LightStatus::BeyondHorizon: return "beyond_horizon";
        case LightStatus::InvalidInput: return "invalid_input";
    }
    return "?";
}

Occluder sphereOccluder(const Vec3& centre, double radius) {
    return [centre, radius](const Vec4& x0, const Vec4& x1) {
        const Vec3 p = x0.segment<3>(1), d = x1.segment<3>(1) - p;
        const double dd = d.squaredNorm();
        const double t = dd > 0 ? std::clamp((centre - p).dot(d) / dd, 0.0, 1.0) : 0.0;
        return (p + t * d - centre).squaredNorm() < radius * radius;
    };
}

ShadowTester::ShadowTester(double a, const Vec4& lightEvent)
    : a_(a),
      light_(lightEvent),
      toLight_(Isometry::movingToOrigin(a, lightEvent)),
      toWorld_(toLight_.inverse()),
      solver_(a) {}

LightResult ShadowTester::test(const Vec3& surface, const Occluder& occluder, const ShadowOptions& opt) const {
    LightResult res;
    if (!surface.allFinite()) {
        res.status = LightStatus::InvalidInput;
        res.message = "surface point has non-finite coordinates";
        return res;
    }
    const Vec4 local = toLight_.apply(Vec4(light_(0), surface(0), surface(1), surface(2)));
    ImageOptions io;
    io.maxWinding = opt.maxWinding;
    io.k0 = +1;  // light leaves the source towards the future
    const ImageSet set = solver_.solve(local.segment<3>(1), io);
    if (set.status == ImageStatus::BeyondHorizon) {
        res.status = LightStatus::BeyondHorizon;
        res.message = "the light is beyond the Goedel horizon of the surface point: no light ray connects them";
        return res;
    }
    if (set.status != ImageStatus::Ok) {
        res.status = LightStatus::InvalidInput;
        res.message = set.message;
        return res;
    }
    const int M = std::max(1, opt.segmentsPerRay);
    for (const Image& im : set.images) {
        ShadowRay sr;
        sr.image = im;
        const OriginGeodesic g = im.ray(a_);
        const Vec4 xl = g.cartesian(im.lambda);
        sr.arrivalEvent = toWorld_.apply(xl);
        sr.tangentWorld = toWorld_.pushForward(xl, g.tangentCartesian(im.lambda));
        // In the surface point's own frame (moved to the origin, where g = diag(1,-1,-1,-1)).
        // A ring (surface point on the light's axis) has no single direction: one representative.
        const Isometry toSurface = Isometry::movingToOrigin(a_, sr.arrivalEvent);
        const Vec4 k = toSurface.pushForward(sr.arrivalEvent, sr.tangentWorld);
        const Vec3 ks = k.segment<3>(1);
        sr.towardLight = ks.norm() > 0 ? Vec3(-ks / ks.norm()) : Vec3::Zero();
        if (occluder) {
            const double l0 = opt.endMargin * im.lambda, l1 = (1 - opt.endMargin) * im.lambda;
            Vec4 prev = toWorld_.apply(g.cartesian(l0));
            for (int i = 1; i <= M && !sr.occluded; ++i) {
                const Vec4 next = toWorld_.apply(g.cartesian(l0 + (l1 - l0) * i / M));
                sr.occluded = occluder(prev, next);
                prev = next;
            }
        }
        res.rays.push_back(sr);
    }
    for (std::size_t i = 0; i < res.rays.size(); ++i)
        if (!res.rays[i].occluded) {
            res.firstUnoccluded = int(i);
            break;
        }
    res.status = res.firstUnoccluded >= 0 ? LightStatus::Lit : LightStatus::Shadowed;
    if (res.rays.empty()) res.message = "no light ray up to the requested winding reaches the point";
    return res;
}

}  // namespace lc::godel
