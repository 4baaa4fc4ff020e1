#include "core/accretion/thin_disk.hpp"

#include "core/input/number_text.hpp"
#include "core/numerics/roots.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lc {
namespace {

using input::significantDigits;

// Nodes of the flux integral: uniform in log r, dense enough that cubic Hermite interpolation
// with exact end derivatives stays within 1e-9 of the integral.
constexpr int kFluxNodes = 768;
// Near the inner edge the integral starts as (r - r_in)^2, so an interpolation's error, small
// against the flux's peak, is large against the flux itself: there it is integrated directly.
constexpr std::size_t kDirectIntervals = 24;

}  // namespace

ThinDiskModel::ThinDiskModel(SpacetimePtr spacetime, double innerRadius, double outerRadius, bool prograde)
    : st_(std::move(spacetime)), sense_(prograde ? 1 : -1) {
    kn_ = dynamic_cast<const KerrNewman*>(st_.get());
    if (!kn_)
        throw std::invalid_argument(
            "a thin disk needs a stationary, axisymmetric hole: the schwarzschild, kerr or "
            "kerr-newman metric (not '" +
            (st_ ? st_->name() : std::string("none")) + "')");
    const double M = kn_->mass();
    // Below the ISCO dE/dr < 0, above it dE/dr > 0: walk inwards from far out to the sign change.
    auto dE = [&](double r) { return dOrbit(r, &CircularOrbit::energy); };
    double hi = 60 * M, fHi = dE(hi);
    double lo = hi, fLo = fHi;
    while (fLo > 0) {
        hi = lo;
        fHi = fLo;
        lo = 0.97 * lo;
        // An extremal hole's ISCO meets its horizon (r = M at a = M): no orbit to stop at.
        if (lo < 1.02 * kn_->outerHorizon() || !orbit(lo * (1 - 1e-4)).exists) {
            if (innerRadius > 0) break;
            throw std::invalid_argument("no innermost stable circular orbit outside r = " + significantDigits(lo) +
                                        " M (a nearly extremal hole): give the disk an inner radius");
        }
        fLo = dE(lo);
    }
    isco_ = fLo > 0 ? kn_->outerHorizon() : illinois(dE, lo, hi, fLo, fHi, 1e-13).x;

    rIn_ = innerRadius > 0 ? innerRadius : isco_;
    rOut_ = outerRadius;
    if (rIn_ < isco_ * (1 - 1e-9))
        throw std::invalid_argument("inner radius " + significantDigits(rIn_) +
                                    " M lies inside the innermost stable circular orbit r = " +
                                    significantDigits(isco_) + " M: no disk matter stays there");
    if (!(rOut_ > rIn_))
        throw std::invalid_argument("outer radius " + significantDigits(rOut_) + " M must exceed the inner radius " +
                                    significantDigits(rIn_) + " M");
    tabulateFlux();
}

CircularOrbit ThinDiskModel::orbit(double r) const {
    CircularOrbit o;
    o.r = r;
    const double a = kn_->spin();
    const double rho = std::sqrt(r * r + a * a);
    Mat4 g;
    std::array<Mat4, 4> dg;
    st_->metricAndDerivatives(Vec4(0, rho, 0, 0), g, dg);
    // Killing components on the +x axis (xi_phi = rho d_y there) and their d/drho.
    const double A = g(0, 0), B = rho * g(0, 2), C = rho * rho * g(2, 2);
    const double dA = dg[1](0, 0), dB = g(0, 2) + rho * dg[1](0, 2), dC = 2 * rho * g(2, 2) + rho * rho * dg[1](2, 2);
    const double disc = dB * dB - dA * dC;
    if (!(disc >= 0) || dC == 0) return o;
    // The root turning with the hole (a >= 0: Omega > 0) for prograde, the other one otherwise.
    const double want = sense_ * (a < 0 ? -1 : 1);
    const double r1 = (-dB + std::sqrt(disc)) / dC, r2 = (-dB - std::sqrt(disc)) / dC;
    o.omega = (r1 > 0) == (want > 0) ? r1 : r2;
    const double norm = A + 2 * o.omega * B + o.omega * o.omega * C;
    if (!(norm > 0)) return o;
    o.ut = 1 / std::sqrt(norm);
    o.energy = o.ut * (A + o.omega * B);
    o.angularMomentum = -o.ut * (B + o.omega * C);
    o.exists = true;
    return o;
}

