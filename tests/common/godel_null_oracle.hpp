// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The Goedel universe's null geodesics through the origin in closed form (docs/PHYSICS.md
// section 2), typed in independently of the library's own closed-form module; the tracer's
// tests hold its numeric rays to them.
#include "core/metrics/godel.hpp"
#include "core/spacetime/frame.hpp"

#include <cmath>

namespace lc::test {

// docs/PHYSICS.md section 2, past-directed (k0 = -1) null ray from the origin event. One
// correction, found by this very test: the ray passes straight through the axis, so with a
// continuous Phi the radius is the signed r_max sin(w l) (equivalently |sin| with phi + pi per
// winding); the |sin| form a source prints holds for the first winding only (docs/PHYSICS.md section 2).
inline Vec4 closedFormNull(double a, double psi, double phi0, double lambda) {
    const double k3 = std::cos(psi), k0 = -1;
    const double w = std::sqrt(1 + k3 * k3) / (2 * a);
    const double rmax = 2 * a * std::sin(psi) / std::sqrt(1 + k3 * k3);  // sin(psi), not sqrt(1 - k3^2): psi -> 0
    const double Phi =
        std::atan(std::sqrt(2 / (1 + k3 * k3)) * std::tan(w * lambda)) + kPi * std::floor(w * lambda / kPi + 0.5);
    const double t = k0 * (2 * kSqrt2 * a * Phi - lambda);
    const double r = rmax * std::sin(w * lambda);
    const double phi = phi0 + k0 * Phi;
    return Vec4(t, r * std::cos(phi), r * std::sin(phi), k3 * lambda);
}

inline PhasePoint pastRay(const GodelCartesian& g, double psi, double phi0) {
    const LocalFrame f = LocalFrame::staticObserver(g, Vec4::Zero());
    const Vec3 n(std::sin(psi) * std::cos(phi0), std::sin(psi) * std::sin(phi0), std::cos(psi));
    return {Vec4::Zero(), f.pastNullMomentum(g, n)};
}

}  // namespace lc::test
