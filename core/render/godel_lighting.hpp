// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Local lighting in the Goedel universe (seed 000 section 5.3, seed 001 section 5.3): a point
// light anywhere reaches a surface point along the future-directed null rays found by the
// inverse problem after moving the light to the origin; each unoccluded ray adds a Lambert
// term, its cosine taken in the rest space of the static observer at the surface point. Lights
// beyond the surface point's horizon reach nothing from there and add nothing.
#include "core/godel/shadow.hpp"
#include "core/scene/scene.hpp"

namespace lc {

class GodelLighting {
public:
    GodelLighting(double a, const Scene& scene, int maxWinding = 1);
    bool active() const { return !lights_.empty(); }
    // Linear RGB light arriving at the surface of sphere `object` at world event x.
    Vec3 at(const Vec4& x, std::size_t object) const;

private:
    struct Light {
        godel::ShadowTester tester;
        Vec3 colour;  // linear RGB times intensity
    };
    double a_;
    const Scene& scene_;
    std::vector<Light> lights_;
    std::vector<godel::Isometry> fromLocal_;  // sphere chart -> world
    godel::ShadowOptions options_;
};

}  // namespace lc