double ThinDiskModel::dOrbit(double r, double CircularOrbit::*member) const {
    // Fourth-order central differences, the step scaled to the distance from the horizon (the scale
    // on which the orbits change): truncation (h^4) and rounding (1e-16 / h) both near 1e-13.
    const double h = 1e-3 * (r - kn_->outerHorizon());
    const double f1 = orbit(r + h).*member - orbit(r - h).*member;
    const double f2 = orbit(r + 2 * h).*member - orbit(r - 2 * h).*member;
    return (8 * f1 - f2) / (12 * h);
}

double ThinDiskModel::fluxIntegrand(double r) const {
    const CircularOrbit o = orbit(r);
    return (o.energy - o.omega * o.angularMomentum) * dOrbit(r, &CircularOrbit::angularMomentum);
}

void ThinDiskModel::tabulateFlux() {
    nodes_.resize(kFluxNodes);
    integral_.assign(kFluxNodes, 0.0);
    integrand_.resize(kFluxNodes);
    const double span = std::log(rOut_ / rIn_);
    for (int k = 0; k < kFluxNodes; ++k) {
        nodes_[k] = k + 1 == kFluxNodes ? rOut_ : rIn_ * std::exp(span * k / (kFluxNodes - 1));
        integrand_[k] = fluxIntegrand(nodes_[k]);
        if (k > 0) {
            const double piece = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
                [&](double r) { return fluxIntegrand(r); }, nodes_[k - 1], nodes_[k], 0);
            integral_[k] = integral_[k - 1] + piece;
        }
    }
    int best = 0;
    double bestFlux = 0;
    for (int k = 0; k < kFluxNodes; ++k)
        if (const double f = flux(nodes_[k]); f > bestFlux) {
            bestFlux = f;
            best = k;
        }
    const double lo = nodes_[std::max(best - 1, 0)], hi = nodes_[std::min(best + 1, kFluxNodes - 1)];
    const auto peak = boost::math::tools::brent_find_minima([&](double r) { return -flux(r); }, lo, hi, 40);
    rPeak_ = peak.first;
    fMax_ = std::max(-peak.second, bestFlux);
}

double ThinDiskModel::flux(double r) const {
    if (!(r > rIn_ && r <= rOut_)) return 0;
    // Cubic Hermite interpolation of the integral between the nodes around r.
    const auto it = std::upper_bound(nodes_.begin(), nodes_.end(), r);
    const std::size_t k = std::min<std::size_t>(std::max<std::ptrdiff_t>(it - nodes_.begin(), 1), nodes_.size() - 1);
    const double r0 = nodes_[k - 1], h = nodes_[k] - r0, s = (r - r0) / h;
    double integral = 0;
    if (k <= kDirectIntervals) {
        integral = integral_[k - 1] + boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
                                          [&](double q) { return fluxIntegrand(q); }, r0, r, 0);
    } else {
        const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s), h01 = s * s * (3 - 2 * s),
                     h11 = s * s * (s - 1);
        integral = h00 * integral_[k - 1] + h10 * h * integrand_[k - 1] + h01 * integral_[k] + h11 * h * integrand_[k];
    }
    const CircularOrbit o = orbit(r);
    const double eMinusOmegaL = o.energy - o.omega * o.angularMomentum;
    // sqrt(-g) of (t, r, z, phi) on the equator is r for Kerr-Newman (Boyer-Lindquist).
    return -dOrbit(r, &CircularOrbit::omega) / (eMinusOmegaL * eMinusOmegaL) * integral / (4 * kPi * r);
}

double ThinDiskModel::radiusAt(const Vec4& x) const { return kn_->radius(x(1), x(2), x(3)); }

double ThinDiskModel::redshift(const Vec4& x, const Vec4& p, double observedEnergy) const {
    const CircularOrbit o = orbit(radiusAt(x));
    return keplerianRedshift<double>(x, p, o.omega, o.ut, observedEnergy);
}

double ThinDiskModel::bardeenIsco(double a, bool prograde) {
    const double s = std::abs(a);
    const double z1 = 1 + std::cbrt(1 - s * s) * (std::cbrt(1 + s) + std::cbrt(1 - s));
    const double z2 = std::sqrt(3 * s * s + z1 * z1);
    const double root = std::sqrt((3 - z1) * (3 + z1 + 2 * z2));
    return 3 + z2 + (prograde ? -root : root);
}

}  // namespace lc
