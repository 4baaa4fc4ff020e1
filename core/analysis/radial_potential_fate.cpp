// SPDX-License-Identifier: BSD-3-Clause
#include "core/analysis/radial_potential_fate.hpp"

#include "core/metrics/boyer_lindquist.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lc {
namespace {

// The real roots of t^3 + P t + Q = 0 (Cardano where one is real, Viete's cosines where three are).
std::vector<double> depressedCubicRoots(double P, double Q) {
    std::vector<double> roots;
    const double disc = 0.25 * Q * Q + P * P * P / 27;
    if (disc > 0) {
        const double s = std::sqrt(disc);
        roots.push_back(std::cbrt(-0.5 * Q + s) + std::cbrt(-0.5 * Q - s));
    } else if (P < 0) {
        const double m = 2 * std::sqrt(-P / 3);
        const double phi = std::acos(std::clamp(3 * Q / (P * m), -1.0, 1.0)) / 3;
        for (int k = 0; k < 3; ++k) roots.push_back(m * std::cos(phi - 2 * kPi * k / 3));
    } else {
        roots.push_back(0);  // P = Q = 0
    }
    return roots;
}

}  // namespace

std::optional<RayFate> radialPotentialFate(const Spacetime::KerrNewmanParameters& hole, const Spacetime& st,
                                           const Vec4& x, const Vec4& p) {
    const double M = hole.mass, a = hole.spin, qe = hole.charge;
    const BoyerLindquistGradients bl = boyerLindquistGradients(x, a);
    const double r = bl.r, rPlus = M + std::sqrt(std::max(0.0, M * M - a * a - qe * qe));
    const double c = bl.cosTheta, s2 = 1 - c * c;
    if (!std::isfinite(r) || !(r > rPlus) || !(s2 > 1e-20) || !p.allFinite()) return std::nullopt;
    const Vec4 k = st.inverseMetric(x) * p;  // dx/dlambda
    const double drdl = bl.dr.dot(k);
    const double E = -p(0), L = x(1) * p(2) - x(2) * p(1);
    // p_theta = Sigma dtheta/dlambda, dtheta = -d(cos theta) / sin(theta)
    const double pTheta = -(r * r + a * a * c * c) / std::sqrt(s2) * bl.dCosTheta.dot(k);
    const double K = pTheta * pTheta + c * c * (L * L / s2 - a * a * E * E) + (L - a * E) * (L - a * E);
    if (!(E != 0) || !std::isfinite(K)) return std::nullopt;
    auto R = [&](double rr) {
        const double A = E * (rr * rr + a * a) - a * L, D = rr * rr - 2 * M * rr + a * a + qe * qe;
        return A * A - D * K;
    };
    // A ray at its turning point (the sign of dr/dlambda is rounding): left to the tracer.
    const double scale = std::pow(E * (r * r + a * a), 2) + std::abs((r * r + a * a + qe * qe) * K);
    if (!(R(r) > 1e-12 * scale) || drdl == 0) return std::nullopt;
    // R's extremes: R'(r) = 4 E r A(r) - (2 r - 2 M) K = 0, the cubic
    // r^3 + (4 E (E a^2 - a L) - 2 K) / (4 E^2) r + 2 M K / (4 E^2) = 0, its roots polished by Newton.
    const double P = (4 * E * (E * a * a - a * L) - 2 * K) / (4 * E * E), Q = 2 * M * K / (4 * E * E);
    bool blockedBelow = false, blockedAbove = false;
    for (double rc : depressedCubicRoots(P, Q)) {
        for (int n = 0; n < 3; ++n) {
            const double f = rc * rc * rc + P * rc + Q, df = 3 * rc * rc + P;
            if (df != 0) rc -= f / df;
        }
        if (!(R(rc) < 0)) continue;
        if (rc > rPlus && rc < r) blockedBelow = true;
        if (rc > r) blockedAbove = true;
    }
    if (blockedBelow && blockedAbove) return std::nullopt;  // a bound orbit: neither end
    if (drdl < 0) return blockedBelow ? RayFate::Escapes : RayFate::Captured;
    return blockedAbove ? RayFate::Captured : RayFate::Escapes;
}

}  // namespace lc
