// SPDX-License-Identifier: BSD-3-Clause
// Metrics written once as code also give their GLSL: the recorded expression of every metric,
// and its symbolic derivatives, agree with the metric's own code (values through g<double>,
// derivatives through Eigen's AutoDiffScalar, an independent differentiation) at points that
// include the Kerr horizon and the Goedel axis; the generated GLSL computes each distinct
// subexpression once; the operations of formulas with cases, and core formulas recorded on
// symbols, equal their double versions. The GPU evaluation of the same GLSL is tested in
// tests/views.
#include "core/codegen/function_glsl.hpp"
#include "core/codegen/symbolic_metric.hpp"
#include "core/colour/srgb.hpp"
#include "core/numerics/bessel.hpp"
#include "core/scene/sky.hpp"
#include "core/sr/doppler.hpp"
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"
#include "tests/common/test_metric.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

namespace {
using namespace lc;
using codegen::Differentiator;
using codegen::evaluate;

struct Case {
    std::shared_ptr<const Spacetime> metric;
    std::vector<Vec4> points;
};

std::vector<Case> cases() {
    const auto kerr = std::make_shared<KerrNewman>(1.0, 0.9, 0.0);
    const double rh = kerr->outerHorizon();
    return {
        {std::make_shared<Minkowski>(), {Vec4(0, 1, 2, 3)}},
        {std::make_shared<Schwarzschild>(1.0), {Vec4(0, 10, 0, 0), Vec4(0, 1.2, 1.2, 0.3), Vec4(0, 2.0001, 0, 0)}},
        {kerr, {Vec4(0, 10, -3, 2), Vec4(0, rh * 1.01, 0, 0.1), Vec4(0, 0.5, 0.5, 1.9), Vec4(0, 0, 0, 3)}},
        {std::make_shared<KerrNewman>(1.0, 0.5, 0.6), {Vec4(0, 3, 1, -1), Vec4(0, 1.9, 0, 0.2)}},
        {std::make_shared<Alcubierre>(2.0, 1.0, 8.0),
         {Vec4(0, 0, 0, 0.5), Vec4(0.3, 1.5, 0.2, 0), Vec4(1, 2.1, 0, 0.4)}},
        {std::make_shared<GodelCartesian>(1.0),
         {Vec4(0, 0, 0, 0), Vec4(0, 0, 0, 5), Vec4(0, 1.9, 0.3, 0), Vec4(0, -2, 0.01, 1)}},
        {std::make_shared<GodelCylindrical>(0.7), {Vec4(0, 0.5, 1.0, 0), Vec4(0, 1.4, 0, 2)}},
        {std::make_shared<lc::test::RippleMetric>(), {Vec4(0.5, 0.2, -0.3, 0.1), Vec4(3, 1, 1, -2)}},
    };
}

TEST(Codegen, EveryMetricsExpressionAndDerivativesMatchItsCode) {
    for (const Case& c : cases()) {
        const auto symbolic = c.metric->symbolic();
        ASSERT_TRUE(symbolic.has_value()) << c.metric->name();
        for (const Vec4& x : c.points) {
            const std::array<double, 4> xa{x(0), x(1), x(2), x(3)};
            Mat4 g;
            std::array<Mat4, 4> dg;
            c.metric->metricAndDerivatives(x, g, dg);
            for (int m = 0; m < 4; ++m)
                for (int n = 0; n < 4; ++n) {
                    const double scale = 1 + std::abs(g(m, n));
                    EXPECT_NEAR(evaluate(symbolic->g(m, n), xa), g(m, n), 1e-13 * scale)
                        << c.metric->name() << " g" << m << n;
                }
            for (int k = 0; k < 4; ++k) {
                Differentiator d(k);
                for (int m = 0; m < 4; ++m)
                    for (int n = 0; n < 4; ++n)
                        EXPECT_NEAR(evaluate(d(symbolic->g(m, n)), xa), dg[k](m, n),
                                    1e-11 * (1 + std::abs(dg[k](m, n))))
                            << c.metric->name() << " d" << k << " g" << m << n << " at " << x.transpose();
            }
        }
    }
}

TEST(Codegen, KerrBoundaryIsTheOuterHorizonForCpuAndGpu) {
    const KerrNewman kerr(1.0, 0.9, 0.3);
    const auto s = kerr.symbolic();
    ASSERT_TRUE(s->boundary.has_value());
    const double rh = kerr.outerHorizon();
    // On the equator the Boyer-Lindquist radius is sqrt(x^2 + y^2 - a^2).
    const double x = std::sqrt(rh * rh + 0.81);
    EXPECT_NEAR(evaluate(*s->boundary, {0, x, 0, 0}), 0.0, 1e-12);
    EXPECT_EQ(kerr.boundary(Vec4(0, x * 1.001, 0, 0)), Boundary::None);
    EXPECT_EQ(kerr.boundary(Vec4(0, x * 0.999, 0, 0)), Boundary::Horizon);
    EXPECT_FALSE(GodelCartesian(1.0).symbolic()->boundary.has_value());
    EXPECT_NE(codegen::metricGlsl(*GodelCartesian(1.0).symbolic()).source.find("return 1.0;"), std::string::npos);
}

TEST(Codegen, GlslComputesEachSubexpressionOncePerFunction) {
    for (const Case& c : cases()) {
        const codegen::GeneratedGlsl glsl = codegen::metricGlsl(*c.metric->symbolic());
        EXPECT_NE(glsl.source.find("void lcMetric(vec4 X, out mat4 g, out mat4 dg0"), std::string::npos);
        EXPECT_NE(glsl.source.find(c.metric->name()), std::string::npos) << "names its origin";
        std::set<std::string> rhs;
        std::istringstream lines(glsl.source);
        const std::regex temporary(R"(^\s*float t\d+ = (.*);$)");
        int count = 0;
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("float lcBoundary", 0) == 0) rhs.clear();  // a function of its own
            std::smatch m;
            if (!std::regex_match(line, m, temporary)) continue;
            ++count;
            EXPECT_TRUE(rhs.insert(m[1]).second) << c.metric->name() << ": computed twice: " << m[1];
        }
        EXPECT_EQ(count, glsl.temporaries);
    }
    // Flat space needs no arithmetic at all; Kerr's metric and 40 derivative entries stay small.
    EXPECT_EQ(codegen::metricGlsl(*Minkowski().symbolic()).temporaries, 0);
    EXPECT_LT(codegen::metricGlsl(*KerrNewman(1, 0.9, 0).symbolic()).temporaries, 400);
}

