// SPDX-License-Identifier: BSD-3-Clause
#include "core/formula/formula_expressions.hpp"

#include "core/numerics/types.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <unordered_map>

namespace lc::formula {
namespace {

using codegen::Expr;

bool isFunction(const std::string& name) {
    for (const auto& f : formulaFunctions())
        if (name == f.name) return true;
    return false;
}

// a^b: whole exponents up to 16 as products (exact, and defined for negative bases, where
// GLSL's pow is not), 1/2 as sqrt.
Expr power(const Expr& a, const Expr& b) {
    if (b.node().op == codegen::Op::Constant) {
        const double n = b.node().value;
        if (n == std::round(n) && std::abs(n) <= 16) {
            Expr result(1.0), base = a;
            for (int k = static_cast<int>(std::abs(n)); k > 0; k >>= 1) {
                if (k & 1) result = result * base;
                if (k > 1) base = base * base;
            }
            return n < 0 ? Expr(1.0) / result : result;
        }
        if (n == 0.5) return sqrt(a);
        if (n == -0.5) return Expr(1.0) / sqrt(a);
    }
    return pow(a, b);
}

Expr call(const std::string& name, const std::vector<Expr>& x, const FormulaScope& scope) {
    if (name == "sin" && scope.sinOf(x[0])) return *scope.sinOf(x[0]);
    if (name == "cos" && scope.cosOf(x[0])) return *scope.cosOf(x[0]);
    static const std::map<std::string, std::function<Expr(const std::vector<Expr>&)>> table{
        {"sqrt", [](auto& v) { return sqrt(v[0]); }},
        {"exp", [](auto& v) { return exp(v[0]); }},
        {"log", [](auto& v) { return log(v[0]); }},
        {"sin", [](auto& v) { return sin(v[0]); }},
        {"cos", [](auto& v) { return cos(v[0]); }},
        {"tan", [](auto& v) { return tan(v[0]); }},
        {"asin", [](auto& v) { return asin(v[0]); }},
        {"acos", [](auto& v) { return acos(v[0]); }},
        {"atan", [](auto& v) { return atan(v[0]); }},
        {"sinh", [](auto& v) { return sinh(v[0]); }},
        {"cosh", [](auto& v) { return cosh(v[0]); }},
        {"tanh", [](auto& v) { return tanh(v[0]); }},
        {"abs", [](auto& v) { return abs(v[0]); }},
        {"min", [](auto& v) { return min(v[0], v[1]); }},
        {"max", [](auto& v) { return max(v[0], v[1]); }},
        {"atan2", [](auto& v) { return atan2(v[0], v[1]); }},
        {"pow", [](auto& v) { return power(v[0], v[1]); }},
        // A smooth step of width w: 0 well below x = 0, 1 well above (tanh, so derivatives exist).
        {"step", [](auto& v) { return Expr(0.5) * (Expr(1.0) + tanh(v[0] / v[1])); }},
        {"besselj0", [](auto& v) { return besselJ0(v[0]); }},
        {"besselj1", [](auto& v) { return besselJ1(v[0]); }},
    };
    return table.at(name)(x);
}

void checkCall(const FormulaNode& n) {
    for (const auto& f : formulaFunctions())
        if (n.name == f.name) {
            if (static_cast<int>(n.args.size()) != f.arity)
                throw FormulaError(n.offset, n.name + " takes " + std::to_string(f.arity) + " argument" +
                                                 (f.arity == 1 ? "" : "s") + ", not " + std::to_string(n.args.size()));
            return;
        }
    std::string names;
    for (const auto& f : formulaFunctions()) names += std::string(names.empty() ? "" : ", ") + f.name;
    throw FormulaError(n.offset, "unknown function '" + n.name + "' (known: " + names + ")");
}

std::string unknownName(const std::string& name, const FormulaScope& scope) {
    if (isFunction(name)) return "'" + name + "' is a function: write " + name + "(...)";
    if (scope.differential(name) >= 0) return "the differential '" + name + "' belongs in the line element ds2 only";
    std::string known;
    for (const auto& c : scope.coordinates()) known += (known.empty() ? "" : ", ") + c;
    return "unknown name '" + name + "' (coordinates: " + known +
           "; parameters and definitions must be declared before use)";
}

// A name's value in the scope, its graph depth noted in `depth`; an unknown name is an error at
// the node.
const FormulaScope::Value& lookUp(const FormulaNode& n, const FormulaScope& scope, int& depth) {
    const FormulaScope::Value* v = scope.find(n.name);
    if (!v) throw FormulaError(n.offset, unknownName(n.name, scope));
    depth = std::max(depth, v->depth);
    return *v;
}

// How a degree-2 polynomial was written, term by term, so that a Kerr-Schild form can be
// recognised: c (dx^k)^2 with a constant c, F (l.dx)^2, or anything else.
struct QuadraticTerm {
    enum class Kind { Square, SquareOfSum, Other } kind = Kind::Other;
    int coordinate = -1;  // Square: k
    Expr factor{1.0};     // c or F
    std::array<Expr, 4> linear{};
};

// A value of a line element's text: a polynomial of degree 0, 1 or 2 in the differentials.
struct Polynomial {
    int degree = 0;
    Expr scalar;                                                    // degree 0
    std::array<Expr, 4> linear{};                                   // degree 1: coefficient of dx^m
    codegen::ExprMatrix4 quadratic = codegen::ExprMatrix4::Zero();  // degree 2: coefficient of dx^m dx^n, m <= n
    std::vector<QuadraticTerm> terms;                               // degree 2: as written
    bool kerrSchildPossible = true;                                 // terms then holds at most the form's five
};

// A product of two linear polynomials as a term: the same one twice is a square.
QuadraticTerm termOf(const Polynomial& a, const Polynomial& b) {
    QuadraticTerm t;
    bool same = true;
    int nonZero = 0, last = -1;
    for (std::size_t k = 0; k < 4; ++k) {
        const Expr &x = a.linear[k], &y = b.linear[k];
        const bool equalConstants = x.node().op == codegen::Op::Constant && y.node().op == codegen::Op::Constant &&
                                    x.node().value == y.node().value;
        same = same && (x.pointer() == y.pointer() || equalConstants);
        if (!a.linear[k].isConstant(0.0)) {
            ++nonZero;
            last = static_cast<int>(k);
        }
    }
    if (!same) return t;
    t.linear = a.linear;
    if (nonZero == 1 && a.linear[static_cast<std::size_t>(last)].node().op == codegen::Op::Constant) {
        const double c = a.linear[static_cast<std::size_t>(last)].node().value;
        t.kind = QuadraticTerm::Kind::Square;
        t.coordinate = last;
        t.factor = Expr(c * c);
    } else {
        t.kind = QuadraticTerm::Kind::SquareOfSum;
    }
    return t;
}

// eta + F (l.dx)^2: four squares of the coordinates with constant factors -1, 1, 1, 1 (or all
// negated) and one square of a sum.
std::optional<KerrSchildForm> kerrSchildForm(const std::vector<QuadraticTerm>& terms) {
    std::array<double, 4> flat{0, 0, 0, 0};
    std::optional<KerrSchildForm> form;
    for (const QuadraticTerm& t : terms) {
        if (t.kind == QuadraticTerm::Kind::Square && t.factor.node().op == codegen::Op::Constant &&
            flat[static_cast<std::size_t>(t.coordinate)] == 0) {
            flat[static_cast<std::size_t>(t.coordinate)] = t.factor.node().value;
        } else if (t.kind != QuadraticTerm::Kind::Other && !form) {
            form = KerrSchildForm{t.factor, t.linear, -1};
        } else {
            return std::nullopt;
        }
    }
    if (!form) return std::nullopt;
    const double s = flat[1];
    if (!(std::abs(s) == 1 && flat[0] == -s && flat[2] == s && flat[3] == s)) return std::nullopt;
    form->timeSign = static_cast<int>(flat[0]);
    return form;
}

class LineElementReader {
public:
    explicit LineElementReader(const FormulaScope& scope) : scope_(scope) {}
    int depth = 0;

