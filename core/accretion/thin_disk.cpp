// SPDX-License-Identifier: BSD-3-Clause
#include "core/accretion/thin_disk.hpp"

#include "core/formula/expression_tape.hpp"
#include "core/input/number_text.hpp"
#include "core/numerics/roots.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
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
    const std::optional<codegen::Expr> label = st_ ? st_->equatorialRadius() : std::nullopt;
    if (!label)
        throw std::invalid_argument(
            "a thin disk needs a stationary, axisymmetric hole with the mirror plane z = 0: the schwarzschild, "
            "kerr or kerr-newman metric, or a formula metric with a far_field that d/dt, rotations about z and "
            "z -> -z leave unchanged (not '" +
            (st_ ? st_->name() : std::string("none")) + "')");
    radius_ = *label;
    radiusTape_ = std::make_shared<formula::ExpressionTape>(std::vector<codegen::Expr>{radius_});
    const FarField far = st_->farField(Vec4::Zero());
    scale_ = far.mass > 0 ? far.mass : far.size > 0 ? far.size : 1;
    rhoHorizon_ = equatorialHorizon();
    spinSense_ = rotationSense();
    auto labelOf = [&](double rho) { return radiusAt(Vec4(0, rho, 0, 0)); };
    // The label must grow outwards (chartRadius inverts it): checked from the horizon to far out.
    for (double rho = rhoHorizon_ + 0.01 * scale_, last = -1e300; rho < 1e5 * scale_; rho *= 1.25) {
        const double r = labelOf(rho);
        if (!(std::isfinite(r) && r > last))
            throw std::invalid_argument("the disk's radius label of metric '" + st_->name() +
                                        "' must be finite and grow outwards along +x on z = 0; at x = " +
                                        significantDigits(rho) + " it is " + significantDigits(r));
        last = r;
    }
    // Below the ISCO dE/dr < 0, above it dE/dr > 0: walk inwards from far out to the sign change.
    auto dE = [&](double rho) { return dOrbitAt(rho, &CircularOrbit::energy); };
    double hi = 60 * scale_ + rhoHorizon_, fHi = dE(hi);
    if (!std::isfinite(fHi))
        throw std::invalid_argument("no circular orbit at r = " + significantDigits(labelOf(hi)) + " in metric '" +
                                    st_->name() + "': the disk's orbits cannot be found");
    // Keplerian orbits far out gain energy outwards; where they do not (no mass: a static particle
    // is already a geodesic), there is no disk to speak of.
    if (!(fHi > 1e-12 / scale_) || !(orbitAt(hi).omega != 0))
        throw std::invalid_argument("circular orbits at r = " + significantDigits(labelOf(hi)) + " in metric '" +
                                    st_->name() +
                                    "' do not gain energy outwards (no mass to orbit?): no innermost stable orbit, no "
                                    "Page-Thorne disk");
    double lo = hi, fLo = fHi;
    while (fLo > 0) {
        hi = lo;
        fHi = fLo;
        lo = rhoHorizon_ + 0.97 * (lo - rhoHorizon_);  // 3 % closer to the horizon (or the axis)
        // An extremal hole's ISCO meets its horizon (r = M at a = M): no orbit to stop at.
        if (lo - rhoHorizon_ < 1e-3 * scale_ || !orbitAt(lo - 1e-4 * (lo - rhoHorizon_)).exists) {
            if (innerRadius > 0) break;
            throw std::invalid_argument(
                "no innermost stable circular orbit outside r = " + significantDigits(labelOf(lo)) +
                " (a nearly extremal hole, or no ISCO in this metric): give the disk an "
                "inner radius");
        }
        fLo = dE(lo);
    }
    isco_ = labelOf(fLo > 0 ? rhoHorizon_ : illinois(dE, lo, hi, fLo, fHi, 1e-13).x);

    rIn_ = innerRadius > 0 ? innerRadius : isco_;
    rOut_ = outerRadius;
    if (rIn_ < isco_ * (1 - 1e-9))
        throw std::invalid_argument("inner radius " + significantDigits(rIn_) +
                                    " M lies inside the innermost stable circular orbit r = " +
                                    significantDigits(isco_) + " M: no disk matter stays there");
    if (!(rOut_ > rIn_))
        throw std::invalid_argument("outer radius " + significantDigits(rOut_) + " M must exceed the inner radius " +
                                    significantDigits(rIn_) + " M");
    rhoIn_ = chartRadius(rIn_);
    rhoOut_ = chartRadius(rOut_);
    tabulateFlux();
}

