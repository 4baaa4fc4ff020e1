// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The oracle of the validation suite: what a static or moving observer of a Kerr-Newman hole sees
// at the shadow's edge, from Boyer-Lindquist closed forms alone (docs/PHYSICS.md, "Validation
// against the literature"). Nothing here traces a ray or uses lc::LocalFrame or the camera code:
// - the static observer's orthonormal frame in BL coordinates (Bardeen, Press & Teukolsky 1972
//   give the metric; the frame is e_t ~ d/dt, e_r ~ d/dr, e_theta ~ d/dtheta, e_phi orthogonal);
// - a ray's constants of motion from its momentum: E = p_t, L = -p_phi, Carter's
//   Q = p_theta^2 - cos^2(theta) (a^2 E^2 - L^2 / sin^2 theta);
// - capture: a ray traced from the observer towards the hole falls in when Chandrasekhar's radial
//   potential R(r) = (r^2 + a^2 - a xi)^2 - Delta (eta + (xi - a)^2) (units E = 1) stays positive
//   from the horizon to the observer; the shadow's edge is the critical curve of Bardeen (1973),
//   where R has a double root;
// - the critical curve itself: a xi = r^2 + a^2 - 4 r Delta / Delta', eta + (xi - a)^2 = 16 r^2 Delta / Delta'^2.
#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace lc::validation {

using V4 = Eigen::Vector4d;  // BL components (t, r, theta, phi)
using M4 = Eigen::Matrix4d;

constexpr double kPiV = 3.14159265358979323846;

struct KerrNewmanBL {
    double M = 1, a = 0, Q = 0;
    double delta(double r) const { return r * r - 2 * M * r + a * a + Q * Q; }
    double horizon() const { return M + std::sqrt(M * M - a * a - Q * Q); }
    // Signature (+, -, -, -), as the code's.
    M4 metric(double r, double th) const {
        const double s2 = std::sin(th) * std::sin(th), rho2 = r * r + a * a * std::cos(th) * std::cos(th);
        const double w = 2 * M * r - Q * Q;
        M4 g = M4::Zero();
        g(0, 0) = 1 - w / rho2;
        g(0, 3) = g(3, 0) = a * s2 * w / rho2;
        g(1, 1) = -rho2 / delta(r);
        g(2, 2) = -rho2;
        g(3, 3) = -((r * r + a * a) * (r * r + a * a) - a * a * delta(r) * s2) * s2 / rho2;
        return g;
    }
    // Radial potential (E = 1) and its derivative.
    double radial(double r, double xi, double eta) const {
        const double p = r * r + a * a - a * xi;
        return p * p - delta(r) * (eta + (xi - a) * (xi - a));
    }
    // Critical curve, parametrised by the radius rp of the spherical photon orbit.
    void critical(double rp, double& xi, double& eta) const {
        const double d = delta(rp), dp = 2 * rp - 2 * M;
        const double k = 16 * rp * rp * d / (dp * dp);
        xi = (rp * rp + a * a - 4 * rp * d / dp) / a;
        eta = k - (xi - a) * (xi - a);
    }
};

// A static observer at (rO, thetaO) and its orthonormal frame e[0] ~ d/dt, e[1] ~ d/dr,
// e[2] ~ d/dtheta, e[3] = d/dphi made orthogonal to e[0].
struct ObserverFrameBL {
    KerrNewmanBL bh;
    double rO, thetaO;
    M4 g;
    std::array<V4, 4> e;

    ObserverFrameBL(KerrNewmanBL b, double r, double th) : bh(b), rO(r), thetaO(th), g(b.metric(r, th)) {
        if (!(g(0, 0) > 0)) throw std::invalid_argument("oracle: no static observer inside the ergoregion");
        e[0] = V4(1, 0, 0, 0) / std::sqrt(g(0, 0));
        e[1] = V4(0, 1, 0, 0) / std::sqrt(-g(1, 1));
        e[2] = V4(0, 0, 1, 0) / std::sqrt(-g(2, 2));
        V4 phi(0, 0, 0, 1);
        phi -= dot(phi, e[0]) * e[0];
        e[3] = phi / std::sqrt(-dot(phi, phi));
    }
    double dot(const V4& x, const V4& y) const { return x.dot(g * y); }
    // Past-directed tangent of the ray seen along frame direction (n_r, n_theta, n_phi).
    V4 pastTangent(const Eigen::Vector3d& n) const {
        const Eigen::Vector3d d = n.normalized();
        return -e[0] + d(0) * e[1] + d(1) * e[2] + d(2) * e[3];
    }
    // xi = L / E and eta = Q / E^2 of that ray.
    void constants(const Eigen::Vector3d& n, double& xi, double& eta) const {
        const V4 p = g * pastTangent(n);  // covariant; (E, L, p_theta) all change sign together
        const double E = p(0), L = -p(3), pth = p(2);
        const double c = std::cos(thetaO), s = std::sin(thetaO);
        xi = L / E;
        eta = (pth * pth - c * c * (bh.a * bh.a * E * E - L * L / (s * s))) / (E * E);
    }
    // Does the ray seen along n (pointing inwards) fall into the hole? R > 0 from the horizon to rO.
    bool captured(const Eigen::Vector3d& n) const {
        double xi, eta;
        constants(n, xi, eta);
        // Traced outwards: it comes back (and then falls in) where R has a root beyond rO, which
        // happens only for observers inside the photon region.
        if (pastTangent(n)(1) >= 0) return turnsBackOutside(xi, eta);
        // R is a quartic: its minimum on [r+, rO] is at an end or at a root of R'; sample densely in
        // log(r - r+) and refine each local minimum by golden section.
        const double rh = bh.horizon();
        auto R = [&](double r) { return bh.radial(r, xi, eta); };
        const int samples = 4000;
        double best = std::min(R(rh * (1 + 1e-12)), R(rO));
        const double l0 = std::log(1e-9 * rh), l1 = std::log(rO - rh);
        auto at = [&](int k) { return rh + std::exp(l0 + (l1 - l0) * k / samples); };
        for (int k = 1; k < samples; ++k) {
            const double r0 = at(k - 1), r1 = at(k), r2 = at(k + 1);
            if (!(R(r1) <= R(r0) && R(r1) <= R(r2))) continue;
            double lo = r0, hi = r2;
            for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
                const double m1 = lo + 0.381966 * (hi - lo), m2 = hi - 0.381966 * (hi - lo);
                (R(m1) < R(m2) ? hi : lo) = R(m1) < R(m2) ? m2 : m1;
            }
            best = std::min(best, R(0.5 * (lo + hi)));
        }
        return best > 0;
    }
    // R < 0 somewhere in (rO, 1e4 rO]: the radial motion has a turning point outside the observer.
    bool turnsBackOutside(double xi, double eta) const {
        const int samples = 20000;
        for (int k = 1; k <= samples; ++k)
            if (bh.radial(rO * std::exp(std::log(1e4) * k / samples), xi, eta) < 0) return true;
        return false;
    }
};

