// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The curvature of any metric written as expressions (Spacetime::symbolic(): every built-in and
// every formula metric), exact: first derivatives of g by the symbolic chain rule, second
// derivatives by forward-mode differentiation of those along a flat tape (never finite
// differences). Conventions (docs/PHYSICS.md section 13): signature (+,-,-,-); Riemann as MTW
// and Landau-Lifshitz, R^a_bcd = d_c Gamma^a_db - d_d Gamma^a_cb + Gamma^a_ce Gamma^e_db
// - Gamma^a_de Gamma^e_cb; Ricci R_bd = R^a_bad; Einstein G_ab = R_ab - g_ab R / 2.
// Invariants with an even number of metric factors (Kretschmann, R_ab R^ab, C_abcd C^abcd) are
// the same in either signature; the Ricci scalar is minus its (-,+,+,+) value (de Sitter: -12 H^2).
#include "core/numerics/types.hpp"
#include "core/spacetime/spacetime.hpp"

#include <array>
#include <memory>

namespace lc {

namespace formula {
class ExpressionTape;
}

// A covariant rank-4 tensor T_abcd in the chart's coordinate basis.
struct Rank4Tensor {
    std::array<double, 256> v{};
    double& operator()(int a, int b, int c, int d) {
        return v[static_cast<std::size_t>(((a * 4 + b) * 4 + c) * 4 + d)];
    }
    double operator()(int a, int b, int c, int d) const {
        return v[static_cast<std::size_t>(((a * 4 + b) * 4 + c) * 4 + d)];
    }
};

// g, its first derivatives dg[k] = d_k g and second derivatives ddg[k][l] = d_k d_l g at an event.
struct MetricJet {
    Mat4 g = Mat4::Zero();
    std::array<Mat4, 4> dg{};
    std::array<std::array<Mat4, 4>, 4> ddg{};
};

// Everything curvature at one event, in the chart's coordinate basis.
struct CurvatureAt {
    Vec4 x = Vec4::Zero();
    Mat4 g = Mat4::Zero(), gInverse = Mat4::Zero();
    std::array<Mat4, 4> christoffel{};  // Gamma^a_bc = christoffel[a](b, c)
    Rank4Tensor riemann;                // R_abcd
    Mat4 ricci = Mat4::Zero();          // R_ab
    double ricciScalar = 0;             // R = g^ab R_ab
    Mat4 einstein = Mat4::Zero();       // G_ab
    Rank4Tensor weyl;                   // C_abcd
    double kretschmann = 0;             // R_abcd R^abcd
    double ricciSquared = 0;            // R_ab R^ab
    double weylSquared = 0;             // C_abcd C^abcd
};

// T_abcd T^abcd with every index raised by gInverse, for a tensor with the pair symmetry
// T_abcd = T_cdab (Riemann, Weyl).
double fullContraction(const Rank4Tensor& t, const Mat4& gInverse);
// Curvature from a metric jet (the formulas of docs/PHYSICS.md section 13).
CurvatureAt curvatureFromJet(const MetricJet& jet);

// Evaluates the jet and the curvature of one spacetime at any event; thread-safe.
class CurvatureProbe {
public:
    // Throws std::invalid_argument when the metric is not written as expressions.
    explicit CurvatureProbe(const Spacetime& spacetime);
    MetricJet jet(const Vec4& x) const;
    CurvatureAt at(const Vec4& x) const { return curvatureFromJet(jet(x)); }
    // Instructions of the tape that gives g, d g and d d g (the cost of one jet).
    std::size_t tapeInstructions() const;

private:
    std::shared_ptr<const formula::ExpressionTape> tape_;  // g_mn (m <= n), then d_k g_mn
};

}  // namespace lc
