// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The analytic shadow at finite distance for Carter's observer of Kerr-Newman (Grenzebach,
// Perlick & Lammerzahl 2014, Phys. Rev. D 89, 124004, Lambda = 0; docs/PHYSICS.md section 9b),
// seen in the code's observer frame: the oracle of the outline tests and bench_shadow_outline.
// Boyer-Lindquist closed forms only, carried to the Kerr-Schild chart by KsPlacement.
#include "core/spacetime/frame.hpp"
#include "tests/validation/ks_placement.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace lc::validation {

// Carter's frame in Boyer-Lindquist components (GPL 2014, eq. 13 with Lambda = 0):
// e0 = ((r^2 + a^2) d_t + a d_phi) / sqrt(rho^2 Delta), e1 = sqrt(Delta / rho^2) d_r,
// e2 = d_theta / rho, e3 = (d_phi + a sin^2 theta d_t) / (rho sin theta).
struct CarterFrameBL {
    KerrNewmanBL bh;
    double rO, thetaO;
    M4 g;
    std::array<V4, 4> e;
    CarterFrameBL(KerrNewmanBL b, double r, double th) : bh(b), rO(r), thetaO(th), g(b.metric(r, th)) {
        const double a = b.a, s = std::sin(th), rho = std::sqrt(r * r + a * a * std::cos(th) * std::cos(th));
        const double d = b.delta(r);
        e[0] = V4(r * r + a * a, 0, 0, a) / (rho * std::sqrt(d));
        e[1] = V4(0, std::sqrt(d) / rho, 0, 0);
        e[2] = V4(0, 0, 1 / rho, 0);
        e[3] = V4(a * s * s, 0, 0, 1) / (rho * s);
    }
    // The past-directed tangent (BL components) of the ray on the shadow's edge that comes from
    // the spherical photon orbit rp, with p_theta of sign `side`: covariant momentum
    // (E, p_r, p_theta, p_phi) = (-1, +-sqrt(R(rO)) / Delta(rO), side sqrt(Theta(thetaO)), xi), with
    // Bardeen's beta^2 = Theta = eta + a^2 cos^2 - xi^2 cot^2. It runs inwards (p_r > 0) when the
    // orbit lies inside the observer, outwards when outside.
    V4 edgeTangent(double rp, int side) const {
        double xi, eta;
        bh.critical(rp, xi, eta);
        const double c = std::cos(thetaO), s = std::sin(thetaO);
        const double theta2 = std::max(0.0, eta + bh.a * bh.a * c * c - xi * xi * c * c / (s * s));
        const double R = std::max(0.0, bh.radial(rO, xi, eta));
        const V4 p(-1, (rO > rp ? 1 : -1) * std::sqrt(R) / bh.delta(rO), side * std::sqrt(theta2), xi);
        return g.inverse() * p;
    }
    // The photon orbits seen from thetaO: beta^2 >= 0 between these radii.
    std::array<double, 2> photonRegion() const { return photonRegionSeenFrom(bh, thetaO); }
};

// The analytic outline seen in the code's frame: angles about the outline's inside point c, from
// the inside point's right (the camera's right made orthogonal to c) towards its up.
struct AnalyticOutline {
    const CarterFrameBL& carter;
    const KsPlacement& at;
    Mat4 g;
    const LocalFrame& frame;
    Vec3 c, right, up;
    std::array<double, 2> region;

    Vec3 direction(double rp, int side) const {
        const Vec4 k = at.vector(carter.edgeTangent(rp, side));
        const double k0 = k.dot(g * frame.e[0]);
        return Vec3(k.dot(g * frame.e[1]), k.dot(g * frame.e[2]), k.dot(g * frame.e[3])) / k0;
    }
    double psi(const Vec3& d) const { return std::atan2(d.dot(up), d.dot(right)); }
    double rho(const Vec3& d) const { return std::atan2(d.cross(c).norm(), d.dot(c)); }
    double rpAt(double t) const { return region[0] + (region[1] - region[0]) * (0.5 - 0.5 * std::cos(kPiV * t)); }

    // The closed curve as u in [0, 2): the p_theta > 0 half out, the p_theta < 0 half back.
    Vec3 onLoop(double u) const {
        u = u - 2 * std::floor(u / 2);
        return u < 1 ? direction(rpAt(u), 1) : direction(rpAt(2 - u), -1);
    }
    // The analytic edge's angle from c at position angle psiK: a root in u of the wrapped angle
    // difference.
    double radiusAt(double psiK) const {
        auto diff = [&](double u) { return std::remainder(psi(onLoop(u)) - psiK, 2 * kPiV); };
        const int samples = 4000;
        for (int k = 0; k < samples; ++k) {
            double lo = 2.0 * k / samples, hi = 2.0 * (k + 1) / samples;
            const double dlo = diff(lo), dhi = diff(hi);
            if (!((dlo <= 0) != (dhi <= 0)) || std::abs(dlo - dhi) > 1) continue;
            for (int it = 0; it < 100; ++it) {
                const double mid = 0.5 * (lo + hi);
                ((diff(mid) <= 0) == (dlo <= 0) ? lo : hi) = mid;
            }
            return rho(onLoop(0.5 * (lo + hi)));
        }
        throw std::runtime_error("oracle: no analytic edge point at this position angle");
    }
    // The solid angle inside the closed analytic curve: sum of (1 - cos rho) dpsi over a dense
    // polygon (both halves, the photon region swept out and back).
    double solidAngle() const {
        const int samples = 40000;
        std::vector<Vec3> loop;
        for (int k = 0; k <= samples; ++k) loop.push_back(direction(rpAt(double(k) / samples), 1));
        for (int k = samples; k >= 0; --k) loop.push_back(direction(rpAt(double(k) / samples), -1));
        double omega = 0;
        for (std::size_t k = 0; k + 1 < loop.size(); ++k) {
            const double dpsi = std::remainder(psi(loop[k + 1]) - psi(loop[k]), 2 * kPiV);
            omega += (1 - std::cos(0.5 * (rho(loop[k]) + rho(loop[k + 1])))) * dpsi;
        }
        return std::abs(omega);
    }
};

}  // namespace lc::validation
