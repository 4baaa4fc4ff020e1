// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Per-fragment exact intersection of a viewing ray with a triangle moving at constant
// velocity (seed 003 sect. 4.2), the polygon-distortion alternative (sect. 3.2) and the
// conservative screen footprint of an apparent triangle (sect. 4.1).
#include <array>
#include <functional>
#include <optional>

#include "core/numerics/select.hpp"
#include "core/sr/observer_camera.hpp"
#include "core/sr/lorentz.hpp"
#include "core/sr/mesh.hpp"

#include <cmath>

namespace lc::sr {

// Moller-Trumbore: the line origin + s dir against the triangle p0 p1 p2, both faces. Returns
// (s, u, v, hit): s the line parameter, u, v the barycentric weights of p1, p2, hit 1 when
// s > 0 and (u, v) lies in the triangle widened by edgeTolerance, 0 otherwise (also for a line
// in the triangle's plane: |det| < parallelTolerance |e1| |e2|). Written once for every scalar:
// double for intersectRest / intersectFlat, codegen::Expr for the shaders. The tolerances are
// the caller's because they depend on the precision: the CPU passes 0 and 1e-14; the GPU's float
// needs an edge tolerance (shared edges overlap instead of cracking; depth decides) and a
// coarser parallel test. With `rasterised` (the GPU's polygon distortion, where the rasteriser
// has already decided coverage) a marginal miss in float is clamped onto the triangle instead:
// u, v clamped, s the distance to that point if not positive, hit always 1.
template <class S>
Eigen::Matrix<S, 4, 1> triangleLineHit(const Eigen::Matrix<S, 3, 1>& origin, const Eigen::Matrix<S, 3, 1>& dir,
                                       const Eigen::Matrix<S, 3, 1>& p0, const Eigen::Matrix<S, 3, 1>& p1,
                                       const Eigen::Matrix<S, 3, 1>& p2, const S& edgeTolerance,
                                       const S& parallelTolerance, bool rasterised = false) {
    using std::abs;
    using std::max;
    using std::min;
    using std::sqrt;
    const Eigen::Matrix<S, 3, 1> e1 = p1 - p0, e2 = p2 - p0;
    const Eigen::Matrix<S, 3, 1> pvec = dir.cross(e2);
    const S det = e1.dot(pvec);
    // 1 unless the line lies in the plane (then det is replaced by 1 so nothing divides by 0).
    const S notParallel =
        ifPositive(parallelTolerance * sqrt(e1.squaredNorm()) * sqrt(e2.squaredNorm()) - abs(det), S(0.0), S(1.0));
    const S inv = ifPositive(notParallel, S(1.0) / ifPositive(notParallel, det, S(1.0)), S(0.0));
    const Eigen::Matrix<S, 3, 1> tvec = origin - p0;
    S u = tvec.dot(pvec) * inv;
    const Eigen::Matrix<S, 3, 1> qvec = tvec.cross(e1);
    S v = dir.dot(qvec) * inv;
    S s = e2.dot(qvec) * inv;
    if (rasterised) {
        u = min(max(u, S(0.0)), S(1.0));
        v = min(max(v, S(0.0)), S(1.0) - u);
        const Eigen::Matrix<S, 3, 1> onTriangle = (S(1.0) - u - v) * p0 + u * p1 + v * p2 - origin;
        s = ifPositive(s, s, sqrt(onTriangle.squaredNorm()));
        return Eigen::Matrix<S, 4, 1>(s, u, v, S(1.0));
    }
    // "not (x < -tol)" as ifPositive(-tol - x, 0, 1): the CPU's comparisons exactly, NaN included.
    const S inside =
        ifPositive(-edgeTolerance - u, S(0.0), S(1.0)) * ifPositive(u - (S(1.0) + edgeTolerance), S(0.0), S(1.0)) *
        ifPositive(-edgeTolerance - v, S(0.0), S(1.0)) * ifPositive(u + v - (S(1.0) + edgeTolerance), S(0.0), S(1.0));
    const S hit = notParallel * inside * ifPositive(s, S(1.0), S(0.0));
    return Eigen::Matrix<S, 4, 1>(s, u, v, hit);
}

using Vec2 = Eigen::Vector2d;

// A triangle at rest in S' with per-vertex normals.
struct RestTriangle {
    std::array<Vec3, 3> p;
    std::array<Vec3, 3> n;
    static RestTriangle fromMesh(const TriMesh& mesh, int triangle);
};

// The viewing ray of one pixel, i.e. the generator of the observer's past light cone, in S':
//   x'(sigma) = origin + sigma (-1, dir),  sigma >= 0 the S' light travel distance.
// doppler = nu_obs / nu_em for light arriving along it from anything at rest in S'.
struct RestRay {
    Vec4 origin;
    Vec3 dir;
    double doppler;
};
// viewDir: unit direction the observer looks along, in S (light arrives along -viewDir).
RestRay makeRestRay(const MovingFrame& frame, const Vec4& observer, const Vec3& viewDir);

struct RayHit {
    double sigma = 0.0;                // S' distance from observer to hit
    Vec3 barycentric = Vec3::Zero();   // weights of p[0], p[1], p[2]
    Vec3 restPoint = Vec3::Zero();     // hit in S'
    Vec4 emissionRest = Vec4::Zero();  // emission event in S'
    Vec4 emission = Vec4::Zero();      // same event in S; spatial part = apparent position
    double depth = 0.0;                // |x_is - x_obs| in S = t_obs - t_emission
    double doppler = 1.0;              // nu_obs / nu_em
};

// Intersection of the light-cone line with the static triangle in S' (seed eq. 15-16, solved
// Moller-Trumbore style), both faces, sigma > 0. Only sigma, barycentric and depth are
// filled (the hot path); completeHit adds the rest.
std::optional<RayHit> intersectRest(const RestTriangle& tri, const RestRay& ray);
void completeHit(RayHit& hit, const RestTriangle& tri, const RestRay& ray, const MovingFrame& frame);
// Convenience: full hit for one viewing ray.
std::optional<RayHit> intersectLocal(const RestTriangle& tri, const MovingFrame& frame, const Vec4& observer,
                                     const Vec3& viewDir);

// Polygon distortion: the flat triangle through the three apparent vertices in S.
std::array<Vec3, 3> apparentTriangle(const RestTriangle& tri, const MovingFrame& frame, const Vec4& observer);
struct FlatHit {
    double distance;
    Vec3 barycentric;
};
// Ray origin + s dir (s > 0) against a flat triangle, both faces.
std::optional<FlatHit> intersectFlat(const std::array<Vec3, 3>& tri, const Vec3& origin, const Vec3& dir);

// Inclusive pixel range; empty when x1 < x0 or y1 < y0.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    bool empty() const { return x1 < x0 || y1 < y0; }
    bool contains(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

// Screen footprint of an apparent triangle. Each viewing ray meets the rest-frame plane
// once, so the apparent triangle's image on the sky is the disk bounded by its apparent
// edges; those are circle arcs on the sky (aberration is conformal) and conic arcs on the
// screen. A conic arc whose end tangents meet ahead of both ends lies in the triangle of its
// ends and that apex (seed Fig. 8), so min-max of corners and apexes bounds every covered
// pixel centre. A triangle whose whole apparent image lies behind the camera or beyond a side
// of the view has no footprint (a bound on each frustum plane over the rest triangle). Where
// the tangent argument fails otherwise (a point behind the camera, tangents that do not meet
// properly, or the image containing the backward direction) the footprint is the whole
// screen, as in the seed.
struct ApparentFootprint {
    std::array<Vec2, 3> corners{};  // projected apparent vertices (pixels)
    std::array<Vec2, 3> apexes{};   // tangent intersection of edge (i, i+1)
    bool fullScreen = false;
    PixelRect rect;  // clipped to the image
};
// A panorama's footprint (no corners or apexes, never fullScreen) is the box in azimuth and
// elevation of the image's boundary, walked in steps of at most a pixel and widened by the largest
// step, over full rows from the pole when the image contains one.
ApparentFootprint apparentFootprint(const RestTriangle& tri, const MovingFrame& frame, const Vec4& observer,
                                    const ObserverCamera& camera, double marginPx = 1.0);

// The pixels of a panorama where a region of the sky may appear: the region bounded by the images
// of the triangle's edges, directionOf(p) giving the viewing direction (in S, any length, nullopt
// where it has none) of the point p on an edge between the corners; containsUp / containsDown say
// whether the region holds the camera's up / down pole. Conservative: a box in azimuth and
// elevation of the boundary walked in angular steps below one pixel, widened by the largest step
// and marginPx; the whole image when a direction is missing.
PixelRect panoramaFootprint(const std::array<Vec3, 3>& corners,
                            const std::function<std::optional<Vec3>(const Vec3&)>& directionOf, bool containsUp,
                            bool containsDown, const Camera& camera, double marginPx = 1.0);

}  // namespace lc::sr
