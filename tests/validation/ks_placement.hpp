// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Where a Boyer-Lindquist event and vector of the validation oracle lie in the code's outgoing
// Kerr-Schild chart (core/metrics/kerr_newman.hpp): x + i y = (r - i a) sin(theta) e^{i phi}, z =
// r cos(theta). d/dt, d/dtheta and d/dphi are the same vectors in both charts (the charts differ by
// functions of r in t and phi); d/dr of Boyer-Lindquist is the Kerr-Schild d/dr plus the multiples
// of d/dt and d/dphi that make it orthogonal to both, as it is in Boyer-Lindquist.
#include "core/metrics/kerr_newman.hpp"
#include "tests/validation/kerr_newman_oracle.hpp"

namespace lc::validation {

struct KsPlacement {
    Vec4 event;
    std::array<Vec4, 4> basis;  // BL d/dt, d/dr, d/dtheta, d/dphi in Kerr-Schild components

    KsPlacement(const KerrNewman& kn, double r, double th, double phi = 0) {
        const double a = kn.spin(), s = std::sin(th), c = std::cos(th), cp = std::cos(phi), sp = std::sin(phi);
        event = Vec4(0, s * (r * cp + a * sp), s * (r * sp - a * cp), r * c);
        basis[0] = Vec4::Unit(0);
        basis[2] = Vec4(0, c * (r * cp + a * sp), c * (r * sp - a * cp), -r * s);
        basis[3] = Vec4(0, -event(2), event(1), 0);
        const Vec4 radial(0, s * cp, s * sp, c);  // Kerr-Schild d/dr at fixed theta and Kerr-Schild phi
        const Mat4 g = kn.metric(event);
        // radial + A d/dt + B d/dphi orthogonal to d/dt and d/dphi.
        Eigen::Matrix2d m;
        m << basis[0].dot(g * basis[0]), basis[3].dot(g * basis[0]), basis[0].dot(g * basis[3]),
            basis[3].dot(g * basis[3]);
        const Eigen::Vector2d rhs(-radial.dot(g * basis[0]), -radial.dot(g * basis[3]));
        const Eigen::Vector2d ab = m.colPivHouseholderQr().solve(rhs);
        basis[1] = radial + ab(0) * basis[0] + ab(1) * basis[3];
    }
    Vec4 vector(const V4& bl) const {
        return bl(0) * basis[0] + bl(1) * basis[1] + bl(2) * basis[2] + bl(3) * basis[3];
    }
};

}  // namespace lc::validation
