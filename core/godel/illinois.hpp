#pragma once
// Bracketed root finding for the Goedel solvers: Illinois regula falsi with a bisection
// safeguard and a *relative* stopping test, because several roots (k3 of a low-|z| image,
// elevation of a near-axis point) sit close to 0 where an absolute tolerance loses digits.
#include <cmath>

namespace lc::godel {

struct RootResult {
    double x = 0;
    int iterations = 0;
    bool converged = false;
};

// f(lo) and f(hi) must not have the same strict sign. Never leaves [lo, hi].
template <class F>
RootResult illinois(F&& f, double lo, double hi, double flo, double fhi, double relTol = 4e-16,
                    int maxIter = 200) {
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

}  // namespace lc::godel
