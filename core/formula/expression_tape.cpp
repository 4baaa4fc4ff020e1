// SPDX-License-Identifier: BSD-3-Clause
#include "core/formula/expression_tape.hpp"

#include "core/numerics/bessel.hpp"

#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

namespace lc::formula {

using codegen::Node;
using codegen::Op;

ExpressionTape::ExpressionTape(const std::vector<codegen::Expr>& outputs) {
    initial_.assign(4, 0.0);
    std::unordered_map<const Node*, std::int32_t> slot;
    std::map<std::uint64_t, std::int32_t> constants;  // by bit pattern: NaN, -0 and +0 stay apart
    // Structure (op, operand slots) -> slot: equal subexpressions built apart are merged.
    std::map<std::tuple<int, std::int32_t, std::int32_t, std::int32_t>, std::int32_t> byStructure;
    std::vector<Instruction> pending;  // ops, numbered after the constants once all are known
    std::vector<std::int32_t> opSlot;  // provisional op index -> final register (filled below)

    // Provisional numbering: values >= 0 are initial_ registers; ops are -(index + 1).
    auto visit = [&](const codegen::NodePtr& root) {
        std::vector<std::pair<const Node*, bool>> stack{{root.get(), false}};
        while (!stack.empty()) {
            auto [n, expanded] = stack.back();
            stack.pop_back();
            if (slot.count(n)) continue;
            if (n->op == Op::Constant) {
                std::uint64_t bits;
                std::memcpy(&bits, &n->value, sizeof bits);
                const auto it = constants.find(bits);
                std::int32_t s;
                if (it != constants.end()) {
                    s = it->second;
                } else {
                    s = static_cast<std::int32_t>(initial_.size());
                    initial_.push_back(n->value);
                    constants[bits] = s;
                }
                slot[n] = s;
                continue;
            }
            if (n->op == Op::Variable) {
                slot[n] = n->variable;
                continue;
            }
            if (n->op == Op::Symbol)
                throw std::invalid_argument("expression tape: the symbol '" + n->symbol + "' has no value");
            if (!expanded) {
                stack.push_back({n, true});
                for (const auto& child : {n->c, n->b, n->a})
                    if (child && !slot.count(child.get())) stack.push_back({child.get(), false});
                continue;
            }
            const std::int32_t a = slot.at(n->a.get()), b = n->b ? slot.at(n->b.get()) : 0,
                               c = n->c ? slot.at(n->c.get()) : 0;
            const auto key = std::make_tuple(static_cast<int>(n->op), a, b, c);
            if (const auto it = byStructure.find(key); it != byStructure.end()) {
                slot[n] = it->second;
                continue;
            }
            const std::int32_t s = -static_cast<std::int32_t>(pending.size()) - 1;
            pending.push_back({n->op, a, b, c});
            byStructure.emplace(key, s);
            slot[n] = s;
        }
    };
    for (const auto& e : outputs) visit(e.pointer());

    // Final registers: initial_ first, then the ops in the order they were created (operands
    // always before their users, as the walk above is post-order).
    const auto base = static_cast<std::int32_t>(initial_.size());
    auto final = [base](std::int32_t s) { return s >= 0 ? s : base + (-s - 1); };
    code_.reserve(pending.size());
    for (const Instruction& in : pending) code_.push_back({in.op, final(in.a), final(in.b), final(in.c)});
    for (const auto& e : outputs) outputs_.push_back(final(slot.at(e.pointer().get())));
}

void ExpressionTape::evaluate(const double* x, double* out) const {
    thread_local std::vector<double> r;
    r.resize(registers());
    std::memcpy(r.data(), initial_.data(), initial_.size() * sizeof(double));
    std::memcpy(r.data(), x, 4 * sizeof(double));
    double* v = r.data() + initial_.size();
    const double* R = r.data();
    for (const Instruction& in : code_) {
        const double a = R[in.a];
        double y;
        switch (in.op) {
            case Op::Add: y = a + R[in.b]; break;
            case Op::Sub: y = a - R[in.b]; break;
            case Op::Mul: y = a * R[in.b]; break;
            case Op::Div: y = a / R[in.b]; break;
            case Op::Neg: y = -a; break;
            case Op::Sqrt: y = std::sqrt(a); break;
            case Op::Tanh: y = std::tanh(a); break;
            case Op::Sin: y = std::sin(a); break;
            case Op::Cos: y = std::cos(a); break;
            case Op::Exp: y = std::exp(a); break;
            case Op::Log: y = std::log(a); break;
            case Op::Abs: y = std::fabs(a); break;
            case Op::Acos: y = std::acos(a); break;
            case Op::Tan: y = std::tan(a); break;
            case Op::Asin: y = std::asin(a); break;
            case Op::Atan: y = std::atan(a); break;
            case Op::Sinh: y = std::sinh(a); break;
            case Op::Cosh: y = std::cosh(a); break;
            case Op::Floor: y = std::floor(a); break;
            case Op::Pow: y = std::pow(a, R[in.b]); break;
            case Op::Atan2: y = std::atan2(a, R[in.b]); break;
            case Op::Min: y = std::fmin(a, R[in.b]); break;
            case Op::Max: y = std::fmax(a, R[in.b]); break;
            case Op::IfPositive: y = a > 0 ? R[in.b] : R[in.c]; break;
            case Op::BesselJ0: y = lc::besselJ0(a); break;
            case Op::BesselJ1: y = lc::besselJ1(a); break;
            default: y = 0; break;
        }
        *v++ = y;
    }
    for (std::size_t i = 0; i < outputs_.size(); ++i) out[i] = R[outputs_[i]];
}

namespace {
// A value and its derivatives along the four coordinates. The derivatives are one vector
// (GCC's vector extension), written and read whole: stored piecewise and loaded as a vector,
// they would stall every load on failed store-to-load forwarding.
typedef double Gradient __attribute__((vector_size(32)));
struct Dual {
    Gradient d;
    double v;
};
inline void scaled(Dual& y, const Dual& a, double f) { y.d = a.d * f; }
}  // namespace

// Threaded dispatch (GCC's labels as values): each operation jumps to the next one's code
// itself, so the branch predictor learns the tape's fixed sequence per operation instead of
// guessing at one shared switch; this halves the cost per instruction against a switch loop.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
void ExpressionTape::evaluateWithGradient(const double* x, double* out) const {
    constexpr std::size_t kStackRegisters = 256;
    Dual stackRegisters[kStackRegisters];
    thread_local std::vector<Dual> heapRegisters;
    Dual* r = stackRegisters;
    if (registers() > kStackRegisters) {
        heapRegisters.resize(registers());
        r = heapRegisters.data();
    }
    for (std::size_t i = 0; i < initial_.size(); ++i) r[i] = Dual{Gradient{0, 0, 0, 0}, initial_[i]};
    for (int k = 0; k < 4; ++k) {
        r[k].v = x[k];
        r[k].d[k] = 1;
    }
    static const void* const labels[] = {&&other, &&other, &&other,  // Constant, Variable, Symbol never reach the tape
                                         &&add,   &&sub,   &&mul,   &&div,   &&neg,    &&sqrt_, &&tanh_,
                                         &&sin_,  &&cos_,  &&exp_,  &&log_,  &&abs_,   &&acos_, &&tan_,
                                         &&asin_, &&atan_, &&sinh_, &&cosh_, &&floor_, &&pow_,  &&atan2_,
                                         &&min_,  &&max_,  &&if_,   &&j0_,   &&j1_};
    static_assert(static_cast<int>(Op::BesselJ1) == 28, "the label table follows codegen::Op");
    Dual* y = r + initial_.size();
    const Instruction* in = code_.data();
    const Instruction* const end = in + code_.size();
#define LC_NEXT                                 \
    do {                                        \
        ++y;                                    \
        if (++in == end) goto done;             \
        goto* labels[static_cast<int>(in->op)]; \
    } while (0)
#define LC_A (r[in->a])
#define LC_B (r[in->b])
#define LC_UNARY(value, factor)  \
    {                            \
        const Dual& a = LC_A;    \
        y->v = (value);          \
        scaled(*y, a, (factor)); \
        LC_NEXT;                 \
    }
    if (in == end) goto done;
    goto* labels[static_cast<int>(in->op)];
add : {
    const Dual &a = LC_A, &b = LC_B;
    y->v = a.v + b.v;
    y->d = a.d + b.d;
    LC_NEXT;
}
sub : {
    const Dual &a = LC_A, &b = LC_B;
    y->v = a.v - b.v;
    y->d = a.d - b.d;
    LC_NEXT;
}
mul : {
    const Dual &a = LC_A, &b = LC_B;
    y->v = a.v * b.v;
    y->d = a.d * b.v + a.v * b.d;
    LC_NEXT;
}
div : {
    const Dual &a = LC_A, &b = LC_B;
    const double q = a.v / b.v, inv = 1 / b.v;
    y->v = q;
    y->d = (a.d - q * b.d) * inv;
    LC_NEXT;
}
neg:
    LC_UNARY(-a.v, -1.0)
sqrt_:
    LC_UNARY(std::sqrt(a.v), 0.5 / y->v)
tanh_:
    LC_UNARY(std::tanh(a.v), 1 - y->v * y->v)
sin_:
    LC_UNARY(std::sin(a.v), std::cos(a.v))
cos_:
    LC_UNARY(std::cos(a.v), -std::sin(a.v))
exp_:
    LC_UNARY(std::exp(a.v), y->v)
log_:
    LC_UNARY(std::log(a.v), 1 / a.v)
abs_:
    LC_UNARY(std::fabs(a.v), a.v > 0 ? 1.0 : a.v < 0 ? -1.0 : 0.0)
acos_:
    LC_UNARY(std::acos(a.v), -1 / std::sqrt(1 - a.v * a.v))
tan_:
    LC_UNARY(std::tan(a.v), 1 + y->v * y->v)
asin_:
    LC_UNARY(std::asin(a.v), 1 / std::sqrt(1 - a.v * a.v))
atan_:
    LC_UNARY(std::atan(a.v), 1 / (1 + a.v * a.v))
sinh_:
    LC_UNARY(std::sinh(a.v), std::cosh(a.v))
cosh_:
    LC_UNARY(std::cosh(a.v), std::sinh(a.v))
floor_:
    LC_UNARY(std::floor(a.v), 0.0)
pow_ : {
    const Dual &a = LC_A, &b = LC_B;
    y->v = std::pow(a.v, b.v);
    if (b.d[0] == 0 && b.d[1] == 0 && b.d[2] == 0 && b.d[3] == 0) {
        scaled(*y, a, b.v * std::pow(a.v, b.v - 1));
    } else {
        const double la = std::log(a.v), f = b.v / a.v;
        y->d = y->v * (b.d * la + f * a.d);
    }
    LC_NEXT;
}
atan2_ : {  // atan2(a = y, b = x)
    const Dual &a = LC_A, &b = LC_B;
    y->v = std::atan2(a.v, b.v);
    const double inv = 1 / (a.v * a.v + b.v * b.v);
    y->d = (b.v * a.d - a.v * b.d) * inv;
    LC_NEXT;
}
min_:  // as std::fmin: a NaN operand gives the other
    *y = std::isnan(LC_B.v) || LC_B.v - LC_A.v > 0 ? LC_A : LC_B;
    LC_NEXT;
max_:
    *y = std::isnan(LC_B.v) || LC_A.v - LC_B.v > 0 ? LC_A : LC_B;
    LC_NEXT;
if_:
    *y = LC_A.v > 0 ? r[in->b] : r[in->c];
    LC_NEXT;
j0_:
    LC_UNARY(lc::besselJ0(a.v), -lc::besselJ1(a.v))
j1_:
    LC_UNARY(lc::besselJ1(a.v), lc::besselJ1Derivative(a.v, lc::besselJ0(a.v), y->v))
other:
    *y = Dual{Gradient{0, 0, 0, 0}, 0};
    LC_NEXT;
#undef LC_UNARY
#undef LC_B
#undef LC_A
#undef LC_NEXT
done:
    for (std::size_t i = 0; i < outputs_.size(); ++i) {
        const Dual& o = r[outputs_[i]];
        out[5 * i] = o.v;
        for (int k = 0; k < 4; ++k) out[5 * i + 1 + static_cast<std::size_t>(k)] = o.d[k];
    }
}
#pragma GCC diagnostic pop

}  // namespace lc::formula
