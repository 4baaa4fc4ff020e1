// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Light anywhere (docs/PHYSICS.md section 4, seed 000 section 5.3, seed 001 section 5.3): move a static
// point light to the origin with an isometry; the rays that light a surface point are then the
// future-directed images (k0 = +1) of that point. Occlusion is tested along the closed-form rays.
#include "core/godel/images.hpp"

#include <functional>
#include <string>
#include <vector>

namespace lc::godel {

// True if something blocks the straight coordinate segment x0 -> x1 (world Cartesian chart). The
// ray is cut into short segments, so a coordinate-straight test is accurate enough.
using Occluder = std::function<bool(const Vec4& x0, const Vec4& x1)>;
// A coordinate ball |(X, Y, z) - centre| < radius of the world chart (static occluder).
Occluder sphereOccluder(const Vec3& centre, double radius);

enum class LightStatus { Lit, Shadowed, BeyondHorizon, InvalidInput };
std::string lightStatusName(LightStatus s);

struct ShadowRay {
    Image image;  // in the light's frame (k0 = +1, lambda from the light)
    bool occluded = false;
    Vec3 towardLight = Vec3::Zero();   // unit, surface point's frame: where the light comes from
    Vec4 tangentWorld = Vec4::Zero();  // dx/dlambda at the surface point, world chart, future
    Vec4 arrivalEvent = Vec4::Zero();  // world chart
};

struct LightResult {
    LightStatus status = LightStatus::Shadowed;
    std::string message;
    std::vector<ShadowRay> rays;  // every ray found up to maxWinding, sorted by lambda
    int firstUnoccluded = -1;     // index into rays, -1 if none
    bool lit() const { return status == LightStatus::Lit; }
};

struct ShadowOptions {
    int maxWinding = 1;
    int segmentsPerRay = 64;  // occlusion test resolution along each ray
    double endMargin = 1e-6;  // fraction of lambda skipped at both ends (the light, the surface)
};

// A static point light; the surface point's frame is the one Isometry::movingToOrigin defines.
class ShadowTester {
public:
    ShadowTester(double a, const Vec4& lightEvent);
    LightResult test(const Vec3& surfacePoint, const Occluder& occluder = {}, const ShadowOptions& opt = {}) const;
    const Isometry& toLight() const { return toLight_; }

private:
    double a_;
    Vec4 light_;
    Isometry toLight_, toWorld_;
    ImageSolver solver_;
};

}  // namespace lc::godel
