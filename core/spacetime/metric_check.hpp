// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Checks that any metric can serve at an event: finite, with finite derivatives, Lorentzian.
// Scene files run them at the observer's event, `lightcone metric check` wherever asked, so a
// metric typed as text that is singular or has the wrong signature there is refused by name.
#include "core/spacetime/spacetime.hpp"

#include <string>
#include <vector>

namespace lc {

// The name of component (m, n) in a chart: "g_tt", "g_t,phi".
std::string componentName(const std::array<std::string, 4>& coordinates, int m, int n);

// The signs of g's eigenvalues at x, largest first, in the program's convention: "(+,-,-,-)"
// for a Lorentzian metric, 0 for an eigenvalue below 1e-14 of the largest; "(undefined)" where
// g is not finite.
std::string signatureAt(const Spacetime& st, const Vec4& x);

// Why the metric cannot serve at x ("g_tt = nan", "dg_xy/dz = inf", "singular (det g = 0)",
// "not Lorentzian: (+,+,-,-)"), or "" when it can.
std::string metricProblemAt(const Spacetime& st, const Vec4& x);

}  // namespace lc

namespace lc {

// The Lie derivative of g along a Killing candidate xi (given with its Jacobian d_m xi^k) at x:
// (L_xi g)_mn = xi^k d_k g_mn + g_kn d_m xi^k + g_mk d_n xi^k, zero everywhere for a symmetry.
Mat4 lieDerivative(const Spacetime& st, const Vec4& x, const Vec4& xi, const Mat4& dxi);

// Whether rotations about the chart's axis 1, 2 or 3 (x, y, z; Cartesian charts) leave g
// unchanged at every event of `samples`, to 1e-9 of g's size there.
bool rotationSymmetricAbout(const Spacetime& st, const std::vector<Vec4>& samples, int axis);

// Whether rotations about the chart's z axis (xi = -y d_x + x d_y, Cartesian charts) leave g
// unchanged at every event of `samples`, to 1e-9 of g's size there.
bool rotationSymmetricAboutZ(const Spacetime& st, const std::vector<Vec4>& samples);

// What keeps circular equatorial orbits from being defined, "" when nothing does: d/dt and
// rotations about z must leave g unchanged and z -> -z must mirror it, at every event of
// `samples` where g is finite (to 1e-9 of g's size there), and g must be finite at most of them.
std::string whyNoCircularOrbits(const Spacetime& st, const std::vector<Vec4>& samples);

}  // namespace lc
