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
