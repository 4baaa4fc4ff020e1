// SPDX-License-Identifier: BSD-3-Clause
#include "core/godel/isometry.hpp"

#include "core/metrics/godel.hpp"
#include "core/spacetime/frame.hpp"

#include <cmath>
#include <stdexcept>

namespace lc::godel {

using Complex = std::complex<double>;

Vec4 killingCylindrical(KillingField k, double a, const Vec4& x) {
    const double r = x(1), phi = x(2);
    const double R = std::sqrt(4 * a * a + r * r), c = std::cos(phi), s = std::sin(phi);
    switch (k) {
        case KillingField::T: return Vec4(1, 0, 0, 0);
        case KillingField::Phi: return Vec4(0, 0, 1, 0);
        case KillingField::Z: return Vec4(0, 0, 0, 1);
        case KillingField::Xi4:
            return Vec4(2 * kSqrt2 * a * r / R * c, R * s, 2 * (2 * a * a + r * r) / (r * R) * c, 0);
        case KillingField::Xi5:
            return Vec4(-2 * kSqrt2 * a * r / R * s, R * c, -2 * (2 * a * a + r * r) / (r * R) * s, 0);
    }
    return Vec4::Zero();
}

// The same fields with V^X = V^r cos phi - r V^phi sin phi, V^Y = V^r sin phi + r V^phi cos phi,
// simplified so that they are polynomial / R and finite on the axis.
Vec4 killingCartesian(KillingField k, double a, const Vec4& x) {
    const double X = x(1), Y = x(2), r2 = X * X + Y * Y;
    const double R = std::sqrt(4 * a * a + r2);
    switch (k) {
        case KillingField::T: return Vec4(1, 0, 0, 0);
        case KillingField::Phi: return Vec4(0, -Y, X, 0);
        case KillingField::Z: return Vec4(0, 0, 0, 1);
        case KillingField::Xi4: return Vec4(2 * kSqrt2 * a * X / R, -X * Y / R, (4 * a * a + r2 + X * X) / R, 0);
        case KillingField::Xi5: return Vec4(-2 * kSqrt2 * a * Y / R, (4 * a * a + r2 + Y * Y) / R, -X * Y / R, 0);
    }
    return Vec4::Zero();
}

Vec4 toCylindrical(const Vec4& c) { return Vec4(c(0), std::hypot(c(1), c(2)), std::atan2(c(2), c(1)), c(3)); }
Vec4 toCartesian(const Vec4& y) { return Vec4(y(0), y(1) * std::cos(y(2)), y(1) * std::sin(y(2)), y(3)); }
Vec4 vectorToCartesian(const Vec4& y, const Vec4& v) {
    const double c = std::cos(y(2)), s = std::sin(y(2)), r = y(1);
    return Vec4(v(0), v(1) * c - r * v(2) * s, v(1) * s + r * v(2) * c, v(3));
}

Isometry::Isometry(double a) : a_(a) {
    if (!(a > 0)) throw std::invalid_argument("Goedel isometry: a must be > 0");
}

Isometry::Isometry(double a, Complex A, Complex B, double T, double Z) : a_(a), A_(A), B_(B), T_(T), Z_(Z) {
    normalise();
}

void Isometry::normalise() {
    // Keep |A|^2 - |B|^2 = 1 against rounding drift after many compositions.
    const double d = std::norm(A_) - std::norm(B_);
    if (!(d > 0)) throw std::invalid_argument("Goedel isometry: not a disk automorphism (|A| <= |B|)");
    const double f = 1 / std::sqrt(d);
    A_ *= f;
    B_ *= f;
}

Isometry Isometry::rotation(double a, double angle) {
    return Isometry(a, std::polar(1.0, angle / 2), Complex(0, 0), 0, 0);
}
Isometry Isometry::timeShift(double a, double dt) { return Isometry(a, 1, 0, dt, 0); }
Isometry Isometry::zShift(double a, double dz) { return Isometry(a, 1, 0, 0, dz); }
Isometry Isometry::diskAutomorphism(double a, double s) {
    if (!(std::abs(s) < 1)) throw std::invalid_argument("Goedel disk automorphism: need |s| < 1");
    const double n = 1 / std::sqrt((1 - s) * (1 + s));
    return Isometry(a, n, -s * n, 0, 0);
}

Isometry Isometry::movingToOrigin(double a, const Vec4& P) {
    const double phiP = (P(1) == 0 && P(2) == 0) ? 0.0 : std::atan2(P(2), P(1));
    // |w| = q/sqrt(1+q^2); 1 - s^2 = 1/(1+q^2) is formed in diskAutomorphism as (1-s)(1+s),
    // which stays accurate for the distances inside a few horizon radii.
    const double q = std::hypot(P(1), P(2)) / (2 * a);
    const double s = q / std::sqrt(1 + q * q);
    const Isometry m = diskAutomorphism(a, s) * rotation(a, -phiP);
    const Vec4 Pm = m.apply(P);
    return timeShift(a, -Pm(0)) * zShift(a, -Pm(3)) * m;
}

Isometry Isometry::observerToOrigin(double a, const Vec4& P) {
    const Isometry moved = movingToOrigin(a, P);
    const LocalFrame frame = LocalFrame::staticObserver(GodelCartesian(a), P);
    const Vec4 e1 = moved.pushForward(P, frame.e[1]);
    return rotation(a, -std::atan2(e1(2), e1(1))).compose(moved);
}

Vec4 Isometry::apply(const Vec4& x) const {
    const Complex zeta(x(1) / (2 * a_), x(2) / (2 * a_));
    const double nu = std::sqrt(1 + std::norm(zeta));
    const Complex D = std::conj(B_) * zeta + std::conj(A_) * nu;
    const Complex N = A_ * zeta + B_ * nu;
    const Complex zp = N * (std::abs(D) / D);
    return Vec4(x(0) + T_ - 2 * kSqrt2 * a_ * std::arg(A_ * D), 2 * a_ * zp.real(), 2 * a_ * zp.imag(), x(3) + Z_);
}

Vec4 Isometry::applyCylindrical(const Vec4& y) const { return toCylindrical(apply(toCartesian(y))); }

Mat4 Isometry::jacobian(const Vec4& x) const {
    const double inv2a = 1 / (2 * a_);
    const Complex zeta(x(1) * inv2a, x(2) * inv2a);
    const double nu = std::sqrt(1 + std::norm(zeta));
    const Complex D = std::conj(B_) * zeta + std::conj(A_) * nu;
    const Complex N = A_ * zeta + B_ * nu;
    const Complex E = std::abs(D) / D;  // e^{-i arg D}
    Mat4 J = Mat4::Zero();
    J(0, 0) = 1;
    J(3, 3) = 1;
    // Derivatives in the scaled variables (x, y) = (X, Y)/(2a): d nu = (x dx + y dy)/nu.
    const double dnu[2] = {zeta.real() / nu, zeta.imag() / nu};
    const Complex dzeta[2] = {Complex(1, 0), Complex(0, 1)};
    for (int j = 0; j < 2; ++j) {
        const Complex dN = A_ * dzeta[j] + B_ * dnu[j];
        const Complex dD = std::conj(B_) * dzeta[j] + std::conj(A_) * dnu[j];
        const double dargD = (dD / D).imag();
        // zeta' = N e^{-i arg D}:  d zeta' = E (dN - i N d arg D).
        const Complex dzp = E * (dN - Complex(0, 1) * N * dargD);
        J(0, 1 + j) = -2 * kSqrt2 * a_ * dargD * inv2a;
        J(1, 1 + j) = dzp.real();  // (2a) * d(Re zeta')/d(2a x): the 2a cancel
        J(2, 1 + j) = dzp.imag();
    }
    return J;
}

Vec4 Isometry::pushForwardCovector(const Vec4& x, const Vec4& p) const {
    return jacobian(x).transpose().partialPivLu().solve(p);
}

Isometry Isometry::inverse() const {
    // SU(1,1) inverse; then fix T, Z so that the origin's image goes back to the origin.
    const Isometry m(a_, std::conj(A_), -B_, 0, 0);
    const Vec4 y = m.apply(apply(Vec4::Zero()));
    return Isometry(a_, std::conj(A_), -B_, -y(0), -y(3));
}

Isometry Isometry::compose(const Isometry& first) const {
    if (first.a_ != a_) throw std::invalid_argument("Goedel isometry: composing maps with different a");
    // Moebius part: matrix product. T, Z: the composite's value at the origin event (the
    // arg terms of the composite vanish there, see the header).
    const Complex A = A_ * first.A_ + B_ * std::conj(first.B_);
    const Complex B = A_ * first.B_ + B_ * std::conj(first.A_);
    const Vec4 o = apply(first.apply(Vec4::Zero()));
    return Isometry(a_, A, B, o(0), o(3));
}

}  // namespace lc::godel