// The operations of formulas with cases and angles (pow, atan2, acos, min, max, ifPositive):
// values against <cmath> and exact derivatives against central differences.
TEST(Codegen, CaseAndAngleOperationsEvaluateAndDifferentiateExactly) {
    using codegen::Expr;
    const Expr x0 = Expr::coordinate(0), x1 = Expr::coordinate(1), x2 = Expr::coordinate(2), x3 = Expr::coordinate(3);
    const Expr f = pow(x0, x1) + atan2(x2, x3) + acos(Expr(0.3) * x0) + min(x1, x2) * max(x0, x3) +
                   ifPositive(x3 - Expr(0.5), x0 * x0, x1 * x2);
    auto direct = [](const std::array<double, 4>& x) {
        return std::pow(x[0], x[1]) + std::atan2(x[2], x[3]) + std::acos(0.3 * x[0]) +
               std::min(x[1], x[2]) * std::max(x[0], x[3]) + (x[3] > 0.5 ? x[0] * x[0] : x[1] * x[2]);
    };
    for (const std::array<double, 4>& x :
         {std::array<double, 4>{1.3, 0.7, -0.4, 0.9}, {2.1, 1.9, 0.8, -0.6}, {0.4, 2.5, 3.0, 0.2}}) {
        EXPECT_NEAR(evaluate(f, x), direct(x), 1e-14 * std::abs(direct(x)));
        for (int k = 0; k < 4; ++k) {
            std::array<double, 4> up = x, down = x;
            up[std::size_t(k)] += 1e-6;
            down[std::size_t(k)] -= 1e-6;
            const double numeric = (direct(up) - direct(down)) / 2e-6;
            EXPECT_NEAR(evaluate(Differentiator(k)(f), x), numeric, 1e-7 * (1 + std::abs(numeric))) << "d/dx" << k;
        }
    }
}

