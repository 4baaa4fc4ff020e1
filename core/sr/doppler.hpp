// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Doppler factor, aberration and searchlight for a source moving with constant velocity
// relative to the observer frame S (seed 003 eq. 3, 4, 9; docs/PHYSICS.md section 6).
#include "core/numerics/types.hpp"
#include "core/sr/lorentz.hpp"

#include <cmath>

namespace lc::sr {

// D = nu_obs / nu_em = 1 / (gamma (1 - beta . n)); beta: source velocity in S, n: unit
// direction from source to observer (the photon's propagation direction) in S. The view
// direction is -n: restRayDoppler below, the one place the factor is written.
double dopplerFactor(const Vec3& beta, const Vec3& n);

// The direction of a photon travelling along the unit vector k, seen from a frame moving with
// -u: the spatial part of Lambda(u) (1, k) over its time part, i.e.
// (k + g u + g^2 / (g + 1) (u . k) u) / (g (1 + u . k)), g = 1 / sqrt(1 - u^2). For every scalar
// (double; codegen::Expr for the shaders' lcAberrateToRest).
template <class S>
Eigen::Matrix<S, 3, 1> boostDirection(const Eigen::Matrix<S, 3, 1>& u, const Eigen::Matrix<S, 3, 1>& k) {
    const S g = lorentzFactor<S>(u);
    const S uk = u.dot(k);
    return (k + g * u + (g * g / (g + S(1.0))) * uk * u) / (g * (S(1.0) + uk));
}

// The frequency ratio nu_obs / nu_em of light seen along the unit view direction d from S, emitted
// by a source moving with beta: 1 / (g (1 + beta . d)) (the light travels along -d). For every
// scalar (the SR renderers' rest-frame rays on CPU and GPU).
template <class S>
S restRayDoppler(const Eigen::Matrix<S, 3, 1>& beta, const Eigen::Matrix<S, 3, 1>& d) {
    return S(1.0) / (lorentzFactor<S>(beta) * (S(1.0) + beta.dot(d)));
}

// Photon propagation direction seen in S of a photon travelling along kRest in S'
// (S' moves with beta relative to S): spatial part of Lambda(beta) (1, kRest), normalised.
Vec3 aberrateToObserver(const Vec3& beta, const Vec3& kRest);
// Inverse: direction in S' of a photon travelling along k in S.
Vec3 aberrateToRest(const Vec3& beta, const Vec3& k);

// Light from a source at rest in S reflected by a surface moving with beta and received in
// S: nu_received / nu_source = (1 - beta . vIn) / (1 - beta . vOut), vIn / vOut the unit
// propagation directions of the incoming and outgoing light in S. This is the reciprocal of
// the factor D of seed 003 eq. 17, i.e. T_apparent = factor * T_light.
// For every scalar (the SR renderers' shading on CPU and GPU).
template <class S>
S reflectionFrequencyRatio(const Eigen::Matrix<S, 3, 1>& beta, const Eigen::Matrix<S, 3, 1>& vIn,
                           const Eigen::Matrix<S, 3, 1>& vOut) {
    // nu' = nu_in gamma (1 - beta.vIn) in S'; the mirror keeps nu'; nu_out = nu' / (gamma (1 - beta.vOut)).
    return (S(1.0) - beta.dot(vIn)) / (S(1.0) - beta.dot(vOut));
}

// A Planck spectrum stays Planck: T_obs = D T_em (the D^5 of L_lambda = D^5 L'_lambda'
// and lambda' = D lambda combine exactly into B(lambda, D T)).
inline double observedTemperature(double emittedK, double D) { return D * emittedK; }
// Searchlight: bolometric radiance scales with D^4, spectral radiance per lambda with D^5.
inline double searchlightBolometric(double D) { return D * D * D * D; }
inline double searchlightSpectral(double D) { return D * D * D * D * D; }

}  // namespace lc::sr
