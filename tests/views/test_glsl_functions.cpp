// Each GLSL function against its C++ twin at sample points, evaluated on the GPU (under Xvfb:
// Mesa llvmpipe) and read back bit for bit: the metric and its gradient generated from every
// metric's code (core/codegen), against lc::Spacetime::metricAndDerivatives in double, at
// points that include the Kerr horizon and the Goedel axis, and for a metric defined only in
// this test. Tolerance: single precision. Each entry is a short chain of float operations on
// inputs of size ~|x|, so its error is a few ulp of the largest intermediate term; we allow
// 2e-5 x (1 + |value| + scale of the inputs' terms), i.e. ~100 float ulp, far below any
// formula error (a wrong sign, factor or index is off by O(1)).
#include "core/codegen/symbolic_metric.hpp"
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"
#include "lightconeGlslProbe.h"
#include "lightconeMetricGlsl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>

namespace {
using namespace lc;

// Defined only here: with nothing else written, its GLSL exists and is right.
class RippleMetric final : public CodedMetric<RippleMetric> {
public:
    std::string name() const override { return "test-ripple"; }
    std::map<std::string, double> parameters() const override { return {}; }
    std::array<std::string, 4> coordinateNames() const override { return {"t", "x", "y", "z"}; }
    template <class S>
    Eigen::Matrix<S, 4, 4> g(const Eigen::Matrix<S, 4, 1>& X) const {
        using std::exp;
        using std::sin;
        using std::tanh;
        const S h = S(0.2) * sin(X(0) - X(3)) * exp(-X(1) * X(1)) + S(0.05) * tanh(S(3.0) * X(2));
        Eigen::Matrix<S, 4, 4> m = Eigen::Matrix<S, 4, 4>::Zero();
        m(0, 0) = S(1.0) + h;
        m(0, 1) = m(1, 0) = S(0.1) * h;
        m(1, 1) = -(S(1.0) - h);
        m(2, 2) = S(-1.0);
        m(3, 3) = -(S(1.0) + S(0.5) * h * h);
        return m;
    }
};

// lcOut[0..15] = g, lcOut[16 + 16 k ..] = d g / d x^k (column-major, as GLSL stores mat4).
const char* kMetricProbeBody =
    "mat4 g, d0, d1, d2, d3; lcMetric(lcIn, g, d0, d1, d2, d3);"
    "for (int m = 0; m < 4; ++m) for (int n = 0; n < 4; ++n) {"
    "  lcOut[4 * m + n] = g[m][n]; lcOut[16 + 4 * m + n] = d0[m][n]; lcOut[32 + 4 * m + n] = d1[m][n];"
    "  lcOut[48 + 4 * m + n] = d2[m][n]; lcOut[64 + 4 * m + n] = d3[m][n]; }"
    "lcOut[80] = lcBoundary(lcIn);";

void expectGpuMetricMatches(const Spacetime& st, const std::vector<Vec4>& points) {
    SCOPED_TRACE(st.name());
    const codegen::GeneratedGlsl glsl = codegen::metricGlsl(*st.symbolic());
    std::vector<std::array<float, 4>> inputs;
    for (const Vec4& x : points) inputs.push_back({float(x(0)), float(x(1)), float(x(2)), float(x(3))});
    const auto gpu = views::evaluateOnGpu({views::metricShaderFunctions(st), kMetricProbeBody, 81}, inputs);
    double worst = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        // The C++ reference at the float-rounded point the GPU saw.
        const Vec4 x(inputs[i][0], inputs[i][1], inputs[i][2], inputs[i][3]);
        Mat4 g;
        std::array<Mat4, 4> dg;
        st.metricAndDerivatives(x, g, dg);
        const double scale = 1 + x.cwiseAbs().maxCoeff();
        for (int m = 0; m < 4; ++m)
            for (int n = 0; n < 4; ++n) {
                const double eg = std::abs(gpu[i][std::size_t(4 * m + n)] - g(m, n)) / (1 + std::abs(g(m, n)) * scale);
                EXPECT_LT(eg, 2e-5) << "g" << m << n << " at " << x.transpose();
                worst = std::max(worst, eg);
                for (int k = 0; k < 4; ++k) {
                    const double v = gpu[i][std::size_t(16 + 16 * k + 4 * m + n)];
                    const double e = std::abs(v - dg[k](m, n)) / (1 + std::abs(dg[k](m, n)) * scale);
                    EXPECT_LT(e, 2e-5) << "d" << k << " g" << m << n << " at " << x.transpose() << ": GPU " << v << " CPU "
                                       << dg[k](m, n);
                    worst = std::max(worst, e);
                }
            }
    }
    std::printf("%s: %zu points, %d generated temporaries, worst scaled error %.2e\n", st.name().c_str(), points.size(),
                glsl.temporaries, worst);
}

