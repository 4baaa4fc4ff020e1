// SPDX-License-Identifier: BSD-3-Clause
#include "core/formula/formula_metric.hpp"

#include "core/formula/formula_expressions.hpp"
#include "core/input/ranges.hpp"
#include "core/numerics/types.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lc::formula {
namespace {

using codegen::Expr;

[[noreturn]] void fail(const FormulaText& t, std::size_t offset, const std::string& problem) {
    throw FormulaMetricError(t.field, describeAt(t.text, offset, problem));
}

FormulaTree parsed(const FormulaText& t, std::size_t start = 0) {
    try {
        return parseFormula(t.text, start);
    } catch (const FormulaError& e) {
        fail(t, e.offset(), e.problem());
    }
}

ScalarFormula scalar(const FormulaText& t, const FormulaScope& scope, std::size_t start = 0) {
    FormulaTree tree = parsed(t, start);
    try {
        return scalarFormula(*tree, scope);
    } catch (const FormulaError& e) {
        fail(t, e.offset(), e.problem());
    }
}

// A function of the coordinates whose sign stops rays (horizon, other_end), no deeper than the GPU
// compiles.
Expr boundaryExpression(const FormulaText& t, const FormulaScope& scope, const std::string& what) {
    const ScalarFormula f = scalar(t, scope);
    if (graphHeight({f.expr}) > kMaxGraphDepth)
        throw FormulaMetricError(t.field,
                                 what + " nests more than " + std::to_string(kMaxGraphDepth) + " operations deep");
    return f.expr;
}

// A far-field number: a formula of the parameters alone, finite and >= 0.
double constant(const std::optional<FormulaText>& t, const FormulaScope& scope, double fallback, bool signedValue) {
    if (!t) return fallback;
    const ScalarFormula f = scalar(*t, scope);
    if (f.expr.node().op != codegen::Op::Constant)
        fail(*t, 0, "the far field is given by the parameters alone, not by the coordinates");
    const double v = f.expr.node().value;
    if (!std::isfinite(v) || (!signedValue && v < 0))
        fail(*t, 0, "the value " + input::formatBound(v) + " is not " + (signedValue ? "finite" : "finite and >= 0"));
    return v;
}

std::map<std::string, double> checkedValues(const FormulaMetricSource& s, const std::map<std::string, double>& given) {
    try {
        return checkedParameterValues(s.name, s.parameters, given);
    } catch (const ParameterError& e) {
        throw FormulaMetricError(kValueField + e.parameter, e.what());
    }
}

}  // namespace

