// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include "core/input/number_text.hpp"
#include "core/spacetime/spacetime.hpp"

#include <cmath>
#include <string>
#include <algorithm>
#include <stdexcept>

namespace lc {

// Boyer-Lindquist radius of a Cartesian Kerr-Schild point (x, y, z) of a hole with spin a: the root
// of r^4 - (x^2 + y^2 + z^2 - a^2) r^2 - a^2 z^2 = 0. For every scalar: KerrNewman::radius calls it,
// the thin disk's radius label (equatorialRadius, from which the GPU's lcDiskRadius is generated).
template <class S>
S kerrSchildRadius(const S& x, const S& y, const S& z, const S& a) {
    using std::sqrt;
    const S rho2 = x * x + y * y + z * z - a * a;
    return sqrt(S(0.5) * (rho2 + sqrt(rho2 * rho2 + S(4.0) * a * a * z * z)));
}

// Kerr-Newman in outgoing Kerr-Schild Cartesian coordinates (t, x, y, z):
//   g = eta - f l (x) l,  eta = diag(1,-1,-1,-1),
//   f = r^2 (2 M r - Q^2) / (r^4 + a^2 z^2),
//   l = (1, -(r x - a y)/(r^2+a^2), -(r y + a x)/(r^2+a^2), -z/r).
// Outgoing (time-reversed ingoing) form: camera rays are traced to the past and then
// cross the past horizon smoothly instead of piling up on it, so they stop cleanly.
// Schwarzschild is a = Q = 0. Spin along +z.
class KerrNewman : public KerrSchildMetric<KerrNewman> {
public:
    KerrNewman(double mass, double spin, double charge) : M_(mass), a_(spin), Q_(charge) {
        if (!(mass > 0)) throw std::invalid_argument("Kerr-Newman: mass M must be > 0");
        if (spin * spin + charge * charge > mass * mass)
            throw std::invalid_argument(
                "Kerr-Newman: a^2 + Q^2 must not exceed M^2 (naked singularity): a = " +
                input::significantDigits(spin) + " and Q = " + input::significantDigits(charge) +
                " with M = " + input::significantDigits(mass) + "; accepted |a| <= " +
                input::significantDigits(std::sqrt(std::max(0.0, mass * mass - charge * charge))));
    }
    std::string name() const override { return Q_ != 0 ? "kerr-newman" : a_ != 0 ? "kerr" : "schwarzschild"; }
    std::map<std::string, double> parameters() const override { return {{"M", M_}, {"a", a_}, {"Q", Q_}}; }
    std::array<std::string, 4> coordinateNames() const override { return {"t", "x", "y", "z"}; }
    bool asymptoticallyFlat() const override { return true; }
    bool hasHorizon() const override { return true; }
    std::optional<KerrNewmanParameters> kerrNewmanParameters() const override {
        return KerrNewmanParameters{M_, a_, Q_};
    }
    std::optional<codegen::Expr> equatorialRadius() const override {
        using codegen::Expr;
        return radius(Expr::coordinate(1), Expr::coordinate(2), Expr::coordinate(3));
    }

    Symmetries symmetries() const override { return {true, true, a_ == 0}; }

    double mass() const { return M_; }
    double spin() const { return a_; }
    double charge() const { return Q_; }
    // Extremal holes (a^2 + Q^2 = M^2, which the constructor accepts) have r_+ = M; rounding in
    // M^2 - a^2 - Q^2 can make that a tiny negative number (a = 0.6, Q = 0.8: -1.1e-16), whose square
    // root, NaN, once left every ray without a horizon to stop at.
    double outerHorizon() const { return M_ + std::sqrt(std::max(0.0, M_ * M_ - a_ * a_ - Q_ * Q_)); }

    // Analytic outside the ring singularity (radius |a|); every spherical photon orbit lies
    // within Boyer-Lindquist r <= 4 M (the retrograde one at extremal spin), i.e. within
    // Cartesian distance sqrt(16 M^2 + a^2), beyond which an outgoing ray escapes.
    FarField farField(const Vec4& /*x*/) const override {
        FarField f;
        f.size = std::abs(a_);
        f.mass = M_;
        f.spin = std::abs(a_);
        f.captureRadius = std::sqrt(16 * M_ * M_ + a_ * a_);
        return f;
    }

    // Boyer-Lindquist radius of a Cartesian Kerr-Schild point.
    template <class S>
    S radius(const S& x, const S& y, const S& z) const {
        return kerrSchildRadius(x, y, z, S(a_));
    }

    // r / r_+ - 1: rays stop where it falls to a small margin (1e-6 on the CPU, which keeps the
    // stop clear of the coordinate blow-up at the past horizon; more on the GPU, in float).
    template <class S>
    S boundaryFunction(const Eigen::Matrix<S, 4, 1>& X) const {
        return radius(X(1), X(2), X(3)) / S(outerHorizon()) - S(1.0);
    }

    Boundary boundary(const Vec4& x) const override {
        const double r = radius(x(1), x(2), x(3));
        if (!std::isfinite(r) || r < 1e-9) return Boundary::Singularity;
        return boundaryFunction<double>(x) < 1e-6 ? Boundary::Horizon : Boundary::None;
    }

    // Hamilton's equations with the gradients of f and l written out, all five sharing one r and
    // its gradient: the numeric tracer's innermost call, 1.5x faster than KerrSchildMetric's
    // automatic derivatives of kerrSchild() (docs/PERFORMANCE.md). tests/core/test_metrics.cpp
    // holds it to both automatic paths.
    HamiltonianFlow flow(const Vec4& x, const Vec4& p) const override;

    // The Kerr-Schild functions f and l (KerrSchildMetric builds g, its inverse and the flow).
    template <class S>
    void kerrSchild(const Eigen::Matrix<S, 4, 1>& X, S& f, Eigen::Matrix<S, 4, 1>& l) const {
        const S &x = X(1), &y = X(2), &z = X(3);
        const S r = radius(x, y, z);
        const S r2 = r * r;
        f = r2 * (S(2.0 * M_) * r - S(Q_ * Q_)) / (r2 * r2 + S(a_ * a_) * z * z);
        l(0) = S(1.0);
        l(1) = -(r * x - S(a_) * y) / (r2 + S(a_ * a_));
        l(2) = -(r * y + S(a_) * x) / (r2 + S(a_ * a_));
        l(3) = -z / r;
    }

private:
    double M_, a_, Q_;
};

class Schwarzschild final : public KerrNewman {
public:
    explicit Schwarzschild(double mass) : KerrNewman(mass, 0.0, 0.0) {}
};

}  // namespace lc
