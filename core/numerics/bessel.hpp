// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Bessel functions of the first kind J0 and J1, for metrics written as text (the formula
// language's besselj0, besselj1: Einstein-Rosen waves). The CPU evaluates them exactly
// (std::cyl_bessel_j, to double precision); the GPU runs the float approximation below
// (Abramowitz and Stegun 9.4.1, 9.4.3, 9.4.4, 9.4.6: |error| < 5e-8 for every x), written once
// as a template and generated as GLSL (views/shaders/core_formula_glsl).
#include "core/numerics/select.hpp"

#include <cmath>

namespace lc {

inline double besselJ0(double x) { return std::cyl_bessel_j(0.0, std::fabs(x)); }
inline double besselJ1(double x) { return x < 0 ? -std::cyl_bessel_j(1.0, -x) : std::cyl_bessel_j(1.0, x); }  // odd

// J1'(x) = J0(x) - J1(x)/x from the values j0 = J0(x), j1 = J1(x), by its series
// 1/2 - 3x^2/16 + 5x^4/384 for |x| <= 1e-3 (error below 1e-14): for the tape (double) and the
// symbolic derivative (codegen::Expr), which both have J1(x) at hand already.
template <class S>
S besselJ1Derivative(const S& x, const S& j0, const S& j1) {
    using std::abs;
    const S x2 = x * x;
    const S series = S(0.5) - S(3.0 / 16) * x2 + S(5.0 / 384) * x2 * x2;
    return ifPositive(abs(x) - S(1e-3), j0 - j1 / ifPositive(abs(x) - S(1e-3), x, S(1.0)), series);
}

namespace bessel_detail {
// c[0] + y (c[1] + y (c[2] + ...)): Horner's rule over the 7 coefficients.
template <class S>
S horner7(const S& y, const double (&c)[7]) {
    S sum = S(c[6]);
    for (int i = 5; i >= 0; --i) sum = S(c[i]) + y * sum;
    return sum;
}

// Abramowitz and Stegun's form: a polynomial P in (x/3)^2 for |x| <= 3, times x for the odd J1;
// beyond, f(3/|x|) cos(|x| + theta(3/|x|)) / sqrt|x|, times sign(x) for J1.
template <class S>
S firstKind(const S& x, const double (&p)[7], const double (&f)[7], const double (&theta)[7], bool odd) {
    using std::abs;
    using std::cos;
    using std::sqrt;
    const S ax = abs(x);
    const S near = ax / S(3.0);
    // max(|x|, 3): finite at x = 0, where the far branch is computed (GLSL) but not taken.
    const S beyond = ifPositive(ax - S(3.0), ax, S(3.0));
    const S far = S(3.0) / beyond;
    const S farValue = horner7(far, f) * cos(ax + horner7(far, theta)) * sqrt(far / S(3.0));
    const S nearValue = horner7(near * near, p);
    if (!odd) return ifPositive(ax - S(3.0), farValue, nearValue);
    return ifPositive(ax - S(3.0), farValue * (x / beyond), x * nearValue);
}
}  // namespace bessel_detail

template <class S>
S besselJ0Approximation(const S& x) {
    static constexpr double p[7] = {1.0, -2.2499997, 1.2656208, -0.3163866, 0.0444479, -0.0039444, 0.0002100};
    static constexpr double f[7] = {0.79788456, -0.00000077, -0.00552740, -0.00009512,
                                    0.00137237, -0.00072805, 0.00014476};
    static constexpr double theta[7] = {-0.78539816, -0.04166397, -0.00003954, 0.00262573,
                                        -0.00054125, -0.00029333, 0.00013558};
    return bessel_detail::firstKind(x, p, f, theta, false);
}

template <class S>
S besselJ1Approximation(const S& x) {
    static constexpr double p[7] = {0.5, -0.56249985, 0.21093573, -0.03954289, 0.00443319, -0.00031761, 0.00001109};
    static constexpr double f[7] = {0.79788456,  0.00000156, 0.01659667, 0.00017105,
                                    -0.00249511, 0.00113653, -0.00020033};
    static constexpr double theta[7] = {-2.35619449, 0.12499612, 0.00005650, -0.00637879,
                                        0.00074348,  0.00079824, -0.00029166};
    return bessel_detail::firstKind(x, p, f, theta, true);
}

}  // namespace lc
