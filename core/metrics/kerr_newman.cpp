// SPDX-License-Identifier: BSD-3-Clause
#include "core/metrics/kerr_newman.hpp"

namespace lc {

// Divisions are the cost here (about 20 as written in the formulas): four reciprocals instead.
HamiltonianFlow KerrNewman::flow(const Vec4& X, const Vec4& p) const {
    const double x = X(1), y = X(2), z = X(3), a2 = a_ * a_;
    // r from r^4 - rho2 r^2 - a^2 z^2 = 0 (kerrSchildRadius); its gradient from differentiating
    // that equation: dr = (r x, r y, z (r^2 + a^2) / r) / D with D = 2 r^2 - rho2.
    const double rho2 = x * x + y * y + z * z - a2, D = std::sqrt(rho2 * rho2 + 4 * a2 * z * z);
    const double r2 = 0.5 * (rho2 + D), r = std::sqrt(r2);
    const double S = r2 + a2, den = r2 * r2 + a2 * z * z;
    const double invR = 1 / r, invD = 1 / D, invS = 1 / S, invDen = 1 / den;
    const Vec3 dr = Vec3(r * x, r * y, z * S * invR) * invD;
    // f = r^2 (2 M r - Q^2) / (r^4 + a^2 z^2)
    const double f = r2 * (2 * M_ * r - Q_ * Q_) * invDen;
    Vec3 dDen = 4 * r * r2 * dr;
    dDen(2) += 2 * a2 * z;
    const Vec3 df = ((6 * M_ * r2 - 2 * Q_ * Q_ * r) * dr - f * dDen) * invDen;
    // l = (1, -u1 / S, -u2 / S, -z / r), u1 = r x - a y, u2 = r y + a x, S = r^2 + a^2.
    const double u1 = r * x - a_ * y, u2 = r * y + a_ * x, l1 = u1 * invS, l2 = u2 * invS, l3 = z * invR;
    const Vec3 dS = 2 * r * dr;
    const Vec3 dl1 = -(x * dr + Vec3(r, -a_, 0) - l1 * dS) * invS;
    const Vec3 dl2 = -(y * dr + Vec3(a_, r, 0) - l2 * dS) * invS;
    const Vec3 dl3 = -(Vec3(0, 0, 1) - l3 * dr) * invR;
    // As KerrSchildMetric::flow: v = eta p + f (l.p) l^, dp_k/dl = -(l.p) (1/2 d_k f (l.p) + f d_k l^.p).
    const Vec4 lUp(1, l1, l2, l3);
    const double lp = lUp.dot(p);
    const Vec3 dlp = -(p(1) * dl1 + p(2) * dl2 + p(3) * dl3);
    HamiltonianFlow out;
    out.dxdl = Vec4(p(0), -p(1), -p(2), -p(3)) + f * lp * lUp;
    out.dpdl(0) = 0;
    out.dpdl.tail<3>() = -lp * (0.5 * lp * df + f * dlp);
    out.H = 0.5 * p.dot(out.dxdl);
    return out;
}

}  // namespace lc