TEST(GlslFunctions, GeneratedMetricAndGradientMatchCoreForEveryMetric) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    const double rh = kerr.outerHorizon();
    expectGpuMetricMatches(Minkowski(), {Vec4(0, 1, 2, 3)});
    expectGpuMetricMatches(Schwarzschild(1.0), {Vec4(0, 10, 0, 0), Vec4(0, 1.2, 1.2, 0.3), Vec4(0, 2.05, 0, 0)});
    expectGpuMetricMatches(kerr, {Vec4(0, 10, -3, 2), Vec4(0, rh * 1.02, 0, 0.1), Vec4(0, 0.5, 0.5, 1.9), Vec4(0, 0.1, 0, 3)});
    expectGpuMetricMatches(KerrNewman(1.0, 0.5, 0.6), {Vec4(0, 3, 1, -1), Vec4(0, 1.9, 0, 0.2)});
    expectGpuMetricMatches(Alcubierre(2.0, 1.0, 8.0), {Vec4(0, 0.2, 0, 0.5), Vec4(0.3, 1.5, 0.2, 0), Vec4(1, 2.1, 0, 0.4)});
    expectGpuMetricMatches(GodelCartesian(1.0), {Vec4(0, 0, 0, 0), Vec4(0, 0, 0, 5), Vec4(0, 1.9, 0.3, 0), Vec4(0, -2, 0.01, 1)});
    expectGpuMetricMatches(RippleMetric(), {Vec4(0.5, 0.2, -0.3, 0.1), Vec4(3, 1, 1, -2)});
}

TEST(GlslFunctions, GeneratedBoundaryIsKerrsHorizonFunction) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    const double rh = kerr.outerHorizon(), x = std::sqrt(rh * rh + 0.81);
    const auto gpu = views::evaluateOnGpu({views::metricShaderFunctions(kerr), kMetricProbeBody, 81},
                                          {{0.f, float(x), 0.f, 0.f}, {0.f, 10.f, 0.f, 0.f}});
    EXPECT_NEAR(gpu[0][80], 0.0, 1e-6);  // on the horizon
    EXPECT_NEAR(gpu[1][80], kerr.boundaryFunction<double>(Vec4(0, 10, 0, 0)), 1e-6);
}

TEST(GlslFunctions, ProbeRefusesBadRequestsAndTransfersFloatsExactly) {
    EXPECT_THROW(views::evaluateOnGpu({"", "lcOut[0] = 1.0;", 1}, {}), std::invalid_argument);
    EXPECT_THROW(views::evaluateOnGpu({"", "lcOut[0] = 1.0;", 0}, {{0, 0, 0, 0}}), std::invalid_argument);
    // Exact transfer: a value with every mantissa bit set comes back bit for bit.
    const auto v = views::evaluateOnGpu({"", "lcOut[0] = lcIn.x; lcOut[1] = -lcIn.y * 2.0;", 2}, {{1.99999988f, 3.0e-38f, 0, 0}});
    EXPECT_EQ(v[0][0], 1.99999988f);
    EXPECT_EQ(v[0][1], -6.0e-38f);
}

}  // namespace
