// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The black-hole shadow as the observer's camera sees it, measured by bisection between camera
// rays that fall in and rays that escape (not from pixels, so its accuracy does not depend on the
// image size). The shadow of a Kerr-Newman hole is symmetric under the reflection that flips the
// sky's component along e_theta (the photons' p_theta -> -p_theta); its symmetry line is found
// first (the midpoint of the vertical chord through the camera's forward direction), then the
// edges along it, the centre between them and the height through that centre. The figures a paper
// plots against spin (docs/PHYSICS.md section "Shadow measurement").
#include "core/scene/scene.hpp"

#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

namespace lc {

struct ShadowSize {
    // Elevation of the symmetry line above the camera's forward direction (0 when forward lies on
    // it, e.g. a camera pointed radially at the hole with up along the spin's projection).
    double centreUpDegrees = 0;
    // Edges along the symmetry line, from the point of it straight above or below forward; each > 0.
    double leftDegrees = 0, rightDegrees = 0;
    double heightDegrees = 0;  // across the symmetry line through the centre, top plus bottom
    // Bardeen's celestial coordinate alpha = -xi / sin(theta_o) (xi = L_z / E of the edge ray, in
    // units of M; > 0 on the camera's right) of each horizontal edge, from the edge ray's own
    // constants of motion, so exact at any distance; NaN where undefined (observer on the axis,
    // not a Kerr-Newman metric).
    double leftAlpha = std::numeric_limits<double>::quiet_NaN(), rightAlpha = std::numeric_limits<double>::quiet_NaN();
    // +1: the rays of the right edge co-rotate with the hole (L_z / spin > 0), -1: counter-rotate, 0: no spin.
    int rightEdgeSense = 0;
    // The estimated error of every edge angle above, degrees: the bisection's last bracket, its
    // ends confirmed by tracing them again 10 times tighter (measureShadow with the CPU tracer;
    // NaN from other edge finders).
    double edgeErrorDegrees = std::numeric_limits<double>::quiet_NaN();
    double widthDegrees() const { return leftDegrees + rightDegrees; }
    double offsetDegrees() const { return 0.5 * (rightDegrees - leftDegrees); }  // centre, > 0: to the right
    // D (tan left + tan right): the width as impact parameters for an observer at distance D >> M.
    double widthImpact(double distance) const;
};

// What measureShadow throws where a great circle through the camera's forward direction sees no
// sky at all (observers just outside a horizon): its edges are undefined, the outline is not.
struct NoSkyAlongGreatCircle : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

// Throws std::invalid_argument when the metric is not asymptotically flat or the camera's forward
// ray does not fall in (the camera does not look at the shadow). Bisection stops when the bracket
// is below `relativeTolerance` times the edge angle (and 1e-15 rad).
ShadowSize measureShadow(const Scene& scene, double relativeTolerance = 1e-11);

// One chord of the measurement: the angle from `axis` towards `towards` (orthogonal unit
// directions, components in the observer's frame, lc::observerFrame) at which rays stop falling
// in; throws when the ray along `axis` itself does not fall in. measureShadow bisects with the
// CPU tracer; the GPU tracer's finder (views/geodesic/gpu_shadow_edges.hpp) zooms in on pixel strips.
using ShadowEdgeFinder = std::function<double(const Vec3& axis, const Vec3& towards)>;
ShadowSize measureShadow(const Scene& scene, const ShadowEdgeFinder& edge);

// The shadow's whole outline: its edge along great circles from a point inside it (the centre
// measureShadow finds on the symmetry line) at `points` position angles, each edge to the
// relative tolerance asked. The curve is a closed loop in the observer's sky; a shadow larger than
// a hemisphere is fine (edges up to 180 degrees from the inside point), one that is not
// star-shaped about that point is refused. Directions are unit vectors in the observer's frame
// (lc::observerFrame components, what LocalFrame::pastNullMomentum takes).
struct ShadowOutline {
    Vec3 forward, right, up;  // the camera's axes (frame components), for the camera's own angles
    Vec3 inside;              // the point the great circles start from
    // True where the dark region is all but a small cap of sky (observers just outside a
    // horizon): `inside` is then a point of the sky and the radii run from it to the shadow.
    bool fromSky = false;
    std::vector<double> positionAngles;  // radians about `inside`, from the camera's right towards its up
    std::vector<double> radii;           // radians from `inside` to each edge point
    std::vector<Vec3> points;            // the edge points, in order of position angle
    double solidAngle = 0;               // of the shadow, steradians (from the integral of 1 - cos radius)
    Vec3 centroid;                       // the mean direction over the dark region (unit)
    // A point's angles as the camera sees it: polar angle from forward and azimuth from right
    // towards up, in degrees.
    double polarDegrees(std::size_t k) const;
    double azimuthDegrees(std::size_t k) const;
};

// Throws std::invalid_argument as measureShadow does, for points outside [8, 100000], and where
// the outline is not star-shaped about its inside point. Parallel over the scene's threads.
ShadowOutline traceShadowOutline(const Scene& scene, int points = 360, double relativeTolerance = 1e-10);

// Bardeen's edge-on width of the Kerr shadow seen from infinity, in units of M: the spread of
// the impact parameters of the two equatorial circular photon orbits, r = 2M(1 + cos(2/3 acos(-+a/M))).
double bardeenEdgeOnWidth(double mass, double spin);

}  // namespace lc
