// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The command line of one command, parsed by CLI11 from its declaration (app/cli/command_line.hpp):
// a misspelt option, a flag given a value, a value missing, a word outside an option's choices
// and an option without the one it needs (or with one it excludes) are errors instead of being
// ignored. Numbers are parsed strictly ("0.5xyz", "nan", "inf" and "2.5" for an integer are
// errors) and checked against the range the declaration gives (core/input/ranges.hpp).
#include "app/cli/command_line.hpp"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace lc::cli {

class Args {
public:
    // argv without the program and command names. Throws std::invalid_argument naming the option.
    Args(const std::vector<std::string>& argv, const CommandDeclaration& command);

    // k: any name of a declared option ("-o" or "--output").
    bool has(const std::string& k) const;
    // The last value given (an option given twice: the later wins).
    std::string get(const std::string& k, const std::string& fallback = "") const;
    std::vector<std::string> all(const std::string& k) const;

    // The option's value, finite and inside its declared range; fallback when absent.
    double number(const std::string& k, double fallback) const;
    int integer(const std::string& k, int fallback) const;
    // "a,b,c": exactly n numbers, each inside the declared range (or `range` for an option that
    // declares none because its numbers have different ranges, such as --blink).
    std::vector<double> numbers(const std::string& k, std::size_t n, const input::Range* range = nullptr) const;
    // The declared range of option k (for values of several parts, such as "T0:T1:N").
    const input::Range& range(const std::string& k) const;

    const std::vector<std::string>& positional() const { return positional_; }

private:
    const CommandDeclaration& command_;
    std::map<std::string, std::vector<std::string>> options_;  // by long name
    std::vector<std::string> positional_;
};

// Same for a "NAME=VALUE" text (trace --param): strict number, named in errors.
double parseNamedNumber(const std::string& option, const std::string& text, const input::Range& range);

}  // namespace lc::cli
