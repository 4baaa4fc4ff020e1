// SPDX-License-Identifier: BSD-3-Clause
#include "core/formula/formula_parser.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace lc::formula {
namespace {

bool isNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string byteText(unsigned char c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02X", c);
    return buf;
}

// Recursive descent over
//   sum     := product (('+' | '-') product)*
//   product := unary (('*' | '/') unary)*
//   unary   := ('-' | '+') unary | power
//   power   := primary (('^' | '**') unary)?        (right-associative: 2^-x, -x^2 = -(x^2))
//   primary := number | name | name '(' sum (',' sum)* ')' | '(' sum ')'
class Parser {
public:
    Parser(const std::string& text, std::size_t start) : s_(text), pos_(start) {}

    FormulaTree parse() {
        if (s_.size() - pos_ > kMaxFormulaBytes)
            throw FormulaError(pos_, "the formula is " + std::to_string(s_.size() - pos_) + " bytes long; at most " +
                                         std::to_string(kMaxFormulaBytes) + " are accepted (use definitions)");
        skipSpace();
        if (pos_ == s_.size()) throw FormulaError(pos_, "the formula is empty");
        FormulaTree tree = sum();
        skipSpace();
        if (pos_ != s_.size()) {
            if (s_[pos_] == ')') throw FormulaError(pos_, "')' without a matching '('");
            throw FormulaError(pos_, "unexpected " + describeToken() + " after a complete expression");
        }
        return tree;
    }

private:
    const std::string& s_;
    std::size_t pos_;
    int nesting_ = 0;

    void skipSpace() {
        while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' || s_[pos_] == '\r'))
            ++pos_;
    }

    // 1-based column of an offset within its line of the text.
    std::size_t columnOf(std::size_t offset) const {
        const std::size_t newline = offset == 0 ? std::string::npos : s_.rfind('\n', offset - 1);
        return offset - (newline == std::string::npos ? 0 : newline + 1) + 1;
    }

    std::string describeToken() const {
        if (pos_ >= s_.size()) return "end of the formula";
        const unsigned char c = static_cast<unsigned char>(s_[pos_]);
        if (c >= 0x80) return "byte " + byteText(c) + " (formulas are ASCII: write theta, not the Greek letter)";
        if (c < 0x20 || c == 0x7f) return "control byte " + byteText(c);
        return std::string("'") + static_cast<char>(c) + "'";
    }

    FormulaTree node(FormulaNode::Kind kind, std::size_t offset) {
        auto n = std::make_unique<FormulaNode>();
        n->kind = kind;
        n->offset = offset;
        return n;
    }

    FormulaTree join(char op, std::size_t offset, FormulaTree a, FormulaTree b) {
        FormulaTree n = node(FormulaNode::Kind::Binary, offset);
        n->op = op;
        n->depth = 1 + std::max(a->depth, b->depth);
        n->args.push_back(std::move(a));
        n->args.push_back(std::move(b));
        checkDepth(*n);
        return n;
    }

    void checkDepth(const FormulaNode& n) const {
        if (n.depth > kMaxTreeDepth)
            throw FormulaError(n.offset, "the formula is more than " + std::to_string(kMaxTreeDepth) +
                                             " operations deep here; split it into definitions");
    }

    FormulaTree sum() {
        FormulaTree left = product();
        for (;;) {
            skipSpace();
            if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) {
                const char op = s_[pos_];
                const std::size_t at = pos_++;
                left = join(op, at, std::move(left), product());
            } else {
                return left;
            }
        }
    }

    FormulaTree product() {
        FormulaTree left = unary();
        for (;;) {
            skipSpace();
            if (pos_ < s_.size() && s_[pos_] == '*' && !(pos_ + 1 < s_.size() && s_[pos_ + 1] == '*')) {
                const std::size_t at = pos_++;
                left = join('*', at, std::move(left), unary());
            } else if (pos_ < s_.size() && s_[pos_] == '/') {
                const std::size_t at = pos_++;
                left = join('/', at, std::move(left), unary());
            } else {
                return left;
            }
        }
    }

