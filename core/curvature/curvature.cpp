// SPDX-License-Identifier: BSD-3-Clause
#include "core/curvature/curvature.hpp"

#include "core/formula/expression_tape.hpp"

#include <stdexcept>
#include <vector>

namespace lc {

namespace {
// The ten independent entries g_mn, m <= n, in the tape's order.
constexpr std::array<std::pair<int, int>, 10> kPairs{
    {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {1, 1}, {1, 2}, {1, 3}, {2, 2}, {2, 3}, {3, 3}}};

}  // namespace

double fullContraction(const Rank4Tensor& t, const Mat4& gi) {
    // U^ef_cd = g^ea g^fb T_abcd; with the pair symmetry T_abcd = T_cdab,
    // T_abcd T^abcd = U^ef_cd U^cd_ef: two raisings instead of four.
    Rank4Tensor half, up;
    for (int e = 0; e < 4; ++e)
        for (int b = 0; b < 4; ++b)
            for (int cd = 0; cd < 16; ++cd) {
                double s = 0;
                for (int a = 0; a < 4; ++a) s += gi(e, a) * t.v[static_cast<std::size_t>((a * 4 + b) * 16 + cd)];
                half.v[static_cast<std::size_t>((e * 4 + b) * 16 + cd)] = s;
            }
    for (int e = 0; e < 4; ++e)
        for (int f = 0; f < 4; ++f)
            for (int cd = 0; cd < 16; ++cd) {
                double s = 0;
                for (int b = 0; b < 4; ++b) s += gi(f, b) * half.v[static_cast<std::size_t>((e * 4 + b) * 16 + cd)];
                up.v[static_cast<std::size_t>((e * 4 + f) * 16 + cd)] = s;
            }
    double sum = 0;
    for (int ef = 0; ef < 16; ++ef)
        for (int cd = 0; cd < 16; ++cd)
            sum += up.v[static_cast<std::size_t>(ef * 16 + cd)] * up.v[static_cast<std::size_t>(cd * 16 + ef)];
    return sum;
}

CurvatureAt curvatureFromJet(const MetricJet& jet) {
    CurvatureAt c;
    c.g = jet.g;
    c.gInverse = jet.g.inverse();
    const Mat4& gi = c.gInverse;
    const auto& dg = jet.dg;
    const auto& ddg = jet.ddg;

    // Christoffel symbols of the first kind Gamma_abc = (d_b g_ac + d_c g_ab - d_a g_bc) / 2,
    // then Gamma^a_bc = g^ad Gamma_dbc.
    std::array<Mat4, 4> first;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            for (int cc = 0; cc < 4; ++cc) first[a](b, cc) = 0.5 * (dg[b](a, cc) + dg[cc](a, b) - dg[a](b, cc));
    for (int a = 0; a < 4; ++a) {
        c.christoffel[a].setZero();
        for (int d = 0; d < 4; ++d) c.christoffel[a] += gi(a, d) * first[d];
    }

    // R_abcd = (d_b d_c g_ad + d_a d_d g_bc - d_a d_c g_bd - d_b d_d g_ac) / 2
    //          + Gamma^e_bc Gamma_ead - Gamma^e_bd Gamma_eac     (Landau-Lifshitz eq. 92.1),
    // computed for a < b, c < d and filled in by its antisymmetries.
    for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b)
            for (int cc = 0; cc < 4; ++cc)
                for (int d = cc + 1; d < 4; ++d) {
                    double r = 0.5 * (ddg[b][cc](a, d) + ddg[a][d](b, cc) - ddg[a][cc](b, d) - ddg[b][d](a, cc));
                    for (int e = 0; e < 4; ++e)
                        r += c.christoffel[e](b, cc) * first[e](a, d) - c.christoffel[e](b, d) * first[e](a, cc);
                    c.riemann(a, b, cc, d) = r;
                    c.riemann(b, a, cc, d) = -r;
                    c.riemann(a, b, d, cc) = -r;
                    c.riemann(b, a, d, cc) = r;
                }

