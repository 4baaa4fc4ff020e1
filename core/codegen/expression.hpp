// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scalar that records the arithmetic done on it, so that a metric written once as
// `template <class S> g(x)` (CodedMetric) can be instantiated with it and its expression
// printed as GLSL for the GPU tracer. Constants are folded in double as the expression is built
// (a metric's parameters arrive as constants), and trivial identities (x + 0, x * 1, x * 0) are
// applied, so derivatives of constant entries vanish instead of filling the shader.
#include <Eigen/Core>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>

namespace lc::codegen {

enum class Op {
    Constant,
    Variable,
    Symbol,
    Add,
    Sub,
    Mul,
    Div,
    Neg,
    Sqrt,
    Tanh,
    Sin,
    Cos,
    Exp,
    Log,
    Abs,
    Acos,
    Tan,
    Asin,
    Atan,
    Sinh,
    Cosh,
    Floor,
    Pow,
    Atan2,
    Min,
    Max,
    IfPositive,
    BesselJ0,
    BesselJ1
};

struct Node;
using NodePtr = std::shared_ptr<const Node>;

struct Node {
    Op op = Op::Constant;
    double value = 0;    // Constant
    int variable = -1;   // Variable: the coordinate index 0..3
    std::string symbol;  // Symbol: a GLSL name (a function argument or a value computed before)
    NodePtr a, b, c;     // operands (b for binary operations, c for IfPositive)
};

class Expr {
public:
    Expr(double constant = 0.0);  // implicit: metrics write S(1.0), Eigen writes Scalar(0)
    explicit Expr(NodePtr node) : node_(std::move(node)) {}
    static Expr coordinate(int index);
    // A named value, printed as its name (e.g. "g[0][1]", "k2x.y"); constant under d/dx^k.
    static Expr symbol(const std::string& name);

    const Node& node() const { return *node_; }
    const NodePtr& pointer() const { return node_; }
    bool isConstant(double value) const { return node_->op == Op::Constant && node_->value == value; }

    Expr& operator+=(const Expr& o);
    Expr& operator-=(const Expr& o);
    Expr& operator*=(const Expr& o);
    Expr& operator/=(const Expr& o);

private:
    NodePtr node_;
};

Expr operator+(const Expr& a, const Expr& b);
Expr operator-(const Expr& a, const Expr& b);
Expr operator*(const Expr& a, const Expr& b);
Expr operator/(const Expr& a, const Expr& b);
Expr operator-(const Expr& a);
// Found by argument-dependent lookup after `using std::sqrt;` in a metric's code.
Expr sqrt(const Expr& a);
Expr tanh(const Expr& a);
Expr sin(const Expr& a);
Expr cos(const Expr& a);
Expr exp(const Expr& a);
Expr log(const Expr& a);
Expr abs(const Expr& a);
Expr acos(const Expr& a);
Expr tan(const Expr& a);
Expr asin(const Expr& a);
Expr atan(const Expr& a);
Expr sinh(const Expr& a);
Expr cosh(const Expr& a);
Expr floor(const Expr& a);  // derivative 0 (where it exists)
// Bessel functions of the first kind (core/numerics/bessel.hpp); printed as GLSL calls to
// lcBesselJ0, lcBesselJ1, which views/shaders generates from their float approximation.
Expr besselJ0(const Expr& a);
Expr besselJ1(const Expr& a);
Expr pow(const Expr& a, const Expr& b);
Expr atan2(const Expr& y, const Expr& x);
Expr min(const Expr& a, const Expr& b);
Expr max(const Expr& a, const Expr& b);
// condition > 0 ? a : b, for formulas with cases (written once for double and Expr through
// lc::ifPositive, core/numerics/select.hpp).
Expr ifPositive(const Expr& condition, const Expr& a, const Expr& b);

// Exact derivatives d e / d x^k by the chain rule on the recorded graph, memoised per node so
// that shared subexpressions are differentiated once.
class Differentiator {
public:
    explicit Differentiator(int coordinate) : k_(coordinate) {}
    Expr operator()(const Expr& e);

private:
    int k_;
    std::unordered_map<const Node*, Expr> done_;
};

// The value at x, in double (tests check generated expressions against the metric's own code);
// symbols take their values from `symbols` (std::out_of_range names a missing one).
double evaluate(const Expr& e, const std::array<double, 4>& x, const std::map<std::string, double>& symbols = {});

using ExprVector4 = Eigen::Matrix<Expr, 4, 1>;
using ExprMatrix4 = Eigen::Matrix<Expr, 4, 4>;

}  // namespace lc::codegen

namespace Eigen {
template <>
struct NumTraits<lc::codegen::Expr> : GenericNumTraits<double> {
    using Real = lc::codegen::Expr;
    using NonInteger = lc::codegen::Expr;
    using Nested = lc::codegen::Expr;
    using Literal = lc::codegen::Expr;
    enum {
        IsComplex = 0,
        IsInteger = 0,
        IsSigned = 1,
        RequireInitialization = 1,
        ReadCost = 1,
        AddCost = 1,
        MulCost = 1
    };
};
}  // namespace Eigen