    FormulaTree unary() {
        skipSpace();
        if (pos_ < s_.size() && (s_[pos_] == '-' || s_[pos_] == '+')) {
            const bool negate = s_[pos_] == '-';
            const std::size_t at = pos_++;
            enter(at);
            FormulaTree operand = unary();
            leave();
            if (!negate) return operand;
            FormulaTree n = node(FormulaNode::Kind::Negate, at);
            n->depth = 1 + operand->depth;
            n->args.push_back(std::move(operand));
            checkDepth(*n);
            return n;
        }
        return power();
    }

    FormulaTree power() {
        FormulaTree base = primary();
        skipSpace();
        const bool caret = pos_ < s_.size() && s_[pos_] == '^';
        const bool stars = pos_ + 1 < s_.size() && s_[pos_] == '*' && s_[pos_ + 1] == '*';
        if (!caret && !stars) return base;
        const std::size_t at = pos_;
        pos_ += caret ? 1 : 2;
        enter(at);
        FormulaTree exponent = unary();
        leave();
        return join('^', at, std::move(base), std::move(exponent));
    }

    void enter(std::size_t at) {
        if (++nesting_ > kMaxNesting)
            throw FormulaError(at, "more than " + std::to_string(kMaxNesting) +
                                       " parentheses, calls or signs inside each other; split it into definitions");
    }
    void leave() { --nesting_; }

    FormulaTree primary() {
        skipSpace();
        if (pos_ >= s_.size()) throw FormulaError(pos_, "the formula ends where a value was expected");
        const char c = s_[pos_];
        if (c == '(') {
            const std::size_t open = pos_++;
            enter(open);
            FormulaTree inner = sum();
            leave();
            skipSpace();
            if (pos_ >= s_.size() || s_[pos_] != ')')
                throw FormulaError(pos_ >= s_.size() ? open : pos_, pos_ >= s_.size()
                                                                        ? "'(' is never closed"
                                                                        : "expected ')' to close the '(' at column " +
                                                                              std::to_string(columnOf(open)) +
                                                                              ", found " + describeToken());
            ++pos_;
            return inner;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
        if (isNameStart(c)) return nameOrCall();
        if (c == ')') throw FormulaError(pos_, "')' where a value was expected");
        throw FormulaError(pos_, "unexpected " + describeToken() + " where a value was expected");
    }

    FormulaTree number() {
        const std::size_t start = pos_;
        while (pos_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '.')) ++pos_;
        if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
            std::size_t p = pos_ + 1;
            if (p < s_.size() && (s_[p] == '+' || s_[p] == '-')) ++p;
            if (p < s_.size() && std::isdigit(static_cast<unsigned char>(s_[p]))) {
                pos_ = p;
                while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
            }
        }
        const std::string literal = s_.substr(start, pos_ - start);
        if (literal.size() > 64) throw FormulaError(start, "a number of more than 64 characters");
        char* end = nullptr;
        const double v = std::strtod(literal.c_str(), &end);
        if (end != literal.c_str() + literal.size() || std::count(literal.begin(), literal.end(), '.') > 1)
            throw FormulaError(start, "'" + literal + "' is not a number");
        if (!std::isfinite(v)) throw FormulaError(start, "the number " + literal + " is beyond double's range");
        if (pos_ < s_.size() && isNameStart(s_[pos_]))
            throw FormulaError(pos_, "a name right after the number " + literal + ": write '*' between them");
        FormulaTree n = node(FormulaNode::Kind::Number, start);
        n->number = v;
        return n;
    }

    FormulaTree nameOrCall() {
        const std::size_t start = pos_;
        while (pos_ < s_.size() && isNameChar(s_[pos_])) ++pos_;
        if (pos_ - start > kMaxNameLength)
            throw FormulaError(start, "a name of " + std::to_string(pos_ - start) + " characters; at most " +
                                          std::to_string(kMaxNameLength));
        const std::string name = s_.substr(start, pos_ - start);
        skipSpace();
        if (pos_ >= s_.size() || s_[pos_] != '(') {
            FormulaTree n = node(FormulaNode::Kind::Name, start);
            n->name = name;
            return n;
        }
        const std::size_t open = pos_++;
        enter(open);
        FormulaTree call = node(FormulaNode::Kind::Call, start);
        call->name = name;
        for (;;) {
            FormulaTree arg = sum();
            call->depth = std::max(call->depth, 1 + arg->depth);
            call->args.push_back(std::move(arg));
            skipSpace();
            if (pos_ < s_.size() && s_[pos_] == ',') {
                ++pos_;
                if (call->args.size() >= 8) throw FormulaError(pos_, "more than 8 arguments");
                continue;
            }
            if (pos_ < s_.size() && s_[pos_] == ')') {
                ++pos_;
                break;
            }
            throw FormulaError(pos_ >= s_.size() ? open : pos_,
                               pos_ >= s_.size()
                                   ? "'(' of " + name + "( is never closed"
                                   : "expected ',' or ')' in the arguments of " + name + ", found " + describeToken());
        }
        leave();
        checkDepth(*call);
        return call;
    }
};

}  // namespace