FormulaMetric::FormulaMetric(FormulaMetricSource source, const std::map<std::string, double>& parameterValues)
    : source_(std::move(source)), values_(checkedValues(source_, parameterValues)) {
    std::unique_ptr<FormulaScope> scopeOwner;
    try {
        if (source_.chart != "cartesian" && source_.chart != "spherical" && source_.chart != "cylindrical")
            throw FormulaMetricError(
                "chart", "unknown chart '" + source_.chart + "' (expected cartesian, spherical or cylindrical)");
        const Chart chart = source_.chart == "spherical"     ? Chart::Spherical
                            : source_.chart == "cylindrical" ? Chart::Cylindrical
                                                             : Chart::Cartesian;
        scopeOwner = std::make_unique<FormulaScope>(source_.coordinates, chart);
    } catch (const std::invalid_argument& e) {
        throw FormulaMetricError("coordinates", e.what());
    }
    FormulaScope& scope = *scopeOwner;
    for (const auto& [name, v] : values_) {
        try {
            scope.addConstant(name, v);
        } catch (const std::invalid_argument& e) {
            throw FormulaMetricError("parameters." + name, e.what());
        }
    }
    for (const FormulaText& d : source_.definitions) {
        std::size_t start = 0;
        std::string name;
        try {
            name = definitionName(d.text, start);
        } catch (const FormulaError& e) {
            fail(d, e.offset(), e.problem());
        }
        const ScalarFormula f = scalar(d, scope, start);
        if (const std::string why = scope.whyTaken(name); !why.empty())
            fail(d, d.text.find(name),
                 why + (scope.has(name) ? " (a definition may not refer to itself or repeat)" : ""));
        scope.addDefinition(name, f.expr, f.depth);
    }

    // g as written, then in the program's signature (+,-,-,-).
    codegen::ExprMatrix4 g = codegen::ExprMatrix4::Zero();
    if (source_.lineElement && !source_.components.empty())
        throw FormulaMetricError("g", "give either the line element ds2 or the components g, not both");
    std::optional<KerrSchildForm> kerrSchild;
    if (source_.lineElement) {
        FormulaTree tree = parsed(*source_.lineElement);
        int depth = 0;
        try {
            g = lineElement(*tree, scope, depth, &kerrSchild);
        } catch (const FormulaError& e) {
            fail(*source_.lineElement, e.offset(), e.problem());
        }
    } else if (!source_.components.empty()) {
        std::array<std::array<bool, 4>, 4> given{};
        for (const auto& [text, mn] : source_.components) {
            const auto [m, n] = mn;
            if (given[static_cast<std::size_t>(m)][static_cast<std::size_t>(n)])
                throw FormulaMetricError(text.field, componentName(source_.coordinates, m, n) +
                                                         " is given twice (g is symmetric: give g_mn or g_nm)");
            given[static_cast<std::size_t>(m)][static_cast<std::size_t>(n)] = true;
            given[static_cast<std::size_t>(n)][static_cast<std::size_t>(m)] = true;
            g(m, n) = g(n, m) = scalar(text, scope).expr;
        }
        // Components in the formula's chart, g_ab = J^m_a g_mn J^n_b in the tracer's.
        if (scope.chart() != Chart::Cartesian) {
            codegen::ExprMatrix4 cartesian = codegen::ExprMatrix4::Zero();
            for (int a = 0; a < 4; ++a)
                for (int b = a; b < 4; ++b) {
                    Expr sum(0.0);
                    for (int m = 0; m < 4; ++m)
                        for (int n = 0; n < 4; ++n)
                            sum = sum + scope.differentialForm(m)[static_cast<std::size_t>(a)] * g(m, n) *
                                            scope.differentialForm(n)[static_cast<std::size_t>(b)];
                    cartesian(a, b) = cartesian(b, a) = sum;
                }
            g = cartesian;
        }
    } else {
        throw FormulaMetricError("ds2", "a metric needs its line element \"ds2\" or its components \"g\"");
    }
    if (source_.mostlyPlus)
        for (int m = 0; m < 4; ++m)
            for (int n = 0; n < 4; ++n) g(m, n) = -g(m, n);

    // The recursive passes (differentiation, the GLSL emitter) go as deep as the graph: its
    // exact height, which powers and step() make larger than the text's count.
    {
        std::vector<Expr> entries;
        for (int m = 0; m < 4; ++m)
            for (int n = m; n < 4; ++n) entries.push_back(g(m, n));
        if (const int height = graphHeight(entries); height > kMaxGraphDepth)
            throw FormulaMetricError(source_.lineElement ? "ds2" : "g",
                                     "the metric's expressions nest " + std::to_string(height) +
                                         " operations deep; at most " + std::to_string(kMaxGraphDepth) +
                                         " (write fewer powers of powers, or fewer definitions inside each other)");
    }
    symbolic_.g = g;
    std::ostringstream origin;
    origin.precision(17);
    // The name goes into a GLSL comment: printable ASCII only, on one line.
    std::string printable = source_.name;
    for (char& c : printable)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    origin << "formula metric '" << printable << "'";
    for (const auto& [k, v] : values_) origin << " " << k << "=" << v;
    symbolic_.origin = origin.str();

    std::vector<Expr> entries;
    for (int m = 0; m < 4; ++m)
        for (int n = m; n < 4; ++n) entries.push_back(g(m, n));
    metricTape_ = std::make_shared<ExpressionTape>(entries);
    if (kerrSchild) useKerrSchild(*kerrSchild);
    if (source_.horizon) {
        symbolic_.boundary = boundaryExpression(*source_.horizon, scope, "the horizon");
        horizonTape_ = std::make_shared<ExpressionTape>(std::vector<Expr>{*symbolic_.boundary});
    }
    if (source_.otherEnd) {
        symbolic_.otherEnd = boundaryExpression(*source_.otherEnd, scope, "the other end");
        otherEndTape_ = std::make_shared<ExpressionTape>(std::vector<Expr>{*symbolic_.otherEnd});
    }

    if (source_.asymptoticallyFlat) {
        far_.mass = constant(source_.farMass, scope, 0, false);
        far_.spin = constant(source_.farSpin, scope, 0, false);
        far_.size = constant(source_.farSize, scope, 0, false);
        far_.captureRadius = constant(source_.farCapture, scope, far_.size + 4 * far_.mass, false);
        for (int i = 0; i < 3; ++i)
            far_.velocity(i) = constant(source_.farVelocity[static_cast<std::size_t>(i)], scope, 0, true);
    }
    findCircularOrbits(scope);
}

