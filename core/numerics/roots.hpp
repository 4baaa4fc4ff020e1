// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Bracketed scalar root finding shared by the renderer and the Goedel solvers.
#include <cmath>
#include <utility>

namespace lc {

// Illinois variant of regula falsi with a bisection safeguard and a *relative* stopping test
// (several roots sit close to 0, e.g. k3 of a low-|z| Goedel image, where an absolute tolerance
// loses digits). f(lo) and f(hi) must not have the same strict sign; never leaves [lo, hi].
struct RootResult {
    double x = 0;
    int iterations = 0;
    bool converged = false;
};

// f(lo) and f(hi) must not have the same strict sign. Never leaves [lo, hi].
template <class F>
RootResult illinois(F&& f, double lo, double hi, double flo, double fhi, double relTol = 4e-16, int maxIter = 200) {
    RootResult res;
    if (flo == 0) return {lo, 0, true};
    if (fhi == 0) return {hi, 0, true};
    if ((flo > 0) == (fhi > 0)) return {0.5 * (lo + hi), 0, false};
    int side = 0;
    for (int i = 1; i <= maxIter; ++i) {
        double c = (lo * fhi - hi * flo) / (fhi - flo);
        // Safeguard: regula falsi may stall at an end where f is very steep; bisect then.
        const double w = hi - lo;
        if (!(c > lo + 1e-3 * w && c < hi - 1e-3 * w) && (i % 4 == 0)) c = 0.5 * (lo + hi);
        if (!(c >= lo && c <= hi)) c = 0.5 * (lo + hi);
        const double fc = f(c);
        res.iterations = i;
        if (fc == 0) return {c, i, true};
        if ((fc > 0) == (fhi > 0)) {
            hi = c;
            fhi = fc;
            if (side == -1) flo *= 0.5;
            side = -1;
        } else {
            lo = c;
            flo = fc;
            if (side == +1) fhi *= 0.5;
            side = +1;
        }
        if (hi - lo <= relTol * std::max(std::abs(lo), std::abs(hi)) || hi - lo < 1e-300) {
            res.x = std::abs(flo) < std::abs(fhi) ? lo : hi;
            res.converged = true;
            return res;
        }
    }
    res.x = std::abs(flo) < std::abs(fhi) ? lo : hi;
    res.converged = std::abs(hi - lo) <= 1e-12 * std::max(1.0, std::abs(res.x));
    return res;
}

// The root alone, for callers that trust the bracket.
template <class F>
double illinoisRoot(F&& f, double a, double b, double fa, double fb, double relTol = 1e-14) {
    return illinois(f, a, b, fa, fb, relTol).x;
}

}  // namespace lc

namespace lc {

// First parameter in [l0, l1] where F drops to <= 0, given F(l0) = f0 > 0; negative if none.
// Along a segment much shorter than the object, F is close to a parabola (exactly one for a
// straight ray and a sphere), so a ray that enters and leaves between the samples is caught:
// the parabola through (l0, lm, l1) locates the minimum, a golden-section search refines it.
template <class F>
double firstEntry(F&& f, double l0, double l1, double f0, double f1, double tol = 1e-13) {
    if (f1 <= 0) return illinoisRoot(f, l0, l1, f0, f1, tol);
    const double lm = 0.5 * (l0 + l1), fm = f(lm);
    if (fm <= 0) return illinoisRoot(f, l0, lm, f0, fm, tol);
    const double curvature = f0 - 2 * fm + f1;  // > 0 when the parabola has a minimum
    if (!(curvature > 0)) return -1;
    const double h = 0.5 * (l1 - l0);
    const double vertex = lm + 0.5 * h * (f0 - f1) / curvature;
    const double predicted = fm - (f1 - f0) * (f1 - f0) / (8 * curvature);
    if (vertex <= l0 || vertex >= l1 || predicted > 0.5 * fm) return -1;  // clearly no dip below zero
    // Golden-section search for the minimum (F is unimodal on such a short segment).
    double a = l0, b = l1;
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
    for (int i = 0; i < 60 && b - a > tol * (1 + std::abs(a)); ++i) {
        if (fc <= 0 || fd <= 0) break;
        if (fc < fd) {
            b = d, d = c, fd = fc;
            c = b - g * (b - a), fc = f(c);
        } else {
            a = c, c = d, fc = fd;
            d = a + g * (b - a), fd = f(d);
        }
    }
    if (fc <= 0) return illinoisRoot(f, l0, c, f0, fc, tol);
    if (fd <= 0) return illinoisRoot(f, l0, d, f0, fd, tol);
    return -1;
}

}  // namespace lc