    Polynomial read(const FormulaNode& n) {
        switch (n.kind) {
            case FormulaNode::Kind::Number: return scalar(Expr(n.number));
            case FormulaNode::Kind::Name: {
                if (const int k = scope_.differential(n.name); k >= 0) {
                    Polynomial p;
                    p.degree = 1;
                    p.linear = scope_.differentialForm(k);
                    return p;
                }
                return scalar(lookUp(n, scope_, depth).expr);
            }
            case FormulaNode::Kind::Negate: return scaled(read(*n.args[0]), Expr(-1.0));
            case FormulaNode::Kind::Call: {
                checkCall(n);
                std::vector<Expr> args;
                for (const auto& a : n.args) {
                    const Polynomial p = read(*a);
                    if (p.degree != 0)
                        throw FormulaError(a->offset, "a differential inside " + n.name +
                                                          "(...): the line element is quadratic in them");
                    args.push_back(p.scalar);
                }
                return scalar(call(n.name, args, scope_));
            }
            case FormulaNode::Kind::Binary: return binary(n);
        }
        throw FormulaError(n.offset, "unreadable expression");
    }

private:
    const FormulaScope& scope_;

    static Polynomial scalar(const Expr& e) {
        Polynomial p;
        p.scalar = e;
        return p;
    }

