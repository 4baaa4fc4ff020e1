// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A geometrically thin, optically thick accretion disk in the equatorial plane of a stationary,
// axisymmetric hole (Novikov & Thorne 1973, Page & Thorne 1974): matter on circular equatorial
// geodesics, radiating the Page-Thorne flux as a black body. docs/PHYSICS.md section 12.
//
// Any metric that declares circular orbits (Spacetime::equatorialRadius: the built-in Kerr-Newman,
// or a formula metric found stationary, axisymmetric and mirror-symmetric) gets the disk: the
// orbits come from its g through the Killing fields xi_t = d_t and xi_phi = -y d_x + x d_y (spin
// along +z): with A = g(xi_t, xi_t), B = g(xi_t, xi_phi), C = g(xi_phi, xi_phi) on the equator, a
// circular geodesic has A' + 2 Omega B' + Omega^2 C' = 0 (' = d/dr), u^t = 1/sqrt(A + 2 Omega B +
// Omega^2 C), E = u_t and L = -u_phi; the ISCO is where dE/dr changes sign. Radii are the metric's
// label (Boyer-Lindquist r for Kerr-Newman: the chart's x^2 + y^2 = r^2 + a^2 at z = 0).
#include "core/spacetime/spacetime.hpp"

#include <memory>
#include <vector>

namespace lc {

namespace formula {
class ExpressionTape;
}

// g = nu_observed / nu_emitted of a ray of covariant momentum p leaving matter at chart event x on
// a circular orbit (u = u^t (d_t + omega d_phi), d_phi = -y d_x + x d_y), received by an observer who
// measures g(p, u_observer) = observedEnergy. For every scalar: ThinDiskModel::redshift calls it, the
// GPU's lcKeplerianRedshift is generated from it.
template <class S>
S keplerianRedshift(const Eigen::Matrix<S, 4, 1>& x, const Eigen::Matrix<S, 4, 1>& p, const S& omega, const S& ut,
                    const S& observedEnergy) {
    return observedEnergy / (ut * (p(0) + omega * (x(1) * p(2) - x(2) * p(1))));
}

// A circular equatorial geodesic at Boyer-Lindquist radius r (signature +,-,-,-).
struct CircularOrbit {
    double r = 0;
    double omega = 0;            // d phi / dt
    double ut = 0;               // u^t
    double energy = 0;           // E = u_t, per unit rest mass
    double angularMomentum = 0;  // L = -u_phi, per unit rest mass
    bool exists = false;         // false inside the photon orbit (no timelike circular orbit)
};

class ThinDiskModel {
public:
    // innerRadius <= 0: the innermost stable circular orbit. prograde: the disk turns with the hole
    // (for a = 0: counter-clockwise about +z). Throws when the orbits at the edges do not exist or
    // the inner edge lies inside the ISCO.
    ThinDiskModel(SpacetimePtr spacetime, double innerRadius, double outerRadius, bool prograde = true);

    const Spacetime& spacetime() const { return *st_; }
    // The radius label as an expression of the chart's coordinates (the GPU's lcDiskRadius is
    // generated from it) and the chart's distance from the axis of the equator's point at label r.
    const codegen::Expr& radiusExpression() const { return radius_; }
    double chartRadius(double r) const;
    double innerRadius() const { return rIn_; }
    double outerRadius() const { return rOut_; }
    bool prograde() const { return sense_ > 0; }
    double isco() const { return isco_; }

    CircularOrbit orbit(double r) const;
    // The Page-Thorne flux F(r) for an accretion rate of 1 (units of M: F M^2 / Mdot), 0 at the
    // inner edge; maxFlux() is its largest value on the disk and peakRadius() where it lies.
    double flux(double r) const;
    double maxFlux() const { return fMax_; }
    double peakRadius() const { return rPeak_; }

    // The disk's point at a chart event on the equator: its radius label.
    double radiusAt(const Vec4& x) const;
    // g = nu_observed / nu_emitted for a ray of covariant momentum p (any scale) leaving the disk at
    // event x, received by an observer who measures energy `observedEnergy` = g(p, u_observer) on
    // the same p.
    double redshift(const Vec4& x, const Vec4& p, double observedEnergy) const;

    // The ISCO of a Kerr hole of spin a (units of M), prograde or retrograde: Bardeen, Press and
    // Teukolsky (1972) eq. 2.21; independent of the metric code, for tests and docs.
    static double bardeenIsco(double a, bool prograde);

private:
    // Inside, orbits are found at the chart's distance rho from the axis (on +x): no label is
    // inverted while the ISCO is sought or the flux integrated; the labels are for the user.
    CircularOrbit orbitAt(double rho) const;
    double dOrbitAt(double rho, double CircularOrbit::*member) const;  // d/drho, central differences
    // sqrt(-g) of the (t, rho, phi) block on the equator, z measured in proper length: the
    // Page-Thorne flux's area element (with d Omega / d rho, a ratio that no relabelling changes).
    double areaElementAt(double rho) const;
    double fluxIntegrandAt(double rho) const;  // (E - Omega L) dL/drho
    double fluxAt(double rho) const;
    double equatorialHorizon() const;  // its rho; 0 without a horizon
    double rotationSense() const;
    void tabulateFlux();

    SpacetimePtr st_;
    codegen::Expr radius_;
    std::shared_ptr<const formula::ExpressionTape> radiusTape_;
    double scale_ = 1;       // the hole's mass (else its far field's size): where orbits are sought
    double rhoHorizon_ = 0;  // the horizon's rho on the equator
    double spinSense_ = 1;   // +1 when frame dragging turns counter-clockwise about +z (or none)
    double sense_ = 1;
    double isco_ = 0, rIn_ = 0, rOut_ = 0;  // labels
    double rhoIn_ = 0, rhoOut_ = 0;
    // The integral of (E - Omega L) dL/drho from the inner edge, at nodes rho_k, with its exact
    // derivative there: cubic Hermite between nodes.
    std::vector<double> nodes_, integral_, integrand_;
    double fMax_ = 0, rPeak_ = 0;
};

}  // namespace lc
