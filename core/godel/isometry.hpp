// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Symmetries of the Goedel universe (docs/PHYSICS.md section 4): the five Killing fields and the
// finite isometries in closed form. Events are in the Cartesian chart (t, X, Y, z) of
// GodelCartesian unless a name says "Cylindrical" (t, r, phi, z).
#include "core/numerics/types.hpp"

#include <complex>

namespace lc::godel {

// d/dt, d/dphi, d/dz, xi4, xi5 (xi5 is xi4 rotated by pi/2; at the origin xi4 = 2a d/dY and
// xi5 = 2a d/dX).
enum class KillingField { T, Phi, Z, Xi4, Xi5 };

// Contravariant components in the cylindrical chart; x = (t, r, phi, z), r > 0.
Vec4 killingCylindrical(KillingField k, double a, const Vec4& x);
// Contravariant components in the Cartesian chart (smooth on the axis); x = (t, X, Y, z).
Vec4 killingCartesian(KillingField k, double a, const Vec4& x);

// Chart conversions (Cartesian <-> cylindrical) for events and contravariant vectors.
Vec4 toCylindrical(const Vec4& cart);
Vec4 toCartesian(const Vec4& cyl);
Vec4 vectorToCartesian(const Vec4& cyl, const Vec4& vCyl);

// A finite isometry that commutes with time translation:
//   zeta = (X + iY)/(2a), nu = sqrt(1 + |zeta|^2)  (w = zeta/nu is the disk point of docs/PHYSICS.md),
//   w' = (A w + B)/(conj(B) w + conj(A)),  |A|^2 - |B|^2 = 1  (an SU(1,1) disk automorphism),
//   t' = t + T - 2 sqrt2 a arg(1 + (conj B / conj A) w),  z' = z + Z.
// With A = 1/sqrt(1-s^2), B = -s/sqrt(1-s^2) this is the map w' = (w - s)/(1 - s w),
// t' = t - 2 sqrt2 a arg(1 - s w). The sign of the t-shift follows from the connection
// form r^2/(sqrt2 a) dphi = 2 sqrt2 a Im(conj(w) dw)/(1 - |w|^2), which a Moebius map changes by
// 2 sqrt2 a d arg(1 - conj(b) w): the sign of docs/PHYSICS.md section 4 is right (tests check the pull-back).
// In the (nu, zeta) variables everything stays exact near the horizon:
//   D = conj(B) zeta + conj(A) nu,  zeta' = (A zeta + B nu) |D|/D,  nu' = |D|,  arg(...) = arg(A D).
class Isometry {
public:
    using Complex = std::complex<double>;

    explicit Isometry(double a = 1.0);                 // identity
    static Isometry rotation(double a, double angle);  // phi' = phi + angle
    static Isometry timeShift(double a, double dt);    // t' = t + dt
    static Isometry zShift(double a, double dz);       // z' = z + dz
    // docs/PHYSICS.md section 4: w' = (w - s)/(1 - s w) with its time shift, |s| < 1.
    static Isometry diskAutomorphism(double a, double s);
    // The isometry that maps event P to the origin (0,0,0,0): rotate by -phi_P, disk map with
    // s = |w(P)|, shift t and z (docs/PHYSICS.md section 4). It defines the static frame at P used
    // throughout lc::godel: the frame that this map sends to the coordinate frame at the origin.
    static Isometry movingToOrigin(double a, const Vec4& P);
    // An observer's view: movingToOrigin followed by the turn about the axis that brings the
    // static observer's frame at P (Gram-Schmidt of d/dx, d/dy, d/dz, lc::LocalFrame::
    // staticObserver: the camera's, docs/PHYSICS.md section 8) onto the coordinate axes at the
    // origin; movingToOrigin alone leaves it turned by up to 145.5 degrees, depending on P. Every
    // view of an observer (images, photo-objects, diagrams, renderers) moves the scene with it, so
    // a direction at the origin of its chart is where the camera sees it.
    static Isometry observerToOrigin(double a, const Vec4& P);
    // The inverse: maps the origin to P (and the origin's frame to P's frame).
    static Isometry movingOriginTo(double a, const Vec4& P) { return movingToOrigin(a, P).inverse(); }

    double a() const { return a_; }
    // apply() shifts t by a constant and by -2 sqrt2 a arg(...), so beyond its constant by less
    // than this many a either way (bounds on where light can be seen use it).
    static constexpr double kTimeShiftBound = 2 * kSqrt2 * kPi;
    Vec4 apply(const Vec4& x) const;
    Vec4 applyCylindrical(const Vec4& xCyl) const;
    // d x'^mu / d x^nu at x (closed form: derivatives of the Moebius map by hand).
    Mat4 jacobian(const Vec4& x) const;
    Vec4 pushForward(const Vec4& x, const Vec4& v) const { return jacobian(x) * v; }
    // Covariant vectors (momenta) go with the inverse transpose.
    Vec4 pushForwardCovector(const Vec4& x, const Vec4& p) const;

    Isometry inverse() const;
    // (this o first)(x) = this->apply(first.apply(x)).
    Isometry compose(const Isometry& first) const;
    Isometry operator*(const Isometry& first) const { return compose(first); }

    Complex A() const { return A_; }
    Complex B() const { return B_; }
    double T() const { return T_; }
    double Z() const { return Z_; }

private:
    Isometry(double a, Complex A, Complex B, double T, double Z);
    void normalise();

    double a_ = 1;
    Complex A_{1, 0}, B_{0, 0};
    double T_ = 0, Z_ = 0;
};

}  // namespace lc::godel