    for (int b = 0; b < 4; ++b)
        for (int d = 0; d < 4; ++d) {
            double s = 0;
            for (int a = 0; a < 4; ++a)
                for (int cc = 0; cc < 4; ++cc) s += gi(a, cc) * c.riemann(a, b, cc, d);
            c.ricci(b, d) = s;
        }
    c.ricci = 0.5 * (c.ricci + c.ricci.transpose()).eval();
    c.ricciScalar = (gi.cwiseProduct(c.ricci)).sum();
    c.einstein = c.ricci - 0.5 * c.ricciScalar * c.g;

    // C_abcd = R_abcd - (g_ac R_bd - g_ad R_bc - g_bc R_ad + g_bd R_ac) / 2
    //          + R (g_ac g_bd - g_ad g_bc) / 6                       (four dimensions).
    const Mat4& g = c.g;
    const Mat4& R = c.ricci;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            for (int cc = 0; cc < 4; ++cc)
                for (int d = 0; d < 4; ++d)
                    c.weyl(a, b, cc, d) =
                        c.riemann(a, b, cc, d) -
                        0.5 * (g(a, cc) * R(b, d) - g(a, d) * R(b, cc) - g(b, cc) * R(a, d) + g(b, d) * R(a, cc)) +
                        c.ricciScalar / 6 * (g(a, cc) * g(b, d) - g(a, d) * g(b, cc));

    c.kretschmann = fullContraction(c.riemann, gi);
    const Mat4 ricciUp = gi * R * gi;
    c.ricciSquared = R.cwiseProduct(ricciUp).sum();
    c.weylSquared = fullContraction(c.weyl, gi);
    return c;
}

CurvatureProbe::CurvatureProbe(const Spacetime& spacetime) {
    const auto symbolic = spacetime.symbolic();
    if (!symbolic)
        throw std::invalid_argument("curvature: the metric '" + spacetime.name() +
                                    "' is not written as expressions (a built-in or a formula metric is)");
    std::vector<codegen::Expr> outputs;
    for (const auto& [m, n] : kPairs) outputs.push_back(symbolic->g(m, n));
    for (int k = 0; k < 4; ++k) {
        codegen::Differentiator d(k);
        for (const auto& [m, n] : kPairs) outputs.push_back(d(symbolic->g(m, n)));
    }
    tape_ = std::make_shared<formula::ExpressionTape>(outputs);
}

std::size_t CurvatureProbe::tapeInstructions() const { return tape_->instructions(); }

MetricJet CurvatureProbe::jet(const Vec4& x) const {
    // Outputs 0..9: g; 10 + 10 k + i: d_k g. With the tape's gradient: out[5 o] the value,
    // out[5 o + 1 + l] its derivative along x^l.
    std::array<double, 50 * 5> out;
    tape_->evaluateWithGradient(x.data(), out.data());
    MetricJet j;
    for (std::size_t i = 0; i < kPairs.size(); ++i) {
        const auto [m, n] = kPairs[i];
        j.g(m, n) = j.g(n, m) = out[5 * i];
        for (int k = 0; k < 4; ++k) {
            const std::size_t o = 10 + 10 * static_cast<std::size_t>(k) + i;
            j.dg[k](m, n) = j.dg[k](n, m) = out[5 * o];
            for (int l = 0; l < 4; ++l)
                j.ddg[k][l](m, n) = j.ddg[k][l](n, m) = out[5 * o + 1 + static_cast<std::size_t>(l)];
        }
    }
    // Symmetric in k and l exactly (the tape's two routes to d_k d_l g agree only to round-off).
    for (int k = 0; k < 4; ++k)
        for (int l = k + 1; l < 4; ++l) {
            const Mat4 mean = 0.5 * (j.ddg[k][l] + j.ddg[l][k]);
            j.ddg[k][l] = j.ddg[l][k] = mean;
        }
    return j;
}

}  // namespace lc
