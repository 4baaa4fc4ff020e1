// SPDX-License-Identifier: BSD-3-Clause
#include "core/codegen/glsl_emitter.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace lc::codegen {
namespace {

std::string expression(Op op, const std::string& a, const std::string& b, const std::string& c) {
    switch (op) {
        case Op::Add: return a + " + " + b;
        case Op::Sub: return a + " - " + b;
        case Op::Mul: return a + " * " + b;
        case Op::Div: return a + " / " + b;
        case Op::Neg: return "-" + a;
        case Op::Sqrt: return "sqrt(" + a + ")";
        case Op::Tanh: return "lcTanh(" + a + ")";
        case Op::Sin: return "sin(" + a + ")";
        case Op::Cos: return "cos(" + a + ")";
        case Op::Exp: return "exp(" + a + ")";
        case Op::Log: return "log(" + a + ")";
        case Op::Abs: return "abs(" + a + ")";
        case Op::Acos: return "acos(" + a + ")";
        case Op::Tan: return "tan(" + a + ")";
        case Op::Asin: return "asin(" + a + ")";
        case Op::Atan: return "atan(" + a + ")";
        case Op::Sinh: return "sinh(" + a + ")";
        case Op::Cosh: return "cosh(" + a + ")";
        case Op::Floor: return "floor(" + a + ")";
        case Op::Pow: return "pow(" + a + ", " + b + ")";
        case Op::Atan2: return "lcAtan2(" + a + ", " + b + ")";
        case Op::Min: return "min(" + a + ", " + b + ")";
        case Op::Max: return "max(" + a + ", " + b + ")";
        case Op::IfPositive: return a + " > 0.0 ? " + b + " : " + c;
        case Op::BesselJ0: return "lcBesselJ0(" + a + ")";
        case Op::BesselJ1: return "lcBesselJ1(" + a + ")";
        default: throw std::logic_error("codegen: not an operation");
    }
}

}  // namespace

std::string floatLiteral(double v) {
    const float f = static_cast<float>(v);
    if (!std::isfinite(f))
        throw std::invalid_argument("codegen: the constant " + std::to_string(v) +
                                    " is outside float's range (GPU tracer)");
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(f));
    std::string s = buf;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return f < 0 ? "(" + s + ")" : s;
}

std::string GlslEmitter::vector(const std::vector<Expr>& components) {
    if (components.empty() || components.size() > 4)
        throw std::invalid_argument("codegen: a GLSL value has 1 to 4 components, not " +
                                    std::to_string(components.size()));
    if (components.size() == 1) return name(components[0]);
    std::string v = "vec" + std::to_string(components.size()) + "(";
    for (std::size_t i = 0; i < components.size(); ++i) v += (i ? ", " : "") + name(components[i]);
    return v + ")";
}

std::string GlslEmitter::name(const NodePtr& node) {
    const Node& n = *node;
    if (const auto it = byNode_.find(&n); it != byNode_.end()) return it->second.second;
    std::string result;
    switch (n.op) {
        case Op::Constant: result = floatLiteral(n.value); break;
        case Op::Variable: result = std::string("X.") + "xyzw"[n.variable]; break;
        case Op::Symbol: result = n.symbol; break;
        default: {
            std::string a = name(n.a), b = n.b ? name(n.b) : std::string(), c = n.c ? name(n.c) : std::string();
            const bool commutative = n.op == Op::Add || n.op == Op::Mul || n.op == Op::Min || n.op == Op::Max;
            if (commutative && b < a) std::swap(a, b);  // one key
            const auto key = std::make_tuple(static_cast<int>(n.op), a, b, c);
            if (const auto it = byStructure_.find(key); it != byStructure_.end()) {
                result = it->second;
                break;
            }
            result = "t" + std::to_string(count_++);
            body_ << "  float " << result << " = " << expression(n.op, a, b, c) << ";\n";
            byStructure_.emplace(key, result);
        }
    }
    byNode_.emplace(&n, std::make_pair(node, result));
    return result;
}

}  // namespace lc::codegen
