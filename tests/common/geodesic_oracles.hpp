// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Independent references for null geodesics (docs/PHYSICS.md section 7), typed from the
// literature and computed by quadrature, with no ray tracing and nothing of core/: the tests of
// the tracer's accuracy and bench_work_precision hold the tracer to them.
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lc::test {

struct EquatorialDeflection {
    double alpha = std::numeric_limits<double>::quiet_NaN();            // total deflection, radians (may exceed 2 pi)
    double closestApproach = std::numeric_limits<double>::quiet_NaN();  // Boyer-Lindquist r0
};

// Kerr (M = 1), a photon in the equatorial plane with energy 1 and angular momentum L (L > 0:
// prograde, turning with the spin), from and to infinity (Chandrasekhar, The Mathematical Theory
// of Black Holes, 1983, section 63): r^2 dr/dl = +-sqrt(R), r^2 dphi/dl = (L - a) + a P / Delta,
// P = r^2 + a^2 - a L, Delta = r^2 - 2 r + a^2, R = P^2 - Delta (L - a)^2
// = r (r^3 + (a^2 - L^2) r + 2 (L - a)^2). alpha = 2 int_{r0}^inf (dphi/dr) dr - pi, r0 the largest
// root of R. Integrated in u = 1/r with R divided by (r - r0), so the turning point's square-root
// singularity is the quadrature's endpoint and not a cancellation. a = 0 is Schwarzschild.
// NaN when the photon has no turning point (it falls in).
inline EquatorialDeflection kerrEquatorialDeflection(double a, double L) {
    const double c1 = a * a - L * L, c0 = 2 * (L - a) * (L - a);
    EquatorialDeflection out;
    if (!(c1 < 0) || 4 * c1 * c1 * c1 + 27 * c0 * c0 >= 0) return out;  // one real root only: captured
    const double m = 2 * std::sqrt(-c1 / 3);
    double r0 = m * std::cos(std::acos(std::clamp(3 * c0 / (c1 * m), -1.0, 1.0)) / 3);
    for (int i = 0; i < 3; ++i) r0 -= (r0 * r0 * r0 + c1 * r0 + c0) / (3 * r0 * r0 + c1);  // Newton polish
    const double u0 = 1 / r0;
    // dphi/du = num(u) / sqrt((u0 - u) q(u) / u0) with q(u) = u^2 (R / (r (r - r0))).
    auto num = [a, L](double u) { return (L - a) + a * (1 + (a * a - a * L) * u * u) / (1 - 2 * u + a * a * u * u); };
    auto q = [r0, c1](double u) { return 1 + r0 * u + (r0 * r0 + c1) * u * u; };
    boost::math::quadrature::tanh_sinh<double> integrator;
    const double I = integrator.integrate(
        [&](double u, double uc) {
            const double gap = uc > 0 ? uc : u0 - u;  // uc: the distance to the nearer end
            return num(u) / std::sqrt(gap * q(u) / u0);
        },
        0.0, u0);
    out.alpha = 2 * std::abs(I) - M_PI;
    out.closestApproach = r0;
    return out;
}

// The prograde (sign +1) or retrograde (-1) equatorial photon of Kerr (M = 1) whose turning point
// is Boyer-Lindquist r0: L from R(r0) = 0, (2 - r0) L^2 - 4 a L + r0^3 + a^2 r0 + 2 a^2 = 0, the root
// for which r0 is the outermost turning point (so the photon comes from infinity).
inline double kerrEquatorialAngularMomentum(double a, double r0, int sign) {
    const double A = 2 - r0, B = -4 * a, C = r0 * r0 * r0 + a * a * r0 + 2 * a * a;
    const double disc = std::sqrt(B * B - 4 * A * C);
    for (double L : {(-B + disc) / (2 * A), (-B - disc) / (2 * A)})
        if (L * sign > 0 && std::abs(kerrEquatorialDeflection(a, L).closestApproach - r0) < 1e-9 * r0) return L;
    return std::numeric_limits<double>::quiet_NaN();
}

// Alcubierre's bubble (speed v along +x, radius R, wall sharpness sigma; Alcubierre 1994, Class.
// Quantum Grav. 11, L73) on its axis: a photon leaving the centre at t = 0 against the motion.
// ds^2 = 0 gives dx/dt = v f - 1, so xi = x - v t obeys dxi/dt = v (f(|xi|) - 1) - 1 < 0 (separable):
// the coordinate time at which it reaches xi < 0 is t(xi) = int_0^xi dxi' / (v (f - 1) - 1),
// f(r) = [tanh(sigma (r + R)) - tanh(sigma (r - R))] / (2 tanh(sigma R)).
inline double alcubierreAxisTime(double v, double R, double sigma, double xi) {
    auto f = [=](double r) {
        return (std::tanh(sigma * (r + R)) - std::tanh(sigma * (r - R))) / (2 * std::tanh(sigma * R));
    };
    auto rate = [&](double x) { return 1 / (v * (f(std::abs(x)) - 1) - 1); };
    // Pieces split across the wall, so each is smooth on its own scale.
    std::vector<double> cuts{xi};
    for (int k = -6; k <= 6; ++k) {
        const double c = -R + k / sigma;
        if (c > xi && c < 0) cuts.push_back(c);
    }
    cuts.push_back(0);
    std::sort(cuts.begin(), cuts.end());
    double t = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
        t += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(rate, cuts[i], cuts[i + 1], 10, 1e-15);
    return -t;  // the integral runs from xi up to 0
}

}  // namespace lc::test
