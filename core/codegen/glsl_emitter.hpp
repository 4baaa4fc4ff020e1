// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Prints recorded expressions as GLSL statements: each distinct subexpression once, as
// `float tN = ...;`, in the order it is first needed, so that generated functions (a metric,
// Hamilton's equations, a Runge-Kutta step) compute every shared factor a single time.
#include "core/codegen/expression.hpp"

#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace lc::codegen {

// Symbols name.x, name.y, ... for the components of a GLSL vector of N components.
template <int N>
Eigen::Matrix<Expr, N, 1> vectorSymbol(const std::string& name) {
    static const char* const components[4] = {"x", "y", "z", "w"};
    Eigen::Matrix<Expr, N, 1> v;
    for (int i = 0; i < N; ++i) v(i) = Expr::symbol(name + "." + components[i]);
    return v;
}

// A constant as a GLSL float literal, rounded to float once; throws std::invalid_argument for a
// constant outside float's range (it would be inf on the GPU).
std::string floatLiteral(double v);

class GlslEmitter {
public:
    // The GLSL name of the value of `node`, emitting the statements it needs first. Nodes are
    // identified by structure (operation and operand names), not only by address, so that equal
    // subexpressions built separately merge. The emitter holds every node it named: a freed
    // node's address could otherwise be reused by a new node and inherit its name.
    std::string name(const NodePtr& node);
    std::string name(const Expr& e) { return name(e.pointer()); }
    // The GLSL value of 1 to 4 expressions: a float's name, or vecN(names...).
    std::string vector(const std::vector<Expr>& components);
    // A statement of the caller's (a function call between generated values), in order.
    void statement(const std::string& line) { body_ << "  " << line << "\n"; }
    std::string body() const { return body_.str(); }
    int count() const { return count_; }

private:
    std::unordered_map<const Node*, std::pair<NodePtr, std::string>> byNode_;
    std::map<std::tuple<int, std::string, std::string, std::string>, std::string> byStructure_;
    std::ostringstream body_;
    int count_ = 0;
};

}  // namespace lc::codegen