double ThinDiskModel::equatorialHorizon() const {
    if (!st_->hasHorizon()) return 0;
    // Along +x on the equator rays stop inside the horizon and run outside it: bisect on the
    // horizon function's sign where the metric gives one (its root is the horizon itself, without
    // the tracer's stop margin), else on where rays stop.
    const std::optional<codegen::SymbolicMetric> symbolic = st_->symbolic();
    auto outsideAt = [&](double rho) {
        if (symbolic && symbolic->boundary) return codegen::evaluate(*symbolic->boundary, {0, rho, 0, 0}) > 0;
        return st_->boundary(Vec4(0, rho, 0, 0)) == Boundary::None;
    };
    double inside = 0, outside = 60 * scale_;
    for (int k = 0; k < 60 && !outsideAt(outside); ++k) outside *= 2;
    for (int k = 0; k < 200 && outside - inside > 1e-15 * outside; ++k) {
        const double mid = 0.5 * (inside + outside);
        (outsideAt(mid) ? outside : inside) = mid;
    }
    return outside;
}

double ThinDiskModel::rotationSense() const {
    // The sense of frame dragging, -g(xi_t, xi_phi) / g(xi_phi, xi_phi), far out on +x; none: +1.
    const double rho = 60 * scale_ + rhoHorizon_;
    const Mat4 g = st_->metric(Vec4(0, rho, 0, 0));
    const double B = rho * g(0, 2), C = rho * rho * g(2, 2);
    const double drag = -B / C, kepler = std::sqrt(std::abs(g(0, 0) / C));
    return drag < -1e-12 * kepler ? -1 : 1;
}

double ThinDiskModel::chartRadius(double r) const {
    // Safeguarded Newton on label(rho, 0, 0) = r, its derivative exact from the tape, inside a
    // bracket that bisection keeps when a Newton step would leave it.
    auto label = [&](double rho, double* slope) {
        const double x[4] = {0, rho, 0, 0};
        double out[5];
        radiusTape_->evaluateWithGradient(x, out);
        if (slope) *slope = out[2];
        return out[0] - r;
    };
    double hi = std::max(r, 1e-300);
    for (int k = 0; k < 64 && !(label(hi, nullptr) >= 0); ++k) hi *= 2;
    double lo = 0.5 * hi;
    for (int k = 0; k < 64 && label(lo, nullptr) > 0; ++k) lo *= 0.5;
    double rho = 0.5 * (lo + hi);
    for (int k = 0; k < 100; ++k) {
        double slope = 0;
        const double f = label(rho, &slope);
        if (f == 0) return rho;
        (f > 0 ? hi : lo) = rho;
        const double newton = rho - f / slope;
        const double next = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
        if (std::abs(next - rho) <= 1e-15 * rho) return next;
        rho = next;
    }
    return rho;
}

double ThinDiskModel::areaElementAt(double rho) const {
    const Mat4 g = st_->metric(Vec4(0, rho, 0, 0));
    // (x, y) -> (rho, phi) multiplies sqrt(-g) by rho; z in proper length divides by sqrt(|g_zz|).
    return rho * std::sqrt(-g.determinant() / std::abs(g(3, 3)));
}

CircularOrbit ThinDiskModel::orbit(double r) const {
    CircularOrbit o = orbitAt(chartRadius(r));
    o.r = r;
    return o;
}

