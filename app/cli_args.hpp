#pragma once
// The command line of one command: every option is declared (as a flag or as taking a value),
// so a misspelt option, a flag given a value or a value missing is an error instead of being
// ignored or swallowing the next argument. Numbers are parsed strictly ("0.5xyz", "nan", "inf"
// and "2.5" for an integer are errors) and checked against core/input/ranges.hpp.
#include "core/input/ranges.hpp"

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace lc::cli {

struct CommandSpec {
    std::set<std::string> valued;  // "--width N", "--width=N"; may repeat where the command says so
    std::set<std::string> flags;   // "--quiet"
};

class Args {
public:
    // argv without the program and command names.
    Args(const std::vector<std::string>& argv, const CommandSpec& spec);

    bool has(const std::string& k) const { return options_.count(k) > 0; }
    std::string get(const std::string& k, const std::string& fallback = "") const {
        return has(k) ? options_.at(k).back() : fallback;
    }
    std::vector<std::string> all(const std::string& k) const {
        return has(k) ? options_.at(k) : std::vector<std::string>{};
    }

    // The option's value, finite and inside `range`; fallback when absent.
    double number(const std::string& k, double fallback, const input::Range& range) const;
    int integer(const std::string& k, int fallback, const input::Range& range) const;
    // "a,b,c": exactly n numbers, each inside `range`.
    std::vector<double> numbers(const std::string& k, std::size_t n, const input::Range& range) const;

    const std::vector<std::string>& positional() const { return positional_; }

private:
    std::map<std::string, std::vector<std::string>> options_;
    std::vector<std::string> positional_;
};

// Same for a "NAME=VALUE" text (trace --param): strict number, named in errors.
double parseNamedNumber(const std::string& option, const std::string& text, const input::Range& range);

}  // namespace lc::cli
