// SPDX-License-Identifier: BSD-3-Clause
#include "core/render/godel_lighting.hpp"

#include "core/colour/blackbody.hpp"
#include "core/colour/srgb.hpp"
#include "core/metrics/godel.hpp"

namespace lc {

GodelLighting::GodelLighting(double a, const Scene& scene, int maxWinding) : a_(a), scene_(scene) {
    options_.maxWinding = maxWinding;
    for (const auto& l : scene.lights) {
        const Vec3 srgb = colour::standardBlackbodyTable()->lookup(l.temperature, colour::ToneMap::ColourOnly);
        Vec3 linear;
        for (int k = 0; k < 3; ++k) linear(k) = colour::srgbDecode(srgb(k));
        lights_.push_back({godel::ShadowTester(a, l.position), l.intensity * linear});
    }
    for (const auto& s : scene.spheres) fromLocal_.push_back(godel::Isometry::movingOriginTo(a, s.centre));
}

Vec3 GodelLighting::at(const Vec4& x, std::size_t object) const {
    const GodelCartesian metric(a_);
    const Mat4 g = metric.metric(x);
    const Vec4 u = Vec4::Unit(0) / std::sqrt(g(0, 0));                         // static observer at the surface point
    auto spatial = [&](const Vec4& v) { return Vec4(v - v.dot(g * u) * u); };  // part orthogonal to u
    auto dot = [&](const Vec4& p, const Vec4& q) { return -p.dot(g * q); };    // positive on rest space

    // Outward normal: the local radial direction pushed from the sphere's chart to the world.
    const SphereObject& s = scene_.spheres[object];
    const Vec3 local = s.placement->toLocal(x);
    const godel::Isometry& fromLocal = fromLocal_[object];
    const Vec4 localEvent = fromLocal.inverse().apply(x);
    const Vec4 n = spatial(fromLocal.pushForward(localEvent, Vec4(0, local(0), local(1), local(2)).normalized()));

    auto occluder = [this](const Vec4& x0, const Vec4& x1) {
        for (const auto& o : scene_.spheres) {
            const double r2 = o.radius * o.radius;
            if (o.placement->toLocal(x0).squaredNorm() < r2 || o.placement->toLocal(x1).squaredNorm() < r2 ||
                o.placement->toLocal(0.5 * (x0 + x1)).squaredNorm() < r2)
                return true;
        }
        return false;
    };
    Vec3 sum = Vec3::Zero();
    for (const auto& light : lights_) {
        const godel::LightResult r = light.tester.test(x.tail<3>(), occluder, options_);
        for (const auto& ray : r.rays) {
            if (ray.occluded) continue;
            const Vec4 toward = -spatial(ray.tangentWorld);  // light arrives along the tangent
            const double c = dot(n, toward) / std::sqrt(dot(n, n) * dot(toward, toward));
            if (c > 0) sum += c * light.colour;
        }
    }
    return sum;
}

}  // namespace lc
