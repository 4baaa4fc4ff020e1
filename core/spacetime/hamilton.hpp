#pragma once
// Hamilton's equations for H = 1/2 g^{mu nu} p_mu p_nu, written once for every scalar: the CPU
// tracer calls it in double (Spacetime::flow), and codegen::flowGlsl records it with
// codegen::Expr to generate the GPU tracer's lcFlow, so the GPU does not re-type the formula.
//   dx^mu/dl = v^mu = g^{mu nu} p_nu,   dp_k/dl = -dH/dx^k = 1/2 v^T (d_k g) v
// (d_k g^{-1} = -g^{-1} (d_k g) g^{-1}), exact given exact d_k g.
#include <Eigen/Dense>

#include <array>

namespace lc {

template <class S>
void hamiltonEquations(const Eigen::Matrix<S, 4, 4>& g, const std::array<Eigen::Matrix<S, 4, 4>, 4>& dg,
                       const Eigen::Matrix<S, 4, 1>& p, Eigen::Matrix<S, 4, 1>& dxdl, Eigen::Matrix<S, 4, 1>& dpdl) {
    dxdl = g.inverse() * p;
    for (int k = 0; k < 4; ++k) dpdl(k) = S(0.5) * dxdl.dot(dg[k] * dxdl);
}

}  // namespace lc