    static Polynomial scaled(Polynomial p, const Expr& f) {
        for (auto& t : p.terms) t.factor = t.factor * f;  // at most 5 (kerrSchildPossible)
        p.scalar = p.scalar * f;
        for (auto& l : p.linear) l = l * f;
        for (int m = 0; m < 4; ++m)
            for (int k = m; k < 4; ++k) p.quadratic(m, k) = p.quadratic(m, k) * f;
        return p;
    }

    Polynomial binary(const FormulaNode& n) {
        const Polynomial a = read(*n.args[0]), b = read(*n.args[1]);
        switch (n.op) {
            case '+':
            case '-': {
                if (a.degree != b.degree)
                    throw FormulaError(n.offset, "'" + std::string(1, n.op) + "' joins a term of degree " +
                                                     std::to_string(a.degree) +
                                                     " in the differentials to one of degree " +
                                                     std::to_string(b.degree) + ": every term of ds2 has two");
                const Expr s(n.op == '+' ? 1.0 : -1.0);
                Polynomial p = a;
                p.kerrSchildPossible = a.kerrSchildPossible && b.kerrSchildPossible;
                for (QuadraticTerm t : b.terms) {
                    t.factor = s * t.factor;
                    p.terms.push_back(t);
                }
                if (p.terms.size() > 5) p.kerrSchildPossible = false;  // eta's four squares and one more
                if (!p.kerrSchildPossible) p.terms.clear();
                p.scalar = a.scalar + s * b.scalar;
                for (std::size_t m = 0; m < 4; ++m) p.linear[m] = a.linear[m] + s * b.linear[m];
                for (int m = 0; m < 4; ++m)
                    for (int k = m; k < 4; ++k) p.quadratic(m, k) = a.quadratic(m, k) + s * b.quadratic(m, k);
                return p;
            }
            case '*': return product(a, b, n.offset);
            case '/':
                if (b.degree != 0) throw FormulaError(n.offset, "division by a differential");
                return scaled(a, Expr(1.0) / b.scalar);
            case '^': {
                if (b.degree != 0) throw FormulaError(n.offset, "a differential in an exponent");
                if (a.degree == 0) return scalar(power(a.scalar, b.scalar));
                const bool square = b.scalar.node().op == codegen::Op::Constant && b.scalar.node().value == 2;
                if (a.degree != 1 || !square)
                    throw FormulaError(n.offset, "only a differential of degree 1 may be squared (^2) in ds2");
                return product(a, a, n.offset);
            }
        }
        throw FormulaError(n.offset, "unknown operator");
    }

    Polynomial product(const Polynomial& a, const Polynomial& b, std::size_t at) {
        if (a.degree + b.degree > 2)
            throw FormulaError(at, "a product of degree " + std::to_string(a.degree + b.degree) +
                                       " in the differentials: the line element is quadratic in them");
        if (a.degree == 0) return scaled(b, a.scalar);
        if (b.degree == 0) return scaled(a, b.scalar);
        Polynomial p;
        p.degree = 2;
        p.terms.push_back(termOf(a, b));
        if (p.terms.back().kind == QuadraticTerm::Kind::Other) {
            p.kerrSchildPossible = false;
            p.terms.clear();
        }
        for (int m = 0; m < 4; ++m)
            for (int k = 0; k < 4; ++k) {
                const Expr c = a.linear[static_cast<std::size_t>(m)] * b.linear[static_cast<std::size_t>(k)];
                if (c.isConstant(0.0)) continue;
                const int i = std::min(m, k), j = std::max(m, k);
                p.quadratic(i, j) = p.quadratic(i, j) + c;
            }
        return p;
    }
};

class ScalarReader {
public:
    explicit ScalarReader(const FormulaScope& scope) : scope_(scope) {}
    int depth = 0;

