// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Closed-form geodesics of the Goedel universe through the origin (docs/PHYSICS.md section 2).
//
// Charts: cylindrical (t, r, phi, z) of GodelCylindrical and Cartesian (t, X, Y, z) of
// GodelCartesian, X = r cos phi, Y = r sin phi; signature (+,-,-,-); parameter a > 0.
//
// One formula covers null (mu = 0) and timelike (mu = 1, parameter = proper time) rays with
// p_t = k0, p_phi = 0, dz/dl = k3, W = k0^2 + mu + k3^2:
//   omega = sqrt(W)/(2a),  rho(l) = r_max sin(omega l),  r_max = 2a sqrt((k0^2-mu-k3^2)/W)
//   Phi(l) = unwrapped arctan( sqrt(2 k0^2/W) tan(omega l) )
//   t = t0 + sgn(k0) 2 sqrt2 a Phi - k0 l,   X + iY = rho e^{i(phi0 + sgn(k0) Phi)},  z = z0 + k3 l.
// rho is the *signed* radius: after each return to the axis the ray retraces the same closed
// loop (seed 000 Fig. 1). In the cylindrical chart this means r = |rho| and
// phi = phi0 + sgn(k0) Phi + pi while rho < 0 (docs/PHYSICS.md section 2); phi = phi0 + k0 Phi
// with an unsigned radius, as a source prints it, agrees on even half-loops only (checked against numeric integration
// in tests/core/test_godel_geodesic.cpp).
#include "core/numerics/types.hpp"

#include <cstddef>
#include <vector>

namespace lc::godel {

class OriginGeodesic {
public:
    // Null ray with unit energy |k0| = 1: k0 = +1 future-, -1 past-directed; local direction at
    // the origin (static frame = coordinate frame there) has polar angle psi from +z, azimuth phi0.
    static OriginGeodesic null(double a, double psi, double phi0, int k0Sign, double t0 = 0, double z0 = 0);
    // Null ray given by k3 in [-1, 1] instead of psi (k3 = cos psi, exact near the poles).
    static OriginGeodesic nullFromK3(double a, double k3, double phi0, int k0Sign, double t0 = 0, double z0 = 0);
    // Null ray from (cos psi, sin psi), sin psi >= 0, normalised here. Use it near the axis:
    // r_max = 2a sin psi / sqrt(1 + cos^2 psi) keeps full relative accuracy where 1 - k3^2 would not.
    static OriginGeodesic nullFromDirection(double a, double cosPsi, double sinPsi, double phi0, int k0Sign,
                                            double t0 = 0, double z0 = 0);
    // Timelike geodesic, parameter = proper time; needs |k0| >= sqrt(1 + k3^2) (k0 < 0: past-directed).
    // Throws std::invalid_argument otherwise.
    static OriginGeodesic timelike(double a, double k0, double k3, double phi0, double t0 = 0, double z0 = 0);

    double a() const { return a_; }
    double k0() const { return k0_; }
    double k3() const { return k3_; }
    double phi0() const { return phi0_; }
    bool isTimelike() const { return mu_ != 0; }
    double omega() const { return omega_; }
    double rMax() const { return rMax_; }

    // Unwrapped phase Phi(l) (continuous, increasing) and its derivative.
    double phase(double l) const;
    double phaseRate(double l) const;
    // Signed radius rho(l) (see header comment) and d rho/dl.
    double signedRadius(double l) const;

    Vec4 cylindrical(double l) const;         // (t, r, phi, z); phi on the axis from phi0 continuity
    Vec4 cartesian(double l) const;           // (t, X, Y, z)
    Vec4 tangentCylindrical(double l) const;  // dx^mu/dl; on the axis dphi/dl is the one-sided limit
    Vec4 tangentCartesian(double l) const;
    Vec4 momentumCylindrical(double l) const;  // p_mu = g_{mu nu} dx^nu/dl = (k0, p_r, 0, -k3)
    Vec4 momentumCartesian(double l) const;
    PhasePoint phasePointCartesian(double l) const { return {cartesian(l), momentumCartesian(l)}; }

private:
    struct Local {  // everything at one parameter value
        double Phi, dPhi, rho, drho;
    };
    Local local(double l) const;
    void init(double radial2);  // radial2 = k0^2 - mu - k3^2, or < 0 to compute it

    double a_ = 1, k0_ = -1, k3_ = 0, phi0_ = 0, t0_ = 0, z0_ = 0;
    int mu_ = 0;
    double s_ = -1;                        // sign of k0
    double omega_ = 0, rMax_ = 0, c_ = 1;  // c = sqrt(2 k0^2 / W)
};

// Batch evaluation, structure of arrays: ray i at parameter lambdas[j] goes to index i*m + j of
// t, X, Y, z (each of size n*m). Plain loops over j with no branches inside, so the compiler can
// vectorise the arithmetic.
struct CartesianBatch {
    std::vector<double> t, X, Y, z;
};
void evaluateBatch(const std::vector<OriginGeodesic>& rays, const std::vector<double>& lambdas, CartesianBatch& out);

}  // namespace lc::godel
