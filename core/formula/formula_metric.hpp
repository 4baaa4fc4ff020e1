// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A metric typed as text (docs/METRICS.md): coordinates, parameters with ranges, definitions,
// then a line element or its components. Parsed into codegen::Expr once; g and its exact first
// derivatives (symbolic differentiation of that graph, no finite differences) run on the CPU
// from a flat ExpressionTape, and the GPU tracer's GLSL is generated from the same graph
// (Spacetime::symbolic), so one formula gives both.
#include "core/formula/expression_tape.hpp"
#include "core/metrics/factory.hpp"
#include "core/spacetime/metric_check.hpp"
#include "core/spacetime/spacetime.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lc::formula {

struct KerrSchildForm;  // core/formula/formula_expressions.hpp
class FormulaScope;

// One formula text and the field it came from ("ds2", "define[2]", "g.t,phi"), for messages.
struct FormulaText {
    std::string field;
    std::string text;
};

// What a metric file or an inline "formula" block says, before any parameter has a value.
struct FormulaMetricSource {
    std::string name = "formula";
    std::string summary;
    std::array<std::string, 4> coordinates{"t", "x", "y", "z"};  // the first is time
    std::string chart = "cartesian";                             // or "spherical", "cylindrical"
    bool mostlyPlus = true;                                      // signature written (-,+,+,+)
    std::vector<MetricParameter> parameters;                     // `why` holds the file's "meaning"
    std::vector<FormulaText> definitions;                        // "name = expression", in order
    std::optional<FormulaText> lineElement;
    std::vector<std::pair<FormulaText, std::pair<int, int>>> components;  // g_mn as given
    std::optional<FormulaText> horizon;  // rays stop where it is <= 0 (a margin of 1e-6)
    // Two-ended metrics: where it is <= 0 (a margin of 1e-6) a ray has reached the other end.
    std::optional<FormulaText> otherEnd;
    // The radius that labels circular orbits and disks (default: the distance from the z axis).
    std::optional<FormulaText> radius;
    // Declared asymptotically flat in a Cartesian chart: its far field (constants only).
    bool asymptoticallyFlat = false;
    std::optional<FormulaText> farMass, farSpin, farSize, farCapture;
    std::array<std::optional<FormulaText>, 3> farVelocity;
};

// The field of a FormulaMetricError about a parameter's value (not about the formula): this
// prefix, then the parameter's name.
inline const std::string kValueField = "value of ";

// A problem in one field of a formula metric; offset is inside that field's text when known.
class FormulaMetricError : public std::runtime_error {
public:
    FormulaMetricError(const std::string& field, const std::string& detail)
        : std::runtime_error(field + ": " + detail), field_(field), detail_(detail) {}
    const std::string& field() const { return field_; }
    // The problem with its column and caret, without the field.
    const std::string& detail() const { return detail_; }

private:
    std::string field_, detail_;
};

class FormulaMetric final : public Spacetime {
public:
    // Throws FormulaMetricError for any problem in the source or the parameter values
    // (unknown parameter, outside its range, parse errors, unknown names...).
    FormulaMetric(FormulaMetricSource source, const std::map<std::string, double>& parameterValues);

    std::string name() const override { return source_.name; }
    std::map<std::string, double> parameters() const override { return values_; }
    // The tracer's chart: the formula's own when Cartesian, else (t, x, y, z) of its pull-back.
    std::array<std::string, 4> coordinateNames() const override;
    Mat4 metric(const Vec4& x) const override;
    void metricAndDerivatives(const Vec4& x, Mat4& g, std::array<Mat4, 4>& dg) const override;
    HamiltonianFlow flow(const Vec4& x, const Vec4& p) const override;
    Boundary boundary(const Vec4& x) const override;
    std::optional<codegen::SymbolicMetric> symbolic() const override { return symbolic_; }
    bool asymptoticallyFlat() const override { return source_.asymptoticallyFlat; }
    bool hasHorizon() const override { return source_.horizon.has_value(); }
    bool hasOtherEnd() const override { return source_.otherEnd.has_value(); }
    FarField farField(const Vec4& x) const override;
    // Offered when the metric is declared asymptotically flat and d/dt, rotations about z and
    // z -> -z leave it unchanged at sample events (whyNoCircularOrbits says what fails).
    std::optional<codegen::Expr> equatorialRadius() const override { return equatorialRadius_; }
    // With circular orbits: d/dt and rotations about z; spherical where rotations about x leave g
    // unchanged at the same sample events too.
    Symmetries symmetries() const override {
        Symmetries s = Spacetime::symmetries();
        s.spherical = spherical_;
        return s;
    }
    const std::string& whyNoCircularOrbits() const { return whyNoCircularOrbits_; }

    const FormulaMetricSource& source() const { return source_; }
    // The metric in the program's convention (+,-,-,-), as expressions of the coordinates.
    const codegen::ExprMatrix4& expressions() const { return symbolic_.g; }
    std::size_t tapeInstructions() const { return metricTape_->instructions(); }
    // Whether the Kerr-Schild closed forms are used (a line element eta + F (l.dx)^2 with l null).
    bool kerrSchild() const { return kerrSchildTape_ != nullptr; }
    Mat4 inverseMetric(const Vec4& x) const override;

private:
    void useKerrSchild(const KerrSchildForm& form);
    void findCircularOrbits(const FormulaScope& scope);
    HamiltonianFlow generalFlowFromTape(const Vec4& x, const Vec4& p) const;

    FormulaMetricSource source_;
    std::map<std::string, double> values_;
    codegen::SymbolicMetric symbolic_;
    std::shared_ptr<const ExpressionTape> metricTape_;    // the 10 entries g_mn, m <= n
    std::shared_ptr<const ExpressionTape> horizonTape_;   // the horizon function, when given
    std::shared_ptr<const ExpressionTape> otherEndTape_;  // the other end's, when given
    // Kerr-Schild form g = eta - f l (x) l with l null for eta, when the line element is written
    // so (core/formula/formula_expressions.hpp): f and l_0..l_3. Hamilton's equations and the
    // inverse then follow in closed form from these five functions, as for the built-in Kerr.
    std::shared_ptr<const ExpressionTape> kerrSchildTape_;
    FarField far_;
    std::optional<codegen::Expr> equatorialRadius_;
    std::string whyNoCircularOrbits_;
    bool spherical_ = false;
};

}  // namespace lc::formula