    Expr read(const FormulaNode& n) {
        switch (n.kind) {
            case FormulaNode::Kind::Number: return Expr(n.number);
            case FormulaNode::Kind::Name: return lookUp(n, scope_, depth).expr;
            case FormulaNode::Kind::Negate: return -read(*n.args[0]);
            case FormulaNode::Kind::Call: {
                checkCall(n);
                std::vector<Expr> args;
                for (const auto& a : n.args) args.push_back(read(*a));
                return call(n.name, args, scope_);
            }
            case FormulaNode::Kind::Binary: {
                const Expr a = read(*n.args[0]), b = read(*n.args[1]);
                switch (n.op) {
                    case '+': return a + b;
                    case '-': return a - b;
                    case '*': return a * b;
                    case '/': return a / b;
                    default: return power(a, b);
                }
            }
        }
        throw FormulaError(n.offset, "unreadable expression");
    }

private:
    const FormulaScope& scope_;
};

void checkGraphDepth(int depth, std::size_t offset) {
    if (depth > kMaxGraphDepth)
        throw FormulaError(offset, "the definitions nest " + std::to_string(depth) + " operations deep; at most " +
                                       std::to_string(kMaxGraphDepth));
}

}  // namespace

int graphHeight(const std::vector<codegen::Expr>& roots) {
    std::unordered_map<const codegen::Node*, int> height;
    std::vector<std::pair<const codegen::Node*, bool>> stack;
    int tallest = 0;
    for (const auto& root : roots) {
        stack.push_back({&root.node(), false});
        while (!stack.empty()) {
            const auto [n, expanded] = stack.back();
            stack.pop_back();
            if (height.count(n)) continue;
            const codegen::Node* children[3] = {n->a.get(), n->b.get(), n->c.get()};
            if (!expanded) {
                stack.push_back({n, true});
                for (const codegen::Node* c : children)
                    if (c && !height.count(c)) stack.push_back({c, false});
                continue;
            }
            int h = 0;
            for (const codegen::Node* c : children)
                if (c) h = std::max(h, height.at(c));
            height[n] = h + 1;
        }
        tallest = std::max(tallest, height.at(&root.node()));
    }
    return tallest;
}

FormulaScope::FormulaScope(const std::array<std::string, 4>& coordinates, Chart chart)
    : coordinates_(coordinates), chart_(chart) {
    for (int k = 0; k < 4; ++k) {
        const std::string& c = coordinates[static_cast<std::size_t>(k)];
        if (const std::string why = whyTaken(c); !why.empty())
            throw std::invalid_argument("coordinate '" + c + "': " + why);
        for (int a = 0; a < 4; ++a)
            jacobian_[static_cast<std::size_t>(k)][static_cast<std::size_t>(a)] = Expr(a == k ? 1.0 : 0.0);
        values_[c] = {Expr::coordinate(k), 1};
    }
    values_["pi"] = {Expr(kPi), 1};
    if (chart == Chart::Cartesian) return;
    // The tracer's Cartesian chart. Within 1e-8 r of the polar axis, where the pull-back's terms
    // are 0/0 on the axis itself, x is moved out to 1e-8 r: the metric there is smooth, so this
    // changes g by about 1e-8 of itself in a cylinder no ray spends time in, while rounding in
    // the Jacobian's cancelling terms grows like 1e-16 r / rho (the two balance at 1e-8).
    const Expr X = Expr::coordinate(1), Y = Expr::coordinate(2), Z = Expr::coordinate(3);
    const Expr r2 = X * X + Y * Y + Z * Z;
    const Expr near = Expr(1e-16) * r2 - (X * X + Y * Y);
    const Expr shift = Expr(1e-8) * sqrt(r2);
    const Expr x = ifPositive(near, ifPositive(X, X + shift, X - shift), X), y = Y, z = Z;
    const Expr rho2 = x * x + y * y, rho = sqrt(rho2), phi = atan2(y, x);
    std::array<Expr, 4> dphi{Expr(0.0), -y / rho2, x / rho2, Expr(0.0)};
    if (chart == Chart::Spherical) {
        const Expr r2s = rho2 + z * z, r = sqrt(r2s);
        theta_ = atan2(rho, z);
        sinTheta_ = rho / r;
        cosTheta_ = z / r;
        values_[coordinates[1]] = {r, graphHeight({r})};
        values_[coordinates[2]] = {theta_, graphHeight({theta_})};
        values_[coordinates[3]] = {phi, graphHeight({phi})};
        jacobian_[1] = {Expr(0.0), x / r, y / r, z / r};
        jacobian_[2] = {Expr(0.0), z * x / (r2s * rho), z * y / (r2s * rho), -rho / r2s};
        jacobian_[3] = dphi;
    } else {
        values_[coordinates[1]] = {rho, graphHeight({rho})};
        values_[coordinates[2]] = {phi, graphHeight({phi})};
        values_[coordinates[3]] = {z, 1};
        jacobian_[1] = {Expr(0.0), x / rho, y / rho, Expr(0.0)};
        jacobian_[2] = dphi;
        jacobian_[3] = {Expr(0.0), Expr(0.0), Expr(0.0), Expr(1.0)};
    }
}

const codegen::Expr* FormulaScope::sinOf(const codegen::Expr& e) const {
    return chart_ == Chart::Spherical && e.pointer() == theta_.pointer() ? &sinTheta_ : nullptr;
}
const codegen::Expr* FormulaScope::cosOf(const codegen::Expr& e) const {
    return chart_ == Chart::Spherical && e.pointer() == theta_.pointer() ? &cosTheta_ : nullptr;
}

int FormulaScope::differential(const std::string& name) const {
    if (name.size() < 2 || name[0] != 'd') return -1;
    for (int k = 0; k < 4; ++k)
        if (name.compare(1, std::string::npos, coordinates_[static_cast<std::size_t>(k)]) == 0) return k;
    return -1;
}

std::string FormulaScope::whyTaken(const std::string& name) const {
    if (isFunction(name)) return "'" + name + "' is a function";
    if (name == "pi") return "'pi' is the constant 3.14159...";
    if (values_.count(name)) return "'" + name + "' is already defined";
    if (differential(name) >= 0) return "'" + name + "' is the differential of a coordinate";
    return "";
}

void FormulaScope::addConstant(const std::string& name, double value) { addDefinition(name, Expr(value), 1); }

void FormulaScope::addDefinition(const std::string& name, const codegen::Expr& value, int depth) {
    if (const std::string why = whyTaken(name); !why.empty()) throw std::invalid_argument(why);
    values_[name] = {value, depth};
}

const FormulaScope::Value* FormulaScope::find(const std::string& name) const {
    const auto it = values_.find(name);
    return it == values_.end() ? nullptr : &it->second;
}

ScalarFormula scalarFormula(const FormulaNode& tree, const FormulaScope& scope) {
    ScalarReader reader(scope);
    ScalarFormula f;
    f.expr = reader.read(tree);
    f.depth = reader.depth + tree.depth;
    checkGraphDepth(f.depth, tree.offset);
    return f;
}

codegen::ExprMatrix4 lineElement(const FormulaNode& tree, const FormulaScope& scope, int& depth,
                                 std::optional<KerrSchildForm>* kerrSchild) {
    LineElementReader reader(scope);
    const Polynomial p = reader.read(tree);
    if (kerrSchild) *kerrSchild = p.degree == 2 && p.kerrSchildPossible ? kerrSchildForm(p.terms) : std::nullopt;
    if (p.degree != 2)
        throw FormulaError(tree.offset, "the line element must be quadratic in the differentials (d" +
                                            scope.coordinates()[0] + "^2, d" + scope.coordinates()[1] + "*d" +
                                            scope.coordinates()[2] + ", ...); this is of degree " +
                                            std::to_string(p.degree));
    depth = reader.depth + tree.depth + 2;
    checkGraphDepth(depth, tree.offset);
    codegen::ExprMatrix4 g;
    for (int m = 0; m < 4; ++m)
        for (int k = m; k < 4; ++k) {
            // dx^m dx^k with m < k collects both orders: g_mk = g_km = half its coefficient.
            g(m, k) = m == k ? p.quadratic(m, k) : Expr(0.5) * p.quadratic(m, k);
            g(k, m) = g(m, k);
        }
    return g;
}

}  // namespace lc::formula
