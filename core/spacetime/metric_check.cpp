// SPDX-License-Identifier: BSD-3-Clause
#include "core/spacetime/metric_check.hpp"

#include "core/input/ranges.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lc {

std::string componentName(const std::array<std::string, 4>& c, int m, int n) {
    const std::string& a = c[static_cast<std::size_t>(m)];
    const std::string& b = c[static_cast<std::size_t>(n)];
    return "g_" + a + (a.size() == 1 && b.size() == 1 ? "" : ",") + b;
}

std::string signatureAt(const Spacetime& st, const Vec4& x) {
    const Mat4 g = st.metric(x);
    if (!g.allFinite()) return "(undefined)";
    const Eigen::SelfAdjointEigenSolver<Mat4> eig(g, Eigen::EigenvaluesOnly);
    const double scale = eig.eigenvalues().cwiseAbs().maxCoeff();
    std::vector<double> values(eig.eigenvalues().data(), eig.eigenvalues().data() + 4);
    std::sort(values.begin(), values.end(), [](double a, double b) { return a > b; });
    std::string s = "(";
    for (std::size_t i = 0; i < 4; ++i)
        s += std::string(i ? "," : "") + (std::abs(values[i]) <= 1e-14 * scale ? "0" : values[i] > 0 ? "+" : "-");
    return s + ")";
}

std::string metricProblemAt(const Spacetime& st, const Vec4& x) {
    Mat4 g;
    std::array<Mat4, 4> dg;
    st.metricAndDerivatives(x, g, dg);
    const auto names = st.coordinateNames();
    for (int m = 0; m < 4; ++m)
        for (int n = m; n < 4; ++n) {
            if (!std::isfinite(g(m, n))) return componentName(names, m, n) + " = " + input::formatBound(g(m, n));
            for (std::size_t k = 0; k < 4; ++k)
                if (!std::isfinite(dg[k](m, n)))
                    return "d" + componentName(names, m, n) + "/d" + names[k] + " = " + input::formatBound(dg[k](m, n));
        }
    const std::string sig = signatureAt(st, x);
    if (sig.find('0') != std::string::npos) return "the metric is singular (det g = 0): signature " + sig;
    if (sig != "(+,-,-,-)")
        return "the metric is not Lorentzian: its eigenvalues have signs " + sig +
               " in the program's convention (+,-,-,-)";
    return "";
}

}  // namespace lc

namespace lc {

Mat4 lieDerivative(const Spacetime& st, const Vec4& x, const Vec4& xi, const Mat4& dxi) {
    Mat4 g;
    std::array<Mat4, 4> dg;
    st.metricAndDerivatives(x, g, dg);
    Mat4 l = Mat4::Zero();
    for (std::size_t k = 0; k < 4; ++k) l += xi(static_cast<int>(k)) * dg[k];
    // dxi(m, k) = d_m xi^k
    l += dxi * g + g * dxi.transpose();
    return l;
}

bool rotationSymmetricAbout(const Spacetime& st, const std::vector<Vec4>& samples, int axis) {
    // xi = e_axis x r: xi^j = -x^k, xi^k = x^j for the cyclic order (axis, j, k).
    const int j = 1 + axis % 3, k = 1 + (axis + 1) % 3;
    Mat4 dxi = Mat4::Zero();
    dxi(j, k) = 1;   // d_j xi^k (lieDerivative's dxi(m, k) = d_m xi^k)
    dxi(k, j) = -1;  // d_k xi^j
    for (const Vec4& x : samples) {
        Vec4 xi = Vec4::Zero();
        xi(j) = -x(k);
        xi(k) = x(j);
        const Mat4 g = st.metric(x);
        if (!g.allFinite()) continue;
        const Mat4 l = lieDerivative(st, x, xi, dxi);
        if (!(l.cwiseAbs().maxCoeff() <= 1e-9 * g.cwiseAbs().maxCoeff() * (1 + x.tail<3>().norm()))) return false;
    }
    return true;
}

bool rotationSymmetricAboutZ(const Spacetime& st, const std::vector<Vec4>& samples) {
    return rotationSymmetricAbout(st, samples, 3);
}

std::string whyNoCircularOrbits(const Spacetime& st, const std::vector<Vec4>& samples) {
    std::size_t finite = 0;
    const Mat4 mirror = Vec4(1, 1, 1, -1).asDiagonal();
    for (const Vec4& x : samples) {
        Mat4 g;
        std::array<Mat4, 4> dg;
        st.metricAndDerivatives(x, g, dg);
        if (!g.allFinite() || !dg[0].allFinite()) continue;
        ++finite;
        const double size = g.cwiseAbs().maxCoeff() * (1 + x.tail<3>().norm());
        if (!(dg[0].cwiseAbs().maxCoeff() <= 1e-9 * size)) return "g depends on t (not stationary)";
        const Vec4 reflected(x(0), x(1), x(2), -x(3));
        if (!((mirror * st.metric(reflected) * mirror - g).cwiseAbs().maxCoeff() <= 1e-9 * size))
            return "z -> -z does not leave g unchanged (no mirror plane z = 0)";
    }
    if (2 * finite < samples.size()) return "g is not finite at most events checked";
    if (!rotationSymmetricAboutZ(st, samples)) return "rotations about the z axis do not leave g unchanged";
    return "";
}

}  // namespace lc