CircularOrbit ThinDiskModel::orbitAt(double rho) const {
    CircularOrbit o;
    o.r = rho;
    Mat4 g;
    std::array<Mat4, 4> dg;
    st_->metricAndDerivatives(Vec4(0, rho, 0, 0), g, dg);
    // Killing components on the +x axis (xi_phi = rho d_y there) and their d/drho.
    const double A = g(0, 0), B = rho * g(0, 2), C = rho * rho * g(2, 2);
    const double dA = dg[1](0, 0), dB = g(0, 2) + rho * dg[1](0, 2), dC = 2 * rho * g(2, 2) + rho * rho * dg[1](2, 2);
    const double disc = dB * dB - dA * dC;
    if (!(disc >= 0) || dC == 0) return o;
    // The root turning with the hole (Omega > 0 where dragging is counter-clockwise) for prograde.
    const double want = sense_ * spinSense_;
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

double ThinDiskModel::dOrbitAt(double rho, double CircularOrbit::*member) const {
    // Fourth-order central differences, the step scaled to the distance from the horizon (the scale
    // on which the orbits change): truncation (h^4) and rounding (1e-16 / h) both near 1e-13.
    const double h = 1e-3 * (rho - rhoHorizon_);
    const double f1 = orbitAt(rho + h).*member - orbitAt(rho - h).*member;
    const double f2 = orbitAt(rho + 2 * h).*member - orbitAt(rho - 2 * h).*member;
    return (8 * f1 - f2) / (12 * h);
}

double ThinDiskModel::fluxIntegrandAt(double rho) const {
    const CircularOrbit o = orbitAt(rho);
    return (o.energy - o.omega * o.angularMomentum) * dOrbitAt(rho, &CircularOrbit::angularMomentum);
}

void ThinDiskModel::tabulateFlux() {
    nodes_.resize(kFluxNodes);
    integral_.assign(kFluxNodes, 0.0);
    integrand_.resize(kFluxNodes);
    const double span = std::log(rhoOut_ / rhoIn_);
    for (int k = 0; k < kFluxNodes; ++k) {
        nodes_[k] = k + 1 == kFluxNodes ? rhoOut_ : rhoIn_ * std::exp(span * k / (kFluxNodes - 1));
        integrand_[k] = fluxIntegrandAt(nodes_[k]);
        if (k > 0) {
            const double piece = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
                [&](double rho) { return fluxIntegrandAt(rho); }, nodes_[k - 1], nodes_[k], 0);
            integral_[k] = integral_[k - 1] + piece;
        }
    }
    int best = 0;
    double bestFlux = 0;
    for (int k = 0; k < kFluxNodes; ++k)
        if (const double f = fluxAt(nodes_[k]); f > bestFlux) {
            bestFlux = f;
            best = k;
        }
    const double lo = nodes_[std::max(best - 1, 0)], hi = nodes_[std::min(best + 1, kFluxNodes - 1)];
    const auto peak = boost::math::tools::brent_find_minima([&](double rho) { return -fluxAt(rho); }, lo, hi, 40);
    rPeak_ = radiusAt(Vec4(0, peak.first, 0, 0));
    fMax_ = std::max(-peak.second, bestFlux);
}

double ThinDiskModel::flux(double r) const {
    if (!(r > rIn_ && r <= rOut_)) return 0;
    return fluxAt(std::clamp(chartRadius(r), rhoIn_, rhoOut_));
}

double ThinDiskModel::fluxAt(double rho) const {
    if (!(rho > rhoIn_ && rho <= rhoOut_)) return 0;
    // Cubic Hermite interpolation of the integral between the nodes around rho.
    const auto it = std::upper_bound(nodes_.begin(), nodes_.end(), rho);
    const std::size_t k = std::min<std::size_t>(std::max<std::ptrdiff_t>(it - nodes_.begin(), 1), nodes_.size() - 1);
    const double r0 = nodes_[k - 1], h = nodes_[k] - r0, s = (rho - r0) / h;
    double integral = 0;
    if (k <= kDirectIntervals) {
        integral = integral_[k - 1] + boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
                                          [&](double q) { return fluxIntegrandAt(q); }, r0, rho, 0);
    } else {
        const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s), h01 = s * s * (3 - 2 * s),
                     h11 = s * s * (s - 1);
        integral = h00 * integral_[k - 1] + h10 * h * integrand_[k - 1] + h01 * integral_[k] + h11 * h * integrand_[k];
    }
    const CircularOrbit o = orbitAt(rho);
    const double eMinusOmegaL = o.energy - o.omega * o.angularMomentum;
    return -dOrbitAt(rho, &CircularOrbit::omega) / (eMinusOmegaL * eMinusOmegaL) * integral /
           (4 * kPi * areaElementAt(rho));
}

double ThinDiskModel::radiusAt(const Vec4& x) const {
    double r = 0;
    radiusTape_->evaluate(x.data(), &r);
    return r;
}

double ThinDiskModel::redshift(const Vec4& x, const Vec4& p, double observedEnergy) const {
    // The orbit through the event: its distance from the axis (the metric is axisymmetric).
    const CircularOrbit o = orbitAt(std::hypot(x(1), x(2)));
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
