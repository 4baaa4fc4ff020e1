// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The expression language of metrics written as text (docs/METRICS.md): numbers, names,
// + - * / ^ (also **), parentheses and the functions of kFormulaFunctions. Parsed into a small
// syntax tree that keeps each node's position, so that every later error (an unknown name, a
// differential where none belongs) points at its place in the text.
//
// Hostile input is bounded here: text length, name length, nesting and tree depth have limits
// that a physicist's formula never reaches, each refused with its own message.
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace lc::formula {

// Limits on one formula text (docs/METRICS.md, "Limits").
inline constexpr std::size_t kMaxFormulaBytes = 64 * 1024;
inline constexpr std::size_t kMaxNameLength = 64;
inline constexpr int kMaxNesting = 100;     // parentheses and function calls inside each other
inline constexpr int kMaxTreeDepth = 1000;  // operations on the longest path of one formula

// A problem at a byte offset of one formula's text; describe() adds the column and a caret line.
class FormulaError : public std::runtime_error {
public:
    FormulaError(std::size_t offset, const std::string& problem)
        : std::runtime_error(problem), offset_(offset), problem_(problem) {}
    std::size_t offset() const { return offset_; }
    const std::string& problem() const { return problem_; }

private:
    std::size_t offset_;
    std::string problem_;
};

// "column 14: unknown name 'rr'" followed by the text (a window of it, if long) and a caret
// under column 14.
std::string describeAt(const std::string& text, std::size_t offset, const std::string& problem);

struct FormulaNode {
    enum class Kind { Number, Name, Negate, Binary, Call };
    Kind kind = Kind::Number;
    double number = 0;  // Number
    std::string name;   // Name, Call
    char op = 0;        // Binary: + - * / ^
    std::vector<std::unique_ptr<FormulaNode>> args;
    std::size_t offset = 0;  // where the node starts (Binary: its operator)
    int depth = 1;           // operations on the longest path below and including this node
};
using FormulaTree = std::unique_ptr<FormulaNode>;

// Parses one expression: the text from `start` to its end (a definition's expression starts after
// "name ="); offsets in nodes and errors count from the text's beginning. Throws FormulaError.
FormulaTree parseFormula(const std::string& text, std::size_t start = 0);

// Splits "name = expression" at its '=' (a definition); throws FormulaError unless the part
// before it is one valid name. `expressionOffset` receives where the expression starts.
std::string definitionName(const std::string& text, std::size_t& expressionOffset);

struct FormulaFunction {
    const char* name;
    int arity;
};
// Every function the language knows, for messages and docs.
const std::vector<FormulaFunction>& formulaFunctions();

}  // namespace lc::formula