void FormulaMetric::findCircularOrbits(const FormulaScope& scope) {
    Expr radius = codegen::sqrt(Expr::coordinate(1) * Expr::coordinate(1) + Expr::coordinate(2) * Expr::coordinate(2));
    if (source_.radius) {
        const ScalarFormula r = scalar(*source_.radius, scope);
        if (graphHeight({r.expr}) > kMaxGraphDepth)
            throw FormulaMetricError(
                "radius", "the radius nests more than " + std::to_string(kMaxGraphDepth) + " operations deep");
        radius = r.expr;
    }
    if (!source_.asymptoticallyFlat) {
        whyNoCircularOrbits_ = "no far_field declared (circular orbits are sought from far out)";
        return;
    }
    if (far_.velocity.norm() > 0) {
        whyNoCircularOrbits_ = "g depends on t (not stationary): its far field moves";
        return;
    }
    // Events on shells from 0.3 to 40 times the far field's scale, off the plane z = 0 (a ring
    // singularity lies in it) and off the axis.
    const double scale = far_.mass > 0 ? far_.mass : far_.size > 0 ? far_.size : 1;
    std::vector<Vec4> events;
    for (int i = 0; i < 24; ++i) {
        const double r = scale * (0.3 + 39.7 * ((i * 7) % 24) / 23.0),
                     th = kPi * (0.1 + 0.8 * ((i * 5) % 24 + 0.5) / 24), ph = 0.83 * i;
        events.emplace_back(0.7 * i - 5, r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph),
                            r * std::cos(th) + (i % 2 ? 0.01 : -0.01) * scale);
    }
    whyNoCircularOrbits_ = lc::whyNoCircularOrbits(*this, events);
    if (whyNoCircularOrbits_.empty()) {
        equatorialRadius_ = radius;
        spherical_ = lc::rotationSymmetricAbout(*this, events, 1);
    }
}

namespace {
// Whether the covariant vector l is null for the flat metric, to rounding (which reaches 3e-11
// of |l|^2 inside Kerr's ring); false where l is not finite. The Kerr-Schild closed forms hold
// only where it is.
bool nullForFlat(double l0, double l1, double l2, double l3) {
    const double squares = l0 * l0 + l1 * l1 + l2 * l2 + l3 * l3;
    return std::abs(l0 * l0 - l1 * l1 - l2 * l2 - l3 * l3) <= 1e-8 * squares;
}

// Events from 0.01 to 10^7 chart units from the origin in every direction, where a Kerr-Schild
// vector must be null (checked before the closed forms are trusted).
std::vector<Vec4> nullCheckEvents() {
    std::vector<Vec4> events;
    for (int i = 0; i < 120; ++i) {
        const double r = std::pow(10.0, -2 + 9.0 * ((i * 37) % 120) / 119.0), th = kPi * ((i * 53) % 120 + 0.5) / 120,
                     ph = 0.61 * i;
        events.emplace_back(0.37 * i - 20, r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph),
                            r * std::cos(th));
    }
    return events;
}
}  // namespace

void FormulaMetric::useKerrSchild(const KerrSchildForm& form) {
    // Program's g = c (eta_written + F L L) with c = -1 for a (-,+,+,+) text; its flat part must be
    // diag(1,-1,-1,-1), and then g = eta - f l l with f = -c F.
    const double c = source_.mostlyPlus ? -1 : 1;
    if (c * form.timeSign != 1) return;
    std::vector<Expr> outputs{Expr(-c) * form.F};
    for (const Expr& l : form.l) outputs.push_back(l);
    auto tape = std::make_shared<ExpressionTape>(outputs);
    int finite = 0;
    for (const Vec4& x : nullCheckEvents()) {
        double v[5];
        tape->evaluate(x.data(), v);
        if (!std::isfinite(v[1] + v[2] + v[3] + v[4])) continue;
        ++finite;
        if (!nullForFlat(v[1], v[2], v[3], v[4])) return;
    }
    if (finite >= 60) kerrSchildTape_ = std::move(tape);  // else too little seen to trust it
}

std::array<std::string, 4> FormulaMetric::coordinateNames() const {
    if (source_.chart == "cartesian") return source_.coordinates;
    return {source_.coordinates[0], "x", "y", "z"};
}

FarField FormulaMetric::farField(const Vec4& x) const {
    FarField f = far_;
    f.centre = far_.velocity * x(0);  // a field moving at constant velocity through the origin
    return f;
}

namespace {
constexpr int kUpper[4][4] = {{0, 1, 2, 3}, {1, 4, 5, 6}, {2, 5, 7, 8}, {3, 6, 8, 9}};
}

