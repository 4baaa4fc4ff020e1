// SPDX-License-Identifier: BSD-3-Clause
// Metrics typed as text (core/formula): the expression language against hand-computed values,
// its errors with their columns, the line element's reading as a quadratic form, hostile input
// refused in bounded time, and formula versions of the built-in metrics against the built-ins
// themselves (an independent implementation: C++ templates with Eigen's automatic
// differentiation), g, dg and Hamilton's equations, including the tape's forward-mode
// derivatives against the symbolic ones.
#include "core/codegen/expression.hpp"
#include "core/formula/expression_tape.hpp"
#include "core/formula/formula_expressions.hpp"
#include "core/formula/formula_metric.hpp"
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/spacetime/metric_check.hpp"
#include "tests/common/test_metric.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>

namespace {
using namespace lc;
using namespace lc::formula;

double valueOf(const std::string& text, const std::array<double, 4>& x = {0.5, 2, 3, 0.25}) {
    FormulaScope scope({"t", "x", "y", "z"});
    scope.addConstant("M", 1.5);
    const FormulaTree tree = parseFormula(text);
    return codegen::evaluate(scalarFormula(*tree, scope).expr, x);
}

// The error's message and where it points (byte offset), from parsing and reading together.
std::pair<std::string, std::size_t> errorOf(const std::string& text) {
    try {
        (void)valueOf(text);
    } catch (const FormulaError& e) {
        return {e.problem(), e.offset()};
    }
    return {"", 0};
}

TEST(FormulaLanguage, PrecedenceAndFunctionsAsWrittenInTextbooks) {
    EXPECT_DOUBLE_EQ(valueOf("1 + 2*3"), 7);
    EXPECT_DOUBLE_EQ(valueOf("-x^2"), -4);    // -(x^2)
    EXPECT_DOUBLE_EQ(valueOf("2^3^2"), 512);  // right-associative
    EXPECT_DOUBLE_EQ(valueOf("2^-1"), 0.5);   // a signed exponent
    EXPECT_DOUBLE_EQ(valueOf("x**3"), 8);     // Python's power
    EXPECT_DOUBLE_EQ(valueOf("(-2)^2"), 4);   // whole powers of negative bases
    EXPECT_DOUBLE_EQ(valueOf("8/4/2"), 1);    // left-associative
    EXPECT_DOUBLE_EQ(valueOf("2*M/x"), 1.5);  // a parameter
    EXPECT_DOUBLE_EQ(valueOf("x^0.5"), std::sqrt(2.0));
    EXPECT_DOUBLE_EQ(valueOf("1.5e-1 * 2E1"), 3);
    EXPECT_DOUBLE_EQ(valueOf("atan2(y, x)"), std::atan2(3.0, 2.0));
    EXPECT_DOUBLE_EQ(valueOf("sinh(z) + cosh(z) + tanh(z)"), std::sinh(0.25) + std::cosh(0.25) + std::tanh(0.25));
    EXPECT_DOUBLE_EQ(valueOf("asin(z) + acos(z) + atan(z) + tan(z)"),
                     std::asin(0.25) + std::acos(0.25) + std::atan(0.25) + std::tan(0.25));
    EXPECT_DOUBLE_EQ(valueOf("min(x, y) + max(x, y) + abs(-t)"), 2 + 3 + 0.5);
    EXPECT_DOUBLE_EQ(valueOf("exp(log(y)) + pow(x, 3)"), 3 + 8);
    EXPECT_DOUBLE_EQ(valueOf("step(x, 0.5)"), 0.5 * (1 + std::tanh(4.0)));
    EXPECT_DOUBLE_EQ(valueOf("sin(pi/2)\n  * cos(0)"), 1);  // lines and spaces
}

TEST(FormulaLanguage, ErrorsSayWhatAndPointWhere) {
    EXPECT_EQ(errorOf("2*M/rr").second, 4u);
    EXPECT_NE(errorOf("2*M/rr").first.find("unknown name 'rr'"), std::string::npos);
    EXPECT_NE(errorOf("(x + 1").first.find("never closed"), std::string::npos);
    EXPECT_NE(errorOf("x + 1)").first.find("')' without a matching '('"), std::string::npos);
    EXPECT_EQ(errorOf("x + 1)").second, 5u);
    EXPECT_NE(errorOf("x +").first.find("ends where a value was expected"), std::string::npos);
    EXPECT_NE(errorOf("2x").first.find("write '*'"), std::string::npos);
    EXPECT_NE(errorOf("1e400").first.find("beyond double's range"), std::string::npos);
    EXPECT_NE(errorOf("sin(x, y)").first.find("sin takes 1 argument, not 2"), std::string::npos);
    EXPECT_NE(errorOf("sine(x)").first.find("unknown function 'sine'"), std::string::npos);
    EXPECT_NE(errorOf("sin").first.find("is a function"), std::string::npos);
    EXPECT_NE(errorOf("dx * 2").first.find("belongs in the line element"), std::string::npos);
    EXPECT_NE(errorOf("x + \xce\xb8").first.find("byte 0xCE"), std::string::npos);
    EXPECT_NE(errorOf("nan").first.find("unknown name 'nan'"), std::string::npos);
    EXPECT_NE(errorOf("").first.find("empty"), std::string::npos);
    const std::string shown = describeAt("2*M/rr", 4, "unknown name 'rr'");
    EXPECT_EQ(shown, "column 5: unknown name 'rr'\n    2*M/rr\n        ^");
}

TEST(FormulaLanguage, HostileTextIsRefusedInBoundedTime) {
    const auto start = std::chrono::steady_clock::now();
    EXPECT_NE(errorOf(std::string(1000, '(') + "x" + std::string(1000, ')')).first.find("inside each other"),
              std::string::npos);
    EXPECT_NE(errorOf(std::string(100000, '(') + "x" + std::string(100000, ')')).first.find("bytes long"),
              std::string::npos);
    std::string sum = "x";
    for (int i = 0; i < 100000; ++i) sum += "+x";
    EXPECT_NE(errorOf(sum).first.find("bytes long"), std::string::npos);  // 200 kB: over the size limit
    std::string deep = "x";
    for (int i = 0; i < 5000; ++i) deep += "+x";  // 10 kB, 5000 operations on one path
    EXPECT_NE(errorOf(deep).first.find("operations deep"), std::string::npos);
    EXPECT_NE(errorOf(std::string(100000, 'a')).first.find("bytes long"), std::string::npos);
    EXPECT_NE(errorOf(std::string(1000, 'a')).first.find("a name of 1000 characters"), std::string::npos);
    EXPECT_NE(errorOf(std::string(10u << 20, ' ')).first.find("bytes long"), std::string::npos);
    std::string minus(150, '-');
    EXPECT_NE(errorOf(minus + "x").first.find("inside each other"), std::string::npos);
    EXPECT_NE(errorOf(std::string("x\0y", 3)).first.find("control byte 0x00"), std::string::npos);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

FormulaMetricSource source(const std::string& ds2, std::vector<std::string> definitions = {}) {
    FormulaMetricSource s;
    s.lineElement = FormulaText{"ds2", ds2};
    for (std::size_t i = 0; i < definitions.size(); ++i)
        s.definitions.push_back({"define[" + std::to_string(i) + "]", definitions[i]});
    return s;
}

std::string metricError(const FormulaMetricSource& s, const std::map<std::string, double>& values = {}) {
    try {
        FormulaMetric m(s, values);
    } catch (const FormulaMetricError& e) {
        return e.what();
    }
    return "";
}

TEST(FormulaLineElement, IsReadAsAQuadraticFormInTheDifferentials) {
    // (-,+,+,+) as written; the program's (+,-,-,-) after reading. A cross term 2 k dt dy is g_ty = k.
    FormulaMetric m(source("-dt^2 + (dx + x*dz)^2 + 2*0.25*dt*dy + dy*dy + 3*dz^2"), {});
    const Mat4 g = m.metric(Vec4(0, 2, 0, 0));
    Mat4 expected;
    expected << 1, 0, -0.25, 0,  //
        0, -1, 0, -2,            //
        -0.25, 0, -1, 0,         //
        0, -2, 0, -(4 + 3);
    EXPECT_LT((g - expected).cwiseAbs().maxCoeff(), 1e-15) << g;
    for (const auto& [ds2, why] : std::vector<std::pair<std::string, std::string>>{
             {"dt^3", "may be squared"},
             {"sin(dt)*dt", "inside sin"},
             {"dt^2 + 1", "joins a term of degree 2"},
             {"dt^2/dx", "division by a differential"},
             {"dt*dx*dy", "degree 3"},
             {"x^2", "of degree 0"},
             {"dt^2 + dq^2", "unknown name 'dq'"},
         }) {
        const std::string e = metricError(source(ds2));
        EXPECT_NE(e.find(why), std::string::npos) << ds2 << ": " << e;
        EXPECT_EQ(e.rfind("ds2: ", 0), 0u) << e;
    }
}

TEST(FormulaLineElement, DefinitionsParametersAndTheirErrors) {
    FormulaMetricSource s = source("-(1 - 2*M/r)*dt^2 + dx^2 + dy^2 + dz^2", {"r = sqrt(x^2 + y^2 + z^2)"});
    s.parameters.push_back({"M", 1, 0, 10, "mass"});
    FormulaMetric m(s, {{"M", 2}});
    EXPECT_NEAR(m.metric(Vec4(0, 8, 0, 0))(0, 0), 0.5, 1e-15);
    EXPECT_EQ(m.parameters().at("M"), 2);
    EXPECT_NE(metricError(s, {{"M", 11}}).find("expected a number in [0, 10], got 11"), std::string::npos);
    EXPECT_NE(metricError(s, {{"Q", 1}}).find("has no parameter 'Q' (it takes: M)"), std::string::npos);
    FormulaMetricSource selfRef = source("dt^2", {"r = r + 1"});
    EXPECT_NE(metricError(selfRef).find("define[0]: column 5: unknown name 'r'"), std::string::npos)
        << metricError(selfRef);
    FormulaMetricSource taken = source("dt^2", {"x = 1"});
    EXPECT_NE(metricError(taken).find("already defined"), std::string::npos) << metricError(taken);
    FormulaMetricSource differential = source("dt^2", {"dt = 1"});
    EXPECT_NE(metricError(differential).find("differential of a coordinate"), std::string::npos);
    // A definition's columns count from the start of its text, "name =" included.
    FormulaMetricSource unclosed = source("dt^2", {"rr = (x*x + y*y, 2"});
    EXPECT_NE(metricError(unclosed).find("column 16: expected ')' to close the '(' at column 6"), std::string::npos)
        << metricError(unclosed);
    FormulaMetricSource noName = source("dt^2", {"2*x"});
    EXPECT_NE(metricError(noName).find("no '=' found"), std::string::npos);
    FormulaMetricSource none;
    EXPECT_NE(metricError(none).find("needs its line element"), std::string::npos);
}

TEST(FormulaLineElement, DeepDefinitionChainsAreRefusedNotOverflowed) {
    std::vector<std::string> chain{"d0 = x"};
    for (int i = 1; i < 10000; ++i) chain.push_back("d" + std::to_string(i) + " = d" + std::to_string(i - 1) + " + x");
    const std::string e = metricError(source("dt^2 - d9999*dx^2 - dy^2 - dz^2", chain));
    EXPECT_NE(e.find("nest"), std::string::npos) << e;
    // 10^4 definitions side by side are fine.
    std::vector<std::string> wide;
    for (int i = 0; i < 10000; ++i) wide.push_back("w" + std::to_string(i) + " = x*" + std::to_string(i));
    EXPECT_EQ(metricError(source("-dt^2 + (1 + w9999^2)*dx^2 + dy^2 + dz^2", wide)), "");
}

// Formula versions of the built-ins, written as a user would (the files of data/metrics/ hold
// the same text, read through the JSON reader in tests/io).
FormulaMetricSource kerrSource() {
    FormulaMetricSource s =
        source("-dt^2 + dx^2 + dy^2 + dz^2 + f*(dt - ((r*x - a*y)*dx + (r*y + a*x)*dy)/(r^2 + a^2) - z*dz/r)^2",
               {"rho2 = x^2 + y^2 + z^2 - a^2", "r = sqrt(0.5*(rho2 + sqrt(rho2^2 + 4*a^2*z^2)))",
                "f = 2*M*r^3/(r^4 + a^2*z^2)"});
    s.parameters = {{"M", 1, 1e-6, 1e6, ""}, {"a", 0.9, -1e6, 1e6, ""}};
    s.horizon = FormulaText{"horizon", "r/(M + sqrt(M^2 - a^2)) - 1"};
    return s;
}

FormulaMetricSource alcubierreSource() {
    FormulaMetricSource s = source("-dt^2 + (dx - v*f*dt)^2 + dy^2 + dz^2",
                                   {"X = x - v*t", "rs = sqrt(X^2 + y^2 + z^2 + 1e-300)",
                                    "f = (tanh(sigma*(rs + R)) - tanh(sigma*(rs - R)))/(2*tanh(sigma*R))"});
    s.parameters = {{"v", 1, -100, 100, ""}, {"R", 1, 1e-3, 1e6, ""}, {"sigma", 8, 1e-3, 1e3, ""}};
    return s;
}

FormulaMetricSource godelSource() {  // components, in the signature (+,-,-,-)
    FormulaMetricSource s;
    s.mostlyPlus = false;
    s.parameters = {{"a", 1, 1e-3, 1e6, ""}};
    s.definitions = {{"define[0]", "k = 1/(4*a^2)"}, {"define[1]", "c = k/(1 + (x^2 + y^2)*k)"}};
    auto component = [&](int m, int n, const std::string& text) {
        s.components.push_back({FormulaText{"g", text}, {m, n}});
    };
    component(0, 0, "1");
    component(0, 1, "-y/(sqrt(2)*a)");
    component(0, 2, "x/(sqrt(2)*a)");
    component(1, 1, "-(1 - c*x^2 - k*y^2)");
    component(2, 2, "-(1 - c*y^2 - k*x^2)");
    component(1, 2, "(c - k)*x*y");
    component(3, 3, "-1");
    return s;
}

struct Pair {
    std::shared_ptr<const Spacetime> builtin, formula;
    std::vector<Vec4> points;
};

std::vector<Pair> pairs() {
    const double rh = 1 + std::sqrt(1 - 0.81);
    return {
        {std::make_shared<KerrNewman>(1.0, 0.9, 0.0),
         std::make_shared<FormulaMetric>(kerrSource(), std::map<std::string, double>{{"a", 0.9}}),
         {Vec4(0, 10, -3, 2), Vec4(0, rh * 1.01, 0, 0.1), Vec4(0, 0.5, 0.5, 1.9), Vec4(0, 0, 0, 3),
          Vec4(3, -7, 2, -4)}},
        {std::make_shared<KerrNewman>(2.0, -1.2, 0.0),
         std::make_shared<FormulaMetric>(kerrSource(), std::map<std::string, double>{{"M", 2}, {"a", -1.2}}),
         {Vec4(0, 9, 1, -2), Vec4(0, 3, 3, 0.1)}},
        {std::make_shared<Alcubierre>(2.0, 1.0, 8.0),
         std::make_shared<FormulaMetric>(alcubierreSource(), std::map<std::string, double>{{"v", 2}}),
         {Vec4(0, 0, 0, 0.5), Vec4(0.3, 1.5, 0.2, 0), Vec4(1, 2.1, 0, 0.4), Vec4(0, 0, 0, 0)}},
        {std::make_shared<GodelCartesian>(1.3),
         std::make_shared<FormulaMetric>(godelSource(), std::map<std::string, double>{{"a", 1.3}}),
         {Vec4(0, 0, 0, 0), Vec4(0, 0, 0, 5), Vec4(0, 2.5, 0.3, 0), Vec4(0, -2.6, 0.01, 1)}},
    };
}

double relative(const Mat4& a, const Mat4& b) {
    return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

TEST(FormulaMetric, BuiltinsWrittenAsTextGiveTheSameMetricAndExactDerivatives) {
    for (const Pair& p : pairs())
        for (const Vec4& x : p.points) {
            SCOPED_TRACE(p.builtin->name() + " at " + std::to_string(x(1)) + "," + std::to_string(x(2)) + "," +
                         std::to_string(x(3)));
            Mat4 g1, g2;
            std::array<Mat4, 4> d1, d2;
            p.builtin->metricAndDerivatives(x, g1, d1);
            p.formula->metricAndDerivatives(x, g2, d2);
            EXPECT_LT(relative(g2, g1), 1e-14);
            EXPECT_LT(relative(p.formula->metric(x), g1), 1e-14);
            for (std::size_t k = 0; k < 4; ++k) EXPECT_LT(relative(d2[k], d1[k]), 1e-12) << "d/dx^" << k;
            // Hamilton's equations: the formula's own flow against the general one of the built-in.
            const Vec4 p0(1.0, 0.3, -0.4, 0.2);
            const HamiltonianFlow f1 = p.builtin->generalFlow(x, p0), f2 = p.formula->flow(x, p0);
            EXPECT_LT((f2.dxdl - f1.dxdl).cwiseAbs().maxCoeff(), 1e-12 * (1 + f1.dxdl.cwiseAbs().maxCoeff()));
            EXPECT_LT((f2.dpdl - f1.dpdl).cwiseAbs().maxCoeff(), 1e-12 * (1 + f1.dpdl.cwiseAbs().maxCoeff()));
            EXPECT_EQ(p.formula->boundary(x), p.builtin->boundary(x));
        }
}

TEST(FormulaMetric, KerrSchildFormIsRecognisedOnlyWhereItHolds) {
    const auto all = pairs();
    EXPECT_TRUE(dynamic_cast<const FormulaMetric&>(*all[0].formula).kerrSchild());   // Kerr
    EXPECT_FALSE(dynamic_cast<const FormulaMetric&>(*all[2].formula).kerrSchild());  // Alcubierre: not flat + square
    EXPECT_FALSE(dynamic_cast<const FormulaMetric&>(*all[3].formula).kerrSchild());  // components
    // Flat plus a square whose vector is not null: the general path, and still the right flow.
    FormulaMetric notNull(source("-dt^2 + dx^2 + dy^2 + dz^2 + 0.3*(dt + 0.5*dx)^2"), {});
    EXPECT_FALSE(notNull.kerrSchild());
    // The inverse from the closed form equals the 4x4 inverse.
    const auto& kerr = *all[0].formula;
    const Vec4 x(0, 4, -2, 1);
    EXPECT_LT(relative(kerr.inverseMetric(x), kerr.metric(x).inverse()), 1e-13);
}

TEST(FormulaMetric, TapeDerivativesEqualTheSymbolicOnesForEveryOperation) {
    // Every operation of the language in one metric: forward mode along the tape against the
    // symbolic derivatives of the expression graph (core/codegen's Differentiator).
    FormulaMetricSource s = source(
        "-(2 + sin(t*x) + cos(y) + tanh(z) + exp(-x^2) + log(2 + y^2) + abs(z - 0.1))*dt^2"
        " + (3 + atan2(y, x) + atan(z) + asin(0.3*z) + acos(0.2*y) + tan(0.1*x))*dx^2"
        " + (2 + sinh(0.2*y) + cosh(0.1*z) + min(x, y) + max(z, t) + step(x - 1, 0.3))*dy^2"
        " + (2 + x^2.5 + pow(y^2 + 1, z) + sqrt(1 + t^2) + besselj0(3*x) + besselj1(2*y - 1)"
        " + besselj1(0.0005*z))*dz^2 + 0.1*x*dt*dz");
    FormulaMetric m(s, {});
    const std::vector<codegen::Expr> entries{m.expressions()(0, 0), m.expressions()(1, 1), m.expressions()(2, 2),
                                             m.expressions()(3, 3), m.expressions()(0, 3)};
    const ExpressionTape tape(entries);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(0.2, 1.7);
    for (int i = 0; i < 50; ++i) {
        const std::array<double, 4> x{u(random), u(random), u(random), u(random)};
        double out[25];
        tape.evaluateWithGradient(x.data(), out);
        for (std::size_t e = 0; e < entries.size(); ++e) {
            EXPECT_NEAR(out[5 * e], codegen::evaluate(entries[e], x), 1e-13 * (1 + std::abs(out[5 * e])));
            for (int k = 0; k < 4; ++k) {
                codegen::Differentiator d(k);
                const double symbolic = codegen::evaluate(d(entries[e]), x);
                EXPECT_NEAR(out[5 * e + 1 + k], symbolic, 1e-12 * (1 + std::abs(symbolic)))
                    << "entry " << e << " d/dx^" << k;
            }
        }
    }
}

TEST(FormulaMetric, ChecksNameTheComponentAndTheSignature) {
    FormulaMetric riemannian(source("dt^2 + dx^2 + dy^2 + dz^2"), {});
    EXPECT_NE(metricProblemAt(riemannian, Vec4(0, 1, 1, 1)).find("not Lorentzian"), std::string::npos);
    EXPECT_EQ(signatureAt(riemannian, Vec4(0, 1, 1, 1)), "(-,-,-,-)");
    FormulaMetric singular(source("-dt^2 + dx^2/x + dy^2 + dz^2"), {});
    EXPECT_EQ(metricProblemAt(singular, Vec4(0, 0, 1, 1)), "g_xx = -inf");
    EXPECT_EQ(metricProblemAt(singular, Vec4(0, 1, 1, 1)), "");
    FormulaMetric degenerate(source("-dt^2 + x*dx^2 + dy^2 + dz^2"), {});
    EXPECT_NE(metricProblemAt(degenerate, Vec4(0, 0, 1, 1)).find("det g = 0"), std::string::npos);
}

// Circular orbits are offered from what the formula is: whyNoCircularOrbits (core/spacetime/
// metric_check) names the symmetry that fails at sample events (d/dt, z -> -z, rotations about
// z); the built-in Kerr has them all; a formula metric needs them and a far field.
TEST(FormulaMetric, CircularOrbitsFollowFromTheSymmetriesOfTheFormula) {
    std::vector<Vec4> events;
    for (int i = 0; i < 16; ++i) events.emplace_back(0.5 * i, 3 + i, 2 - 0.4 * i, 0.3 * i - 2);
    EXPECT_EQ(whyNoCircularOrbits(KerrNewman(1.0, 0.9, 0.0), events), "");
    auto withFarField = [](FormulaMetricSource s) {
        s.asymptoticallyFlat = true;
        s.farMass = FormulaText{"far_field.mass", "1"};
        return s;
    };
    const FormulaMetric ticking(withFarField(source("-(1 - 2/sqrt(x^2+y^2+z^2+1) + 0.01*sin(t))*dt^2 + dx^2 + "
                                                    "dy^2 + dz^2")),
                                {});
    EXPECT_EQ(ticking.whyNoCircularOrbits(), "g depends on t (not stationary)");
    EXPECT_FALSE(ticking.equatorialRadius());
    const FormulaMetric lopsided(
        withFarField(source("-(1 - 2/sqrt(x^2+y^2+z^2+1) + 0.1*z/(x^2+y^2+z^2+1))*dt^2 + dx^2 + dy^2 + dz^2")), {});
    EXPECT_NE(lopsided.whyNoCircularOrbits().find("mirror"), std::string::npos) << lopsided.whyNoCircularOrbits();
    const FormulaMetric squashed(withFarField(source("-(1 - 2/sqrt(2*x^2+y^2+z^2+1))*dt^2 + dx^2 + dy^2 + dz^2")), {});
    EXPECT_NE(squashed.whyNoCircularOrbits().find("rotations"), std::string::npos) << squashed.whyNoCircularOrbits();
    const FormulaMetric round(withFarField(source("-(1 - 2/sqrt(x^2+y^2+z^2+1))*dt^2 + dx^2 + dy^2 + dz^2")), {});
    EXPECT_EQ(round.whyNoCircularOrbits(), "");
    ASSERT_TRUE(round.equatorialRadius());
    // The default label is the distance from the z axis.
    EXPECT_DOUBLE_EQ(codegen::evaluate(*round.equatorialRadius(), {0, 3, 4, 7}), 5.0);
    EXPECT_FALSE(FormulaMetric(source("-(1 - 2/sqrt(x^2+y^2+z^2+1))*dt^2 + dx^2 + dy^2 + dz^2"), {})
                     .equatorialRadius());  // no far field
}

// Found in review: constants are pooled by their bits (NaN, -0 and +0 kept apart); min and max
// treat NaN as std::fmin does in both evaluators; the graph's real depth (powers expand into
// products) is what is limited; a Kerr-Schild vector null at the sample events but not everywhere
// falls back to the general form; the name cannot break out of the GLSL comment.
TEST(FormulaMetric, ReviewFindingsStayFixed) {
    using codegen::Expr;
    const Expr x = Expr::coordinate(1);
    const ExpressionTape pool({Expr(std::nan("")) + x, Expr(-3.0) + x, Expr(1.0) + x, atan2(Expr(0.0), x),
                               atan2(Expr(-0.0), x), atan2(Expr(0.0), x)});
    const std::array<double, 4> at{0, -1, 0, 0};
    double v[6];
    pool.evaluate(at.data(), v);
    EXPECT_TRUE(std::isnan(v[0]));
    EXPECT_EQ(v[1], -4);
    EXPECT_EQ(v[2], 0);
    EXPECT_EQ(v[3], kPi);
    EXPECT_EQ(v[4], -kPi);
    EXPECT_EQ(v[5], kPi);

    const ExpressionTape minimum({min(sqrt(x - Expr(2.0)), Expr(1.0)), max(Expr(1.0), sqrt(x - Expr(2.0)))});
    const std::array<double, 4> inside{0, 1, 0, 0};
    double values[2], withGradient[10];
    minimum.evaluate(inside.data(), values);
    minimum.evaluateWithGradient(inside.data(), withGradient);
    EXPECT_EQ(values[0], 1);
    EXPECT_EQ(withGradient[0], 1);
    EXPECT_EQ(values[1], 1);
    EXPECT_EQ(withGradient[5], 1);

    std::vector<std::string> powers{"p0 = 1 + x^2"};
    for (int i = 1; i <= 200; ++i)
        powers.push_back("p" + std::to_string(i) + " = ((p" + std::to_string(i - 1) + "^16)^16)^-16");
    EXPECT_NE(metricError(source("-dt^2 + p200*dx^2 + dy^2 + dz^2", powers)).find("operations deep"),
              std::string::npos);

    FormulaMetric late(source("-dt^2 + dx^2 + dy^2 + dz^2 + 2/r*(dt - (x*dx + y*dy + z*dz)/r + max(t - 30, 0)*dz)^2",
                              {"r = sqrt(x^2 + y^2 + z^2)"}),
                       {});
    EXPECT_TRUE(late.kerrSchild());  // null wherever it was sampled (t < 24)
    const Vec4 x40(40, 6, -3, 2), p0(1, 0.2, -0.3, 0.1);
    const HamiltonianFlow f = late.flow(x40, p0), g = late.generalFlow(x40, p0);
    EXPECT_LT((f.dpdl - g.dpdl).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((f.dxdl - g.dxdl).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT(relative(late.inverseMetric(x40), late.metric(x40).inverse()), 1e-13);

    FormulaMetricSource named = source("-dt^2 + dx^2 + dy^2 + dz^2");
    named.name = "x\n#error injected";
    EXPECT_EQ(FormulaMetric(named, {}).symbolic()->origin.find('\n'), std::string::npos);
}

}  // namespace
