#pragma once
// The black-hole shadow as the observer's camera sees it, measured by bisection between camera
// rays that fall in and rays that escape (not from pixels, so its accuracy does not depend on the
// image size): its edges along the camera's horizontal through the forward direction, its
// centre's offset and its height through that centre. The figures a paper plots against spin.
#include "core/scene/scene.hpp"

namespace lc {

struct ShadowSize {
    double leftDegrees = 0, rightDegrees = 0;  // edge angles from forward, each > 0
    double heightDegrees = 0;                  // through the centre, top plus bottom
    double widthDegrees() const { return leftDegrees + rightDegrees; }
    double offsetDegrees() const { return 0.5 * (rightDegrees - leftDegrees); }  // > 0: to the right
    // D (tan left + tan right): the width as impact parameters for an observer at distance D >> M.
    double widthImpact(double distance) const;
};

// Throws std::invalid_argument when the metric is not asymptotically flat or the camera's forward
// ray does not fall in (the camera does not look at the shadow). `angleTolerance` in radians.
ShadowSize measureShadow(const Scene& scene, double angleTolerance = 1e-9);

// Bardeen's edge-on width of the Kerr shadow seen from infinity, in units of M: the spread of
// the impact parameters of the two equatorial circular photon orbits, r = 2M(1 + cos(2/3 acos(-+a/M))).
double bardeenEdgeOnWidth(double mass, double spin);

}  // namespace lc
