// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The constants of a geodesic that the tracer holds (docs/PHYSICS.md section 7b): H = 1/2 p.g^-1 p,
// p . xi for every Killing field xi the metric declares (Spacetime::symmetries: d/dt, rotations
// about z, all rotations) and a spinning Kerr-Newman hole's Carter constant. A Runge-Kutta step
// keeps none of them but p_t exactly (the angular momenta are bilinear in x and p, H and Carter's
// quadratic in p), and near an unstable photon orbit their drift is what the instability
// amplifies: the ray ends on a neighbouring orbit. Restoring them after every accepted step leaves
// only an error along the exact orbit, which the instability does not amplify.
#include "core/spacetime/spacetime.hpp"

#include <array>
#include <optional>

namespace lc {

class ConstantsOfMotion {
public:
    // The constants' values at `start`, where they are held; none held for a metric declaring no
    // symmetry but H.
    ConstantsOfMotion(const Spacetime& spacetime, const PhasePoint& start);
    // Within the region where light can orbit (kOrbitRegion), moves p (x stays) by the smallest
    // change (Euclidean in the chart's components) that gives every constant its starting value to
    // first order: one Newton step, exact for the linear p . xi, leaving H and Carter's off by the
    // square of their drift. Conditions dependent at x (three rotations give two conditions on p)
    // or nearly so are dropped. v = g^-1 p at q (the tracer's stop tests have it). Returns whether
    // p changed.
    bool restore(PhasePoint& q, const Vec4& v) const;
    // How many constants are held (H included): at most 5, at most 4 independent at a point.
    int count() const { return killingCount_ + (carterSpin_ != 0) + 1; }
    // Carter's constant of a Kerr-Newman hole of spin a along z (outgoing Kerr-Schild chart) at q,
    // with mass^2 = 2 H0: Q = p_theta^2 + cos^2(theta) (a^2 (mass^2 - E^2) + L_z^2 / sin^2(theta)),
    // E = p_t, L_z = x p_y - y p_x, theta and r Boyer-Lindquist's, p_theta = p . d x / d theta at
    // fixed r and Kerr-Schild azimuth. `gradient`: dQ/dp with H0 fixed. None within 1e-3 rad of
    // the axis, where L_z^2 / sin^2(theta) is a ratio of small numbers.
    static std::optional<double> carterConstant(double a, double H0, const PhasePoint& q, Vec4* gradient = nullptr);

private:
    static constexpr double kLargestChange = 1e-3;  // of |p|: more is no drift
    // Asymptotically flat metrics: held only within this many capture radii of the centre, where
    // light can orbit, and outside the core where the metric is not analytic (FarField::size:
    // Kerr's ring, through whose disk the chart passes to its r < 0 sheet). Farther out nothing
    // amplifies a drift, and holding L through p would turn the ray by its position's error over
    // the distance (b = 10 M's deflection error 20x larger held out to 12 M: docs/PHYSICS.md 7b).
    static constexpr double kOrbitRegion = 1.5;
    // Killing field i at x: d/dt, or the rotation about axes_[i].
    Vec4 killingField(int i, const Vec4& x) const;

    const Spacetime& spacetime_;
    int killingCount_ = 0;
    std::array<Vec3, 4> axes_{};  // per field: zero for d/dt, else the rotation's axis
    Vec4 killingValues_ = Vec4::Zero();
    double carterSpin_ = 0;  // a spinning Kerr-Newman hole's a: its Carter constant is held
    double carter_ = 0;
    double hamiltonian_ = 0;
};

}  // namespace lc
