// SPDX-License-Identifier: BSD-3-Clause
#include "core/godel/geodesic.hpp"

#include <cmath>
#include <stdexcept>

namespace lc::godel {

namespace {
// (-1)^m for an integer-valued double m, without branches.
inline double parity(double m) { return 1.0 - 2.0 * (m - 2.0 * std::floor(0.5 * m)); }
}  // namespace

void OriginGeodesic::init(double radial2) {
    if (!(a_ > 0)) throw std::invalid_argument("Goedel geodesic: a must be > 0");
    s_ = k0_ >= 0 ? 1.0 : -1.0;
    const double W = k0_ * k0_ + mu_ + k3_ * k3_;
    // radial2 = k0^2 - mu - k3^2 >= 0 was checked by the factories; clamp rounding only.
    if (radial2 < 0) radial2 = std::max(0.0, k0_ * k0_ - mu_ - k3_ * k3_);
    omega_ = std::sqrt(W) / (2 * a_);
    rMax_ = 2 * a_ * std::sqrt(radial2 / W);
    c_ = std::sqrt(2 * k0_ * k0_ / W);
}

OriginGeodesic OriginGeodesic::null(double a, double psi, double phi0, int k0Sign, double t0, double z0) {
    return nullFromDirection(a, std::cos(psi), std::abs(std::sin(psi)), phi0, k0Sign, t0, z0);
}

OriginGeodesic OriginGeodesic::nullFromDirection(double a, double cosPsi, double sinPsi, double phi0, int k0Sign,
                                                 double t0, double z0) {
    const double n = std::hypot(cosPsi, sinPsi);
    if (!(n > 0) || !(sinPsi >= 0)) throw std::invalid_argument("Goedel null geodesic: bad direction");
    OriginGeodesic g;
    g.a_ = a;
    g.k0_ = k0Sign >= 0 ? 1.0 : -1.0;
    g.k3_ = cosPsi / n;
    g.phi0_ = phi0;
    g.t0_ = t0;
    g.z0_ = z0;
    g.mu_ = 0;
    const double sp = sinPsi / n;
    g.init(sp * sp);
    return g;
}

OriginGeodesic OriginGeodesic::nullFromK3(double a, double k3, double phi0, int k0Sign, double t0, double z0) {
    if (!(std::abs(k3) <= 1 + 1e-12)) throw std::invalid_argument("Goedel null geodesic: |k3| must be <= 1");
    OriginGeodesic g;
    g.a_ = a;
    g.k0_ = k0Sign >= 0 ? 1.0 : -1.0;
    g.k3_ = std::max(-1.0, std::min(1.0, k3));
    g.phi0_ = phi0;
    g.t0_ = t0;
    g.z0_ = z0;
    g.mu_ = 0;
    g.init(-1);
    return g;
}

OriginGeodesic OriginGeodesic::timelike(double a, double k0, double k3, double phi0, double t0, double z0) {
    if (!(k0 * k0 >= (1 + k3 * k3) * (1 - 1e-14)))
        throw std::invalid_argument("Goedel timelike geodesic: need |k0| >= sqrt(1 + k3^2)");
    OriginGeodesic g;
    g.a_ = a;
    g.k0_ = k0;
    g.k3_ = k3;
    g.phi0_ = phi0;
    g.t0_ = t0;
    g.z0_ = z0;
    g.mu_ = 1;
    g.init(-1);
    return g;
}

// theta = omega l is split as m pi + theta_r with |theta_r| <= pi/2, so the arctan branch is
// chosen by m (the "unwrapping" of docs/PHYSICS.md) and atan2 with cos(theta_r) >= 0 stays finite
// exactly at theta_r = +-pi/2 where tan() would overflow.
OriginGeodesic::Local OriginGeodesic::local(double l) const {
    const double th = omega_ * l;
    const double m = std::nearbyint(th / kPi);
    const double thr = th - m * kPi;
    const double sr = std::sin(thr), cr = std::cos(thr), sg = parity(m);
    Local L;
    L.Phi = m * kPi + std::atan2(c_ * sr, cr);
    L.dPhi = c_ * omega_ / (cr * cr + c_ * c_ * sr * sr);
    L.rho = rMax_ * sg * sr;
    L.drho = rMax_ * omega_ * sg * cr;
    return L;
}

double OriginGeodesic::phase(double l) const { return local(l).Phi; }
double OriginGeodesic::phaseRate(double l) const { return local(l).dPhi; }
double OriginGeodesic::signedRadius(double l) const { return local(l).rho; }

Vec4 OriginGeodesic::cartesian(double l) const {
    const Local L = local(l);
    const double al = phi0_ + s_ * L.Phi;
    return Vec4(t0_ + s_ * 2 * kSqrt2 * a_ * L.Phi - k0_ * l, L.rho * std::cos(al), L.rho * std::sin(al),
                z0_ + k3_ * l);
}

Vec4 OriginGeodesic::cylindrical(double l) const {
    const Local L = local(l);
    // On the axis (rho = 0) take the side the ray moves to next: phi stays continuous there.
    const bool flipped = L.rho < 0 || (L.rho == 0 && L.drho < 0);
    return Vec4(t0_ + s_ * 2 * kSqrt2 * a_ * L.Phi - k0_ * l, std::abs(L.rho),
                phi0_ + s_ * L.Phi + (flipped ? kPi : 0.0), z0_ + k3_ * l);
}

Vec4 OriginGeodesic::tangentCylindrical(double l) const {
    const Local L = local(l);
    const bool flipped = L.rho < 0 || (L.rho == 0 && L.drho < 0);
    return Vec4(s_ * 2 * kSqrt2 * a_ * L.dPhi - k0_, flipped ? -L.drho : L.drho, s_ * L.dPhi, k3_);
}

Vec4 OriginGeodesic::tangentCartesian(double l) const {
    const Local L = local(l);
    const double al = phi0_ + s_ * L.Phi, ca = std::cos(al), sa = std::sin(al);
    const double dal = s_ * L.dPhi;
    return Vec4(s_ * 2 * kSqrt2 * a_ * L.dPhi - k0_, L.drho * ca - L.rho * dal * sa, L.drho * sa + L.rho * dal * ca,
                k3_);
}

Vec4 OriginGeodesic::momentumCylindrical(double l) const {
    const Local L = local(l);
    const bool flipped = L.rho < 0 || (L.rho == 0 && L.drho < 0);
    const double u = L.rho * L.rho / (4 * a_ * a_);
    const double rdot = flipped ? -L.drho : L.drho;
    return Vec4(k0_, -rdot / (1 + u), 0.0, -k3_);
}

Vec4 OriginGeodesic::momentumCartesian(double l) const {
    const Local L = local(l);
    const double al = phi0_ + s_ * L.Phi;
    const double u = L.rho * L.rho / (4 * a_ * a_);
    // p_phi = 0, so the spatial momentum is p_r dr = -(drho/(1+u)) (cos al dX + sin al dY).
    const double pr = -L.drho / (1 + u);
    return Vec4(k0_, pr * std::cos(al), pr * std::sin(al), -k3_);
}

void evaluateBatch(const std::vector<OriginGeodesic>& rays, const std::vector<double>& lambdas, CartesianBatch& out) {
    const std::size_t n = rays.size(), m = lambdas.size();
    out.t.resize(n * m);
    out.X.resize(n * m);
    out.Y.resize(n * m);
    out.z.resize(n * m);
    const double* lam = lambdas.data();
    for (std::size_t i = 0; i < n; ++i) {
        const OriginGeodesic& g = rays[i];
        const double om = g.omega(), c = std::sqrt(2 * g.k0() * g.k0()) * (1.0 / (2 * g.a() * om));
        const double rm = g.rMax(), s = g.k0() >= 0 ? 1.0 : -1.0, k0 = g.k0(), k3 = g.k3();
        const double tf = s * 2 * kSqrt2 * g.a(), ph0 = g.phi0();
        const Vec4 origin = g.cartesian(0.0);  // carries t0, z0
        const double t0 = origin(0), z0 = origin(3);
        double* T = out.t.data() + i * m;
        double* X = out.X.data() + i * m;
        double* Y = out.Y.data() + i * m;
        double* Z = out.z.data() + i * m;
        for (std::size_t j = 0; j < m; ++j) {
            const double th = om * lam[j];
            const double mm = std::nearbyint(th * (1.0 / kPi));
            const double thr = th - mm * kPi;
            const double sr = std::sin(thr), cr = std::cos(thr);
            const double Phi = mm * kPi + std::atan2(c * sr, cr);
            const double rho = rm * parity(mm) * sr;
            const double al = ph0 + s * Phi;
            T[j] = t0 + tf * Phi - k0 * lam[j];
            X[j] = rho * std::cos(al);
            Y[j] = rho * std::sin(al);
            Z[j] = z0 + k3 * lam[j];
        }
    }
}

}  // namespace lc::godel
