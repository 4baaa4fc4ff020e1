// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// From parsed formula text to codegen::Expr, the expression graph that every metric's exact
// derivatives, CPU tape and GPU shader come from. Names resolve in a FormulaScope: the chart's
// coordinates, the metric's parameters (folded as constants), pi, and earlier definitions.
// A line element is read as a quadratic form in the differentials d<coordinate>.
#include "core/codegen/expression.hpp"
#include "core/formula/formula_parser.hpp"

#include <array>
#include <map>
#include <optional>
#include <vector>
#include <string>

namespace lc::formula {

// Deepest expression graph a metric may build (definitions stack up): the differentiator and
// the GLSL emitter recurse over it.
inline constexpr int kMaxGraphDepth = 2000;

// The chart a formula is written in. The tracer always works in a Cartesian chart (t, x, y, z):
// a spherical (t, r, theta, phi) or cylindrical (t, rho, phi, z) formula is pulled back to it with
// exact Jacobians, so rays cross the polar axis without a seam (docs/METRICS.md, Charts).
enum class Chart { Cartesian, Spherical, Cylindrical };

// The longest path from any of `roots` to a leaf of the expression graph, found without
// recursion: the exact depth that the recursive passes over the graph (differentiation, GLSL)
// will reach, where the parse tree's count misses what powers and functions expand into.
int graphHeight(const std::vector<codegen::Expr>& roots);

class FormulaScope {
public:
    explicit FormulaScope(const std::array<std::string, 4>& coordinates, Chart chart = Chart::Cartesian);
    const std::array<std::string, 4>& coordinates() const { return coordinates_; }
    Chart chart() const { return chart_; }
    // d(coordinate k) as a combination of dt, dx, dy, dz (unit vectors in a Cartesian chart).
    const std::array<codegen::Expr, 4>& differentialForm(int k) const { return jacobian_[static_cast<std::size_t>(k)]; }
    // sin and cos of the polar angle theta (spherical charts) in closed form, rho/r and z/r; null
    // when `e` is not theta.
    const codegen::Expr* sinOf(const codegen::Expr& e) const;
    const codegen::Expr* cosOf(const codegen::Expr& e) const;

    // Throws std::invalid_argument when the name is taken (a coordinate, a differential, a
    // function, pi, another parameter or definition).
    void addConstant(const std::string& name, double value);
    void addDefinition(const std::string& name, const codegen::Expr& value, int depth);

    bool has(const std::string& name) const { return values_.count(name) != 0; }
    // The coordinate index of a differential "d<coordinate>", or -1.
    int differential(const std::string& name) const;
    // Why a name cannot be defined, or "" if it can.
    std::string whyTaken(const std::string& name) const;

    struct Value {
        codegen::Expr expr;
        int depth;
    };
    const Value* find(const std::string& name) const;

private:
    std::array<std::string, 4> coordinates_;
    Chart chart_;
    std::array<std::array<codegen::Expr, 4>, 4> jacobian_;
    codegen::Expr theta_, sinTheta_, cosTheta_;
    std::map<std::string, Value> values_;
};

// A scalar formula (no differentials); throws FormulaError at the offending node.
struct ScalarFormula {
    codegen::Expr expr;
    int depth = 0;  // graph depth, with the definitions it uses
};
ScalarFormula scalarFormula(const FormulaNode& tree, const FormulaScope& scope);

// A line element written as flat space plus one square, ds^2 = eta + F (l_m dx^m)^2 with eta
// the four squares -dt^2 + dx^2 + dy^2 + dz^2 (or their negatives): Kerr-Schild form, which
// gives the inverse metric in closed form and Hamilton's equations from F and l alone.
struct KerrSchildForm {
    codegen::Expr F;
    std::array<codegen::Expr, 4> l;
    int timeSign = -1;  // the sign of dt^2 in eta as written
};

// A line element ds^2 = sum g_mn dx^m dx^n: its symmetric coefficients g_mn (as written, before
// any change of signature), and its Kerr-Schild form when it is written as one. Throws
// FormulaError where a term is not quadratic in the differentials (dt^3, sin(dt), dt + 1, dt/dr).
codegen::ExprMatrix4 lineElement(const FormulaNode& tree, const FormulaScope& scope, int& depth,
                                 std::optional<KerrSchildForm>* kerrSchild = nullptr);

}  // namespace lc::formula