Mat4 FormulaMetric::metric(const Vec4& x) const {
    double v[10];
    metricTape_->evaluate(x.data(), v);
    Mat4 g;
    for (int m = 0; m < 4; ++m)
        for (int n = 0; n < 4; ++n) g(m, n) = v[kUpper[m][n]];
    return g;
}

void FormulaMetric::metricAndDerivatives(const Vec4& x, Mat4& g, std::array<Mat4, 4>& dg) const {
    double v[50];  // per entry: the value, then its four derivatives
    metricTape_->evaluateWithGradient(x.data(), v);
    for (int m = 0; m < 4; ++m)
        for (int n = 0; n < 4; ++n) {
            const double* e = v + 5 * kUpper[m][n];
            g(m, n) = e[0];
            for (std::size_t k = 0; k < 4; ++k) dg[k](m, n) = e[1 + k];
        }
}

// Hamilton's equations from the tape's 10 entries and their gradients directly:
// dp_k/dl = 1/2 sum_mn v^m v^n d_k g_mn over the symmetric entries (weights v_m^2 and 2 v_m v_n),
// without assembling the four matrices d_k g.
Mat4 FormulaMetric::inverseMetric(const Vec4& x) const {
    if (!kerrSchildTape_) return metric(x).inverse();
    double v[5];
    kerrSchildTape_->evaluate(x.data(), v);
    if (!nullForFlat(v[1], v[2], v[3], v[4])) return metric(x).inverse();  // the closed form does not hold here
    const Vec4 lUp(v[1], -v[2], -v[3], -v[4]);
    Mat4 gi = v[0] * lUp * lUp.transpose();
    gi.diagonal() += Vec4(1, -1, -1, -1);
    return gi;
}

HamiltonianFlow FormulaMetric::flow(const Vec4& x, const Vec4& p) const {
    if (kerrSchildTape_) {  // as KerrSchildMetric::flow: from f, l and their gradients alone
        double e[25];
        kerrSchildTape_->evaluateWithGradient(x.data(), e);
        const double f = e[0];
        const Vec4 df(e[1], e[2], e[3], e[4]);
        Vec4 lUp, dlp = Vec4::Zero();
        for (int m = 0; m < 4; ++m) {
            const double sign = m == 0 ? 1 : -1;
            const double* l = e + 5 * (m + 1);
            lUp(m) = sign * l[0];
            for (int k = 0; k < 4; ++k) dlp(k) += sign * p(m) * l[1 + k];
        }
        const double lp = lUp.dot(p);
        // l must be null here too (it was checked at sample events only): else the general form.
        if (!nullForFlat(e[5], e[10], e[15], e[20])) return generalFlowFromTape(x, p);
        HamiltonianFlow out;
        out.dxdl = Vec4(p(0), -p(1), -p(2), -p(3)) + f * lp * lUp;
        out.dpdl = -lp * (0.5 * lp * df + f * dlp);
        out.H = 0.5 * p.dot(out.dxdl);
        return out;
    }
    return generalFlowFromTape(x, p);
}

HamiltonianFlow FormulaMetric::generalFlowFromTape(const Vec4& x, const Vec4& p) const {
    double e[50];
    metricTape_->evaluateWithGradient(x.data(), e);
    Mat4 g;
    for (int m = 0; m < 4; ++m)
        for (int n = 0; n < 4; ++n) g(m, n) = e[5 * kUpper[m][n]];
    HamiltonianFlow f;
    f.dxdl = g.inverse() * p;
    const Vec4& v = f.dxdl;
    double w[10];
    for (int m = 0; m < 4; ++m)
        for (int n = m; n < 4; ++n) w[kUpper[m][n]] = (m == n ? 0.5 : 1.0) * v(m) * v(n);
    for (int k = 0; k < 4; ++k) {
        double s = 0;
        for (int i = 0; i < 10; ++i) s += w[i] * e[5 * i + 1 + k];
        f.dpdl(k) = s;
    }
    f.H = 0.5 * p.dot(f.dxdl);
    return f;
}

Boundary FormulaMetric::boundary(const Vec4& x) const {
    if (otherEndTape_) {
        double e;
        otherEndTape_->evaluate(x.data(), &e);
        if (!std::isfinite(e)) return Boundary::Singularity;
        if (e < 1e-6) return Boundary::OtherEnd;
    }
    if (!horizonTape_) return Boundary::None;
    double h;
    horizonTape_->evaluate(x.data(), &h);
    if (!std::isfinite(h)) return Boundary::Singularity;
    return h < 1e-6 ? Boundary::Horizon : Boundary::None;
}

}  // namespace lc::formula