// Core formulas written once as templates give the same values recorded on symbols as in
// double: the sky lookup, the sRGB decode (both cases and negatives) and the aberration that the
// shaders' lcSkyUv, lcSrgbDecode and lcAberrateToRest are generated from.
TEST(Codegen, FormulasRecordedOnSymbolsEqualTheirDoubleInstances) {
    using codegen::Expr;
    using codegen::vectorSymbol;
    const Eigen::Matrix<Expr, 2, 1> uv = skyUv(vectorSymbol<3>("d"));
    for (const Vec3& d :
         {Vec3(0.3, -0.4, 0.866).normalized(), Vec3(0, 0, 1), Vec3(-1, 0, 0), Vec3(0.2, 0.1, -1.5).normalized()}) {
        const std::map<std::string, double> at{{"d.x", d(0)}, {"d.y", d(1)}, {"d.z", d(2)}};
        const Vec2 cpu = skyUv(d);
        EXPECT_DOUBLE_EQ(evaluate(uv(0), {}, at), cpu(0));
        EXPECT_DOUBLE_EQ(evaluate(uv(1), {}, at), cpu(1));
    }
    const Expr decoded = colour::srgbToLinear(Expr::symbol("e"));
    for (double e : {-0.5, -0.01, 0.0, 0.02, 0.04045, 0.0405, 0.5, 1.0, 1.7})
        EXPECT_DOUBLE_EQ(evaluate(decoded, {}, {{"e", e}}), colour::srgbDecode(e)) << e;
    const Eigen::Matrix<Expr, 3, 1> k = sr::boostDirection<Expr>(-vectorSymbol<3>("beta"), vectorSymbol<3>("k"));
    const Vec3 beta(0.6, -0.3, 0.5), kIn = Vec3(-0.2, 0.9, 0.4).normalized();
    const std::map<std::string, double> at{{"beta.x", beta(0)}, {"beta.y", beta(1)}, {"beta.z", beta(2)},
                                           {"k.x", kIn(0)},     {"k.y", kIn(1)},     {"k.z", kIn(2)}};
    const Vec3 cpu = sr::aberrateToRest(beta, kIn);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(evaluate(k(i), {}, at), cpu(i), 1e-15);
    EXPECT_THROW(evaluate(k(0), {}, {}), std::out_of_range);  // a symbol without a value is named
}

// The GPU's Bessel functions: the approximation (Abramowitz and Stegun 9.4.1-9.4.6, |error| <
// 5e-8) against std::cyl_bessel_j from -60 to 60, its recorded expression (what becomes GLSL)
// against its double instance, and J1' (lc::besselJ1Derivative, which the tape and the symbolic
// derivative both instantiate) against the identity J1' = (J0 - J2)/2, through its series branch
// near 0.
TEST(Codegen, BesselApproximationHoldsItsPublishedBoundAndJ1PrimeTheIdentity) {
    const codegen::Expr x = codegen::Expr::coordinate(0);
    const codegen::Expr j0 = besselJ0Approximation(x), j1 = besselJ1Approximation(x);
    double worst0 = 0, worst1 = 0, worstPrime = 0;
    for (int i = -6000; i <= 6000; ++i) {
        const double v = 0.01 * i + 1e-3 * (i % 7);
        worst0 = std::max(worst0, std::abs(besselJ0Approximation(v) - besselJ0(v)));
        worst1 = std::max(worst1, std::abs(besselJ1Approximation(v) - besselJ1(v)));
        EXPECT_NEAR(codegen::evaluate(j0, {v, 0, 0, 0}), besselJ0Approximation(v), 1e-15) << v;
        EXPECT_NEAR(codegen::evaluate(j1, {v, 0, 0, 0}), besselJ1Approximation(v), 1e-15) << v;
        const double identity = 0.5 * (besselJ0(v) - std::cyl_bessel_j(2.0, std::abs(v)));  // J2 is even
        worstPrime = std::max(worstPrime, std::abs(besselJ1Derivative(v, besselJ0(v), besselJ1(v)) - identity));
    }
    for (const double v : {0.0, 1e-9, -4e-4, 9.99e-4, 1.001e-3}) {
        const double identity = 0.5 * (besselJ0(v) - std::cyl_bessel_j(2.0, std::abs(v)));
        worstPrime = std::max(worstPrime, std::abs(besselJ1Derivative(v, besselJ0(v), besselJ1(v)) - identity));
    }
    std::printf("Bessel approximation for the GPU: |J0 error| <= %.1e, |J1 error| <= %.1e; J1' within %.1e\n", worst0,
                worst1, worstPrime);
    EXPECT_LT(worst0, 5e-8);
    EXPECT_LT(worst1, 5e-8);
    EXPECT_LT(worstPrime, 1e-13);
    EXPECT_NEAR(besselJ0(2.404825557695773), 0, 1e-15);       // the first zero of J0 (A and S table 9.5)
    EXPECT_NEAR(besselJ1(-1.0), -0.4400505857449335, 1e-15);  // odd
}

TEST(Codegen, ConstantsOutsideFloatRangeAreRefused) {
    EXPECT_THROW(codegen::metricGlsl(*GodelCartesian(1e-30).symbolic()), std::invalid_argument);
    EXPECT_NO_THROW(codegen::metricGlsl(*GodelCartesian(1e-3).symbolic()));
}

}  // namespace
