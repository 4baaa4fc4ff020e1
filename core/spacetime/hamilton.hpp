// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Hamilton's equations for H = 1/2 g^{mu nu} p_mu p_nu, written once for every scalar: the CPU
// tracer calls it in double (Spacetime::flow), and codegen::flowGlsl records it with
// codegen::Expr to generate the GPU tracer's lcFlow, so the GPU does not re-type the formula.
//   dx^mu/dl = v^mu = g^{mu nu} p_nu,   dp_k/dl = -dH/dx^k = 1/2 v^T (d_k g) v
// (d_k g^{-1} = -g^{-1} (d_k g) g^{-1}), exact given exact d_k g.
#include <Eigen/Dense>

#include <array>
#include <cmath>

namespace lc {

template <class S>
void hamiltonEquations(const Eigen::Matrix<S, 4, 4>& g, const std::array<Eigen::Matrix<S, 4, 4>, 4>& dg,
                       const Eigen::Matrix<S, 4, 1>& p, Eigen::Matrix<S, 4, 1>& dxdl, Eigen::Matrix<S, 4, 1>& dpdl) {
    dxdl = g.inverse() * p;
    for (int k = 0; k < 4; ++k) dpdl(k) = S(0.5) * dxdl.dot(dg[k] * dxdl);
}

// How far a ray has left the light cone, as both tracers judge it: |H| = 1/2 |p.v| (v = g^{-1} p)
// relative to the size of its terms, |p| |v|, which grow where a ray piles up on a chart's horizon
// (and its rounding with them), or to the launch scale (|p_0|^2, at least 1), whichever is larger.
// A drift above the tracer's tolerance stops the ray (StopReason::ConstraintBlowUp; the GPU's
// failed class). For every scalar: the CPU's RayMonitor in double, codegen::Expr for the GPU
// tracer's lcConstraintDrift.
template <class S>
S constraintDrift(const Eigen::Matrix<S, 4, 1>& p, const Eigen::Matrix<S, 4, 1>& v, const S& launchScale) {
    using std::abs;
    using std::max;
    using std::sqrt;
    return S(0.5) * abs(p.dot(v)) / max(launchScale, sqrt(p.squaredNorm()) * sqrt(v.squaredNorm()));
}

}  // namespace lc