std::string describeAt(const std::string& text, std::size_t offset, const std::string& problem) {
    offset = std::min(offset, text.size());
    // The line of a multi-line text that holds the offset.
    const std::size_t lineStart = text.rfind('\n', offset == 0 ? 0 : offset - 1) == std::string::npos
                                      ? 0
                                      : text.rfind('\n', offset == 0 ? 0 : offset - 1) + 1;
    std::size_t lineEnd = text.find('\n', offset);
    if (lineEnd == std::string::npos) lineEnd = text.size();
    int lineNumber = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(lineStart), '\n'));
    // A window of at most 72 characters around the offset, printable bytes only.
    const std::size_t from = offset - lineStart > 40 ? offset - 40 : lineStart;
    const std::size_t to = std::min(lineEnd, from + 72);
    std::string excerpt;
    for (std::size_t i = from; i < to; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        excerpt += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
    }
    std::string where = "column " + std::to_string(offset - lineStart + 1);
    if (lineNumber > 1 || lineEnd < text.size()) where = "line " + std::to_string(lineNumber) + ", " + where;
    return where + ": " + problem + "\n    " + (from > lineStart ? "..." : "") + excerpt + (to < lineEnd ? "..." : "") +
           "\n    " + std::string((from > lineStart ? 3 : 0) + (offset - from), ' ') + "^";
}

FormulaTree parseFormula(const std::string& text, std::size_t start) { return Parser(text, start).parse(); }

std::string definitionName(const std::string& text, std::size_t& expressionOffset) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) throw FormulaError(0, "a definition is written 'name = expression' (no '=' found)");
    std::size_t b = 0, e = eq;
    while (b < e && std::isspace(static_cast<unsigned char>(text[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(text[e - 1]))) --e;
    if (b == e) throw FormulaError(eq, "a definition needs a name before '='");
    if (!isNameStart(text[b])) throw FormulaError(b, "a name starts with a letter or '_'");
    for (std::size_t i = b; i < e; ++i)
        if (!isNameChar(text[i])) throw FormulaError(i, "a definition's name is one word of letters, digits and '_'");
    if (e - b > kMaxNameLength)
        throw FormulaError(
            b, "a name of " + std::to_string(e - b) + " characters; at most " + std::to_string(kMaxNameLength));
    expressionOffset = eq + 1;
    return text.substr(b, e - b);
}

const std::vector<FormulaFunction>& formulaFunctions() {
    static const std::vector<FormulaFunction> list{
        {"sqrt", 1}, {"exp", 1},   {"log", 1},  {"sin", 1},  {"cos", 1},      {"tan", 1},      {"asin", 1},
        {"acos", 1}, {"atan", 1},  {"sinh", 1}, {"cosh", 1}, {"tanh", 1},     {"abs", 1},      {"min", 2},
        {"max", 2},  {"atan2", 2}, {"pow", 2},  {"step", 2}, {"besselj0", 1}, {"besselj1", 1},
    };
    return list;
}

}  // namespace lc::formula
