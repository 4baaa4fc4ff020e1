#pragma once
// Bracketed scalar root finding shared by the renderer and the Goedel solvers.
#include <cmath>
#include <utility>

namespace lc {

// Illinois variant of regula falsi: f(a) and f(b) must have opposite signs (or one is 0).
// Converges superlinearly and never leaves the bracket.
template <class F>
double illinoisRoot(F&& f, double a, double b, double fa, double fb, double tol = 1e-14, int maxIter = 100) {
    if (fa == 0) return a;
    if (fb == 0) return b;
    int side = 0;
    double c = a;
    for (int i = 0; i < maxIter; ++i) {
        c = (a * fb - b * fa) / (fb - fa);
        const double fc = f(c);
        if (fc == 0 || std::abs(b - a) < tol * (1 + std::abs(c))) return c;
        if ((fc > 0) == (fb > 0)) {
            b = c;
            fb = fc;
            if (side == -1) fa *= 0.5;
            side = -1;
        } else {
            a = c;
            fa = fc;
            if (side == +1) fb *= 0.5;
            side = +1;
        }
    }
    return c;
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
