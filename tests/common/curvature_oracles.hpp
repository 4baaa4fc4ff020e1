// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Closed forms the curvature tests and bench_curvature hold the code to (docs/PHYSICS.md section
// 13), typed once, from the papers and nothing of core/curvature.
#include <cmath>

namespace lc::test {

// Kretschmann scalar of Kerr-Newman (Henry 2000, ApJ 535, 350, eq. 9) at Boyer-Lindquist r and
// cos(theta) = c, with Sigma = r^2 + a^2 c^2:
// K = 8/Sigma^6 [6M^2 (r^6 - 15 a^2 r^4 c^2 + 15 a^4 r^2 c^4 - a^6 c^6)
//                - 12 M Q^2 r (r^4 - 10 a^2 r^2 c^2 + 5 a^4 c^4) + Q^4 (7 r^4 - 34 a^2 r^2 c^2 + 7 a^4 c^4)].
// Kerr (Q = 0): 48 M^2 (r^2 - a^2 c^2)(r^4 - 14 a^2 r^2 c^2 + a^4 c^4)/Sigma^6; Reissner-Nordstrom
// (a = 0): (48 M^2 r^2 - 96 M Q^2 r + 56 Q^4)/r^8; Schwarzschild 48 M^2/r^6.
inline double kerrNewmanKretschmann(double M, double a, double Q, double r, double c) {
    const double y2 = a * a * c * c, r2 = r * r, sigma = r2 + y2;
    return 8 / std::pow(sigma, 6) *
           (6 * M * M * (r2 * r2 * r2 - 15 * y2 * r2 * r2 + 15 * y2 * y2 * r2 - y2 * y2 * y2) -
            12 * M * Q * Q * r * (r2 * r2 - 10 * y2 * r2 + 5 * y2 * y2) +
            std::pow(Q, 4) * (7 * r2 * r2 - 34 * y2 * r2 + 7 * y2 * y2));
}

// The energy density Alcubierre's Eulerian observers measure (Alcubierre 1994, Class. Quantum Grav.
// 11, L73, eq. 19), at (X, y, z) from the bubble's centre, X along its motion with speed v:
// rho = -(1/8 pi) v^2 (y^2 + z^2) / (4 r_s^2) (df/dr_s)^2, f the top hat of radius R and wall sharpness
// sigma, df/dr = sigma [sech^2(sigma (r + R)) - sech^2(sigma (r - R))] / (2 tanh(sigma R)). 0 at the centre.
inline double alcubierreEulerianDensity(double v, double R, double sigma, double X, double y, double z) {
    const double rs = std::sqrt(X * X + y * y + z * z);
    if (!(rs > 0)) return 0;
    auto sech2 = [](double u) { return 1 / (std::cosh(u) * std::cosh(u)); };
    const double df = sigma * (sech2(sigma * (rs + R)) - sech2(sigma * (rs - R))) / (2 * std::tanh(sigma * R));
    return -v * v * (y * y + z * z) / (4 * rs * rs) * df * df / (8 * 3.14159265358979323846);
}

}  // namespace lc::test