// Bisection for the angle from `axis` towards `towards` (frame directions) at which rays stop
// falling in, to 1e-15 relative; a scan of the half great circle first (edges may lie beyond 90
// degrees).
inline double edgeAngle(const ObserverFrameBL& o, const Eigen::Vector3d& axis, const Eigen::Vector3d& towards) {
    const int scan = 96;
    int first = 1;
    while (first < scan && o.captured(std::cos(kPiV * first / scan) * axis + std::sin(kPiV * first / scan) * towards))
        ++first;
    double in = kPiV * (first - 1) / scan, out = kPiV * first / scan;
    while (out - in > 1e-15 * out + 1e-18) {
        const double mid = 0.5 * (in + out);
        (o.captured(std::cos(mid) * axis + std::sin(mid) * towards) ? in : out) = mid;
    }
    return 0.5 * (in + out);
}

// The shadow of the camera forward = -e_r, up = -e_theta, right = +e_phi of the observer's frame
// (frame components (n_r, n_theta, n_phi)), measured as lc::measureShadow defines it: edges along
// the symmetry line (here through forward), centre between them, height across the line there.
struct OracleShadow {
    double left, right, height;  // radians
};
inline OracleShadow oracleShadow(const ObserverFrameBL& o) {
    const Eigen::Vector3d f(-1, 0, 0), up(0, -1, 0), right(0, 0, 1);
    OracleShadow s;
    s.right = edgeAngle(o, f, right);
    s.left = edgeAngle(o, f, -right);
    const double c = 0.5 * (s.right - s.left);
    const Eigen::Vector3d centre = std::cos(c) * f + std::sin(c) * right;
    s.height = edgeAngle(o, centre, up) + edgeAngle(o, centre, -up);
    return s;
}

// The spherical photon orbits seen from thetaO: Bardeen's beta^2 = eta + a^2 cos^2 - xi^2 cot^2 >= 0
// between these two radii (its roots, by a scan for sign changes and bisection).
inline std::array<double, 2> photonRegionSeenFrom(const KerrNewmanBL& bh, double thetaO) {
    const double c = std::cos(thetaO), s = std::sin(thetaO);
    auto beta2 = [&](double rp) {
        double xi, eta;
        bh.critical(rp, xi, eta);
        return eta + bh.a * bh.a * c * c - xi * xi * c * c / (s * s);
    };
    const double r0 = bh.horizon() * (1 + 1e-9), r1 = 6 * bh.M;
    std::array<double, 2> out{};
    int found = 0;
    const int samples = 20000;
    for (int k = 0; k < samples && found < 2; ++k) {
        double lo = r0 + (r1 - r0) * k / samples, hi = r0 + (r1 - r0) * (k + 1) / samples;
        if ((beta2(lo) > 0) == (beta2(hi) > 0)) continue;
        const bool loPositive = beta2(lo) > 0;
        for (int it = 0; it < 200; ++it) {
            const double mid = 0.5 * (lo + hi);
            ((beta2(mid) > 0) == loPositive ? lo : hi) = mid;
        }
        out[found++] = 0.5 * (lo + hi);
    }
    if (found != 2) throw std::runtime_error("oracle: the critical curve does not cross beta = 0 twice");
    return out;
}

// Bardeen's alpha = -xi / sin(thetaO) of the critical curve's points with beta = 0 (the horizontal
// edges): at the two ends of the photon region seen from thetaO.
inline std::array<double, 2> bardeenHorizontalAlphas(const KerrNewmanBL& bh, double thetaO) {
    std::array<double, 2> out{};
    const std::array<double, 2> ends = photonRegionSeenFrom(bh, thetaO);
    for (int k = 0; k < 2; ++k) {
        double xi, eta;
        bh.critical(ends[k], xi, eta);
        out[k] = -xi / std::sin(thetaO);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace lc::validation
