// SPDX-License-Identifier: BSD-3-Clause
#include "core/codegen/expression.hpp"

#include "core/numerics/bessel.hpp"

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace lc::codegen {
namespace {

Expr make(Op op, const Expr& a, const Expr* b = nullptr, const Expr* c = nullptr) {
    auto n = std::make_shared<Node>();
    n->op = op;
    n->a = a.pointer();
    if (b) n->b = b->pointer();
    if (c) n->c = c->pointer();
    return Expr(NodePtr(std::move(n)));
}

bool constant(const Expr& e, double& v) {
    if (e.node().op != Op::Constant) return false;
    v = e.node().value;
    return true;
}

}  // namespace

Expr::Expr(double c) {
    auto n = std::make_shared<Node>();
    n->value = c;
    node_ = std::move(n);
}

Expr Expr::coordinate(int index) {
    if (index < 0 || index > 3) throw std::out_of_range("codegen: coordinate index must be 0..3");
    auto n = std::make_shared<Node>();
    n->op = Op::Variable;
    n->variable = index;
    return Expr(NodePtr(std::move(n)));
}

Expr Expr::symbol(const std::string& name) {
    if (name.empty()) throw std::invalid_argument("codegen: a symbol needs a name");
    auto n = std::make_shared<Node>();
    n->op = Op::Symbol;
    n->symbol = name;
    return Expr(NodePtr(std::move(n)));
}

Expr& Expr::operator+=(const Expr& o) { return *this = *this + o; }
Expr& Expr::operator-=(const Expr& o) { return *this = *this - o; }
Expr& Expr::operator*=(const Expr& o) { return *this = *this * o; }
Expr& Expr::operator/=(const Expr& o) { return *this = *this / o; }

Expr operator+(const Expr& a, const Expr& b) {
    double x, y;
    const bool ca = constant(a, x), cb = constant(b, y);
    if (ca && cb) return Expr(x + y);
    if (ca && x == 0) return b;
    if (cb && y == 0) return a;
    return make(Op::Add, a, &b);
}

Expr operator-(const Expr& a, const Expr& b) {
    double x, y;
    const bool ca = constant(a, x), cb = constant(b, y);
    if (ca && cb) return Expr(x - y);
    if (cb && y == 0) return a;
    if (ca && x == 0) return -b;
    return make(Op::Sub, a, &b);
}

Expr operator*(const Expr& a, const Expr& b) {
    double x, y;
    const bool ca = constant(a, x), cb = constant(b, y);
    if (ca && cb) return Expr(x * y);
    if ((ca && x == 0) || (cb && y == 0)) return Expr(0.0);
    if (ca && x == 1) return b;
    if (cb && y == 1) return a;
    if (ca && x == -1) return -b;
    if (cb && y == -1) return -a;
    return make(Op::Mul, a, &b);
}

Expr operator/(const Expr& a, const Expr& b) {
    double x, y;
    const bool ca = constant(a, x), cb = constant(b, y);
    if (ca && cb) return Expr(x / y);
    if (ca && x == 0) return Expr(0.0);
    if (cb && y == 1) return a;
    return make(Op::Div, a, &b);
}

Expr operator-(const Expr& a) {
    double x;
    if (constant(a, x)) return Expr(-x);
    if (a.node().op == Op::Neg) return Expr(a.node().a);
    return make(Op::Neg, a);
}

#define LC_CODEGEN_UNARY(name, op, fn)          \
    Expr name(const Expr& a) {                  \
        double x;                               \
        if (constant(a, x)) return Expr(fn(x)); \
        return make(op, a);                     \
    }
LC_CODEGEN_UNARY(sqrt, Op::Sqrt, std::sqrt)
LC_CODEGEN_UNARY(tanh, Op::Tanh, std::tanh)
LC_CODEGEN_UNARY(sin, Op::Sin, std::sin)
LC_CODEGEN_UNARY(cos, Op::Cos, std::cos)
LC_CODEGEN_UNARY(exp, Op::Exp, std::exp)
LC_CODEGEN_UNARY(log, Op::Log, std::log)
LC_CODEGEN_UNARY(abs, Op::Abs, std::fabs)
LC_CODEGEN_UNARY(acos, Op::Acos, std::acos)
LC_CODEGEN_UNARY(tan, Op::Tan, std::tan)
LC_CODEGEN_UNARY(asin, Op::Asin, std::asin)
LC_CODEGEN_UNARY(atan, Op::Atan, std::atan)
LC_CODEGEN_UNARY(sinh, Op::Sinh, std::sinh)
LC_CODEGEN_UNARY(cosh, Op::Cosh, std::cosh)
LC_CODEGEN_UNARY(floor, Op::Floor, std::floor)
LC_CODEGEN_UNARY(besselJ0, Op::BesselJ0, lc::besselJ0)
LC_CODEGEN_UNARY(besselJ1, Op::BesselJ1, lc::besselJ1)
#undef LC_CODEGEN_UNARY

#define LC_CODEGEN_BINARY(name, op, fn)                              \
    Expr name(const Expr& a, const Expr& b) {                        \
        double x, y;                                                 \
        if (constant(a, x) && constant(b, y)) return Expr(fn(x, y)); \
        return make(op, a, &b);                                      \
    }
LC_CODEGEN_BINARY(pow, Op::Pow, std::pow)
LC_CODEGEN_BINARY(atan2, Op::Atan2, std::atan2)
LC_CODEGEN_BINARY(min, Op::Min, std::fmin)
LC_CODEGEN_BINARY(max, Op::Max, std::fmax)
#undef LC_CODEGEN_BINARY

Expr ifPositive(const Expr& condition, const Expr& a, const Expr& b) {
    double c;
    if (constant(condition, c)) return c > 0 ? a : b;
    return make(Op::IfPositive, condition, &a, &b);
}

Expr Differentiator::operator()(const Expr& e) {
    const Node& n = e.node();
    if (const auto it = done_.find(&n); it != done_.end()) return it->second;
    const Expr a = n.a ? Expr(n.a) : Expr(), b = n.b ? Expr(n.b) : Expr();
    Expr d;
    switch (n.op) {
        case Op::Constant: d = Expr(0.0); break;
        case Op::Variable: d = Expr(n.variable == k_ ? 1.0 : 0.0); break;
        case Op::Symbol: d = Expr(0.0); break;
        case Op::Add: d = (*this)(a) + (*this)(b); break;
        case Op::Sub: d = (*this)(a) - (*this)(b); break;
        case Op::Mul: d = (*this)(a)*b + a * (*this)(b); break;
        case Op::Div: d = ((*this)(a)-e * (*this)(b)) / b; break;  // (a' - (a/b) b') / b
        case Op::Neg: d = -(*this)(a); break;
        case Op::Sqrt: d = (*this)(a) / (Expr(2.0) * e); break;
        case Op::Tanh: d = (*this)(a) * (Expr(1.0) - e * e); break;
        case Op::Sin: d = (*this)(a)*cos(a); break;
        case Op::Cos: d = -((*this)(a)*sin(a)); break;
        case Op::Exp: d = (*this)(a)*e; break;
        case Op::Log: d = (*this)(a) / a; break;
        case Op::Abs: d = (*this)(a) * (a / e); break;  // sign(a), undefined at 0 as |x|' is
        case Op::Acos: d = -(*this)(a) / sqrt(Expr(1.0) - a * a); break;
        case Op::Tan: d = (*this)(a) * (Expr(1.0) + e * e); break;
        case Op::Asin: d = (*this)(a) / sqrt(Expr(1.0) - a * a); break;
        case Op::Atan: d = (*this)(a) / (Expr(1.0) + a * a); break;
        case Op::Sinh: d = (*this)(a)*cosh(a); break;
        case Op::Cosh: d = (*this)(a)*sinh(a); break;
        case Op::Floor: d = Expr(0.0); break;  // piecewise constant
        case Op::Pow: d = e * ((*this)(b)*log(a) + b * (*this)(a) / a); break;
        case Op::Atan2: d = (b * (*this)(a)-a * (*this)(b)) / (a * a + b * b); break;  // atan2(a = y, b = x)
        case Op::Min: d = ifPositive(b - a, (*this)(a), (*this)(b)); break;
        case Op::Max: d = ifPositive(a - b, (*this)(a), (*this)(b)); break;
        case Op::IfPositive: d = ifPositive(a, (*this)(b), (*this)(Expr(n.c))); break;
        case Op::BesselJ0: d = -((*this)(a)*besselJ1(a)); break;
        case Op::BesselJ1: d = (*this)(a)*lc::besselJ1Derivative(a, besselJ0(a), e); break;
    }
    done_.emplace(&n, d);
    return d;
}

double evaluate(const Expr& e, const std::array<double, 4>& x, const std::map<std::string, double>& symbols) {
    std::unordered_map<const Node*, double> memo;
    struct Walk {
        const std::array<double, 4>& x;
        const std::map<std::string, double>& symbols;
        std::unordered_map<const Node*, double>& memo;
        double operator()(const Node& n) {
            if (const auto it = memo.find(&n); it != memo.end()) return it->second;
            double v = 0;
            switch (n.op) {
                case Op::Constant: v = n.value; break;
                case Op::Variable: v = x[static_cast<std::size_t>(n.variable)]; break;
                case Op::Symbol: {
                    const auto it = symbols.find(n.symbol);
                    if (it == symbols.end()) throw std::out_of_range("codegen: no value for symbol '" + n.symbol + "'");
                    v = it->second;
                    break;
                }
                case Op::Add: v = (*this)(*n.a) + (*this)(*n.b); break;
                case Op::Sub: v = (*this)(*n.a) - (*this)(*n.b); break;
                case Op::Mul: v = (*this)(*n.a) * (*this)(*n.b); break;
                case Op::Div: v = (*this)(*n.a) / (*this)(*n.b); break;
                case Op::Neg: v = -(*this)(*n.a); break;
                case Op::Sqrt: v = std::sqrt((*this)(*n.a)); break;
                case Op::Tanh: v = std::tanh((*this)(*n.a)); break;
                case Op::Sin: v = std::sin((*this)(*n.a)); break;
                case Op::Cos: v = std::cos((*this)(*n.a)); break;
                case Op::Exp: v = std::exp((*this)(*n.a)); break;
                case Op::Log: v = std::log((*this)(*n.a)); break;
                case Op::Abs: v = std::fabs((*this)(*n.a)); break;
                case Op::Acos: v = std::acos((*this)(*n.a)); break;
                case Op::Tan: v = std::tan((*this)(*n.a)); break;
                case Op::Asin: v = std::asin((*this)(*n.a)); break;
                case Op::Atan: v = std::atan((*this)(*n.a)); break;
                case Op::Sinh: v = std::sinh((*this)(*n.a)); break;
                case Op::Cosh: v = std::cosh((*this)(*n.a)); break;
                case Op::Floor: v = std::floor((*this)(*n.a)); break;
                case Op::Pow: v = std::pow((*this)(*n.a), (*this)(*n.b)); break;
                case Op::Atan2: v = std::atan2((*this)(*n.a), (*this)(*n.b)); break;
                case Op::Min: v = std::fmin((*this)(*n.a), (*this)(*n.b)); break;
                case Op::Max: v = std::fmax((*this)(*n.a), (*this)(*n.b)); break;
                case Op::IfPositive: v = (*this)(*n.a) > 0 ? (*this)(*n.b) : (*this)(*n.c); break;
                case Op::BesselJ0: v = lc::besselJ0((*this)(*n.a)); break;
                case Op::BesselJ1: v = lc::besselJ1((*this)(*n.a)); break;
            }
            memo.emplace(&n, v);
            return v;
        }
    };
    return Walk{x, symbols, memo}(e.node());
}

}  // namespace lc::codegen
