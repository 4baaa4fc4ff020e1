// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Boyer-Lindquist r and cos(theta) of a Kerr-Schild Cartesian point of a Kerr-Newman hole, with
// their gradients, from r^4 - (x^2 + y^2 + z^2 - a^2) r^2 - a^2 z^2 = 0 by implicit
// differentiation: what named observers and the radial potential's fate need of the chart.
#include "core/metrics/kerr_newman.hpp"

namespace lc {

struct BoyerLindquistGradients {
    double r, cosTheta;
    Vec4 dr, dCosTheta;  // d/dx^mu of each (covariant components in the Kerr-Schild chart)
};

inline BoyerLindquistGradients boyerLindquistGradients(const Vec4& x, double a) {
    BoyerLindquistGradients b;
    b.r = kerrSchildRadius(x(1), x(2), x(3), a);
    const double r = b.r, s2 = x.tail<3>().squaredNorm();
    const double dFdr = 4 * r * r * r - 2 * (s2 - a * a) * r;
    const Vec3 dFdx(-2 * x(1) * r * r, -2 * x(2) * r * r, -2 * x(3) * (r * r + a * a));
    b.dr << 0, -dFdx / dFdr;
    b.cosTheta = x(3) / r;
    b.dCosTheta = -x(3) / (r * r) * b.dr;
    b.dCosTheta(3) += 1 / r;
    return b;
}

}  // namespace lc
