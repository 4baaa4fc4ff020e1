// SPDX-License-Identifier: BSD-3-Clause
#include "app/cli/cli_args.hpp"

#include "app/cli/cli11_parser.hpp"

#include <CLI/CLI.hpp>

namespace lc::cli {

std::unique_ptr<CLI::App> makeParser(const CommandDeclaration& command) {
    auto app = std::make_unique<CLI::App>(command.summary, "lightcone " + command.name);
    app->set_help_flag();  // main.cpp answers --help from the same declaration
    app->allow_extras();   // positionals and unknown options, named by Args below
    for (const OptionDeclaration& o : command.options) {
        CLI::Option* option = o.flag() ? app->add_flag(o.names, o.help) : app->add_option(o.names, o.help);
        option->group(o.group);
        if (o.flag())
            option->disable_flag_override();  // "--quiet=yes" is refused
        else
            option->type_name(o.value)
                ->expected(1)  // one value per occurrence: "--width 5 6" leaves 6 positional
                ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
                ->allow_extra_args(false);
    }
    for (const OptionDeclaration& o : command.options) {
        CLI::Option* option = app->get_option(o.longName());
        for (const std::string& other : o.needs) option->needs(app->get_option(other));
        for (const std::string& other : o.excludes) option->excludes(app->get_option(other));
    }
    return app;
}

namespace {

bool looksLikeOption(const std::string& a) { return a.size() > 1 && a[0] == '-' && !input::parseNumber(a); }

std::string optionName(const std::string& a) { return a.substr(0, a.find('=')); }

std::string list(const CommandDeclaration& command) {
    std::string s;
    for (const OptionDeclaration& o : command.options) s += " " + o.longName();
    return s;
}

double checked(const std::string& option, const std::string& text, const input::Range& range) {
    const auto v = input::parseNumber(text);
    if (!v) throw std::invalid_argument("option " + option + " expects " + range.describe() + ", got '" + text + "'");
    range.require(*v, "option " + option);
    return *v;
}

// CLI11 names a value missing or a flag given one by its class; the command line says which.
std::invalid_argument mismatch(const std::vector<std::string>& argv, const CommandDeclaration& command,
                               const CLI::ParseError& error) {
    for (const std::string& a : argv) {
        const OptionDeclaration* o = command.option(optionName(a));
        if (o && o->flag() && a.find('=') != std::string::npos)
            return std::invalid_argument("option " + o->longName() + " is a flag and takes no value");
    }
    if (!argv.empty())
        if (const OptionDeclaration* o = command.option(argv.back()); o && !o->flag())
            return std::invalid_argument("option " + o->longName() + " needs a value (" + o->value + ")");
    return std::invalid_argument(error.what());
}

// The declared pair CLI11 found broken (it throws before saying which), in Lightcone's words.
std::invalid_argument brokenRule(const CLI::App& app, const CommandDeclaration& command, const CLI::ParseError& error) {
    const auto given = [&](const std::string& name) { return app.get_option(name)->count() > 0; };
    for (const OptionDeclaration& o : command.options)  // "not both" first: a missing partner may be the fix
        for (const std::string& other : o.excludes)
            if (given(o.longName()) && given(other))
                return std::invalid_argument("give " + o.longName() + " or " + other + ", not both");
    for (const OptionDeclaration& o : command.options)
        for (const std::string& other : o.needs)
            if (given(o.longName()) && !given(other))
                return std::invalid_argument(o.longName() + " goes with " + other);
    return std::invalid_argument(error.what());
}

// Every remaining argument that looks like an option is one the command does not declare.
void rejectUnknownOptions(const std::vector<std::string>& remaining, const CommandDeclaration& command) {
    for (const std::string& a : remaining)
        if (looksLikeOption(a))
            throw std::invalid_argument("unknown option '" + optionName(a) + "' (this command takes:" + list(command) +
                                        ")");
}

void requireChoice(const OptionDeclaration& o, const std::string& value) {
    for (const std::string& c : o.choices)
        if (c == value) return;
    std::string words;
    for (const std::string& c : o.choices) words += (words.empty() ? "" : ", ") + c;
    throw std::invalid_argument("option " + o.longName() + ": expected one of " + words + "; got '" + value + "'");
}

// What CLI11 would take wrongly or name unclearly: `--width=` (no value after '=') and an option
// whose value is missing because the next argument is an option (`--data --help`).
void rejectMissingValues(const std::vector<std::string>& argv, const CommandDeclaration& command) {
    for (std::size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        const OptionDeclaration* o = command.option(optionName(a));
        if (!o || o->flag()) continue;
        if (a.size() > o->longName().size() && a.back() == '=')
            throw std::invalid_argument("option " + o->longName() + " needs a value (" + o->value + ") after '='");
        if (a.find('=') != std::string::npos || i + 1 >= argv.size()) continue;
        const std::string& next = argv[i + 1];
        if (next == "--help" || next == "-h" || (looksLikeOption(next) && command.option(optionName(next))))
            throw std::invalid_argument("option " + o->longName() + " needs a value (" + o->value +
                                        "), got the option '" + next + "'");
    }
}

}  // namespace

Args::Args(const std::vector<std::string>& argv, const CommandDeclaration& command) : command_(command) {
    rejectMissingValues(argv, command);
    const auto app = makeParser(command);
    try {
        app->parse(std::vector<std::string>(argv.rbegin(), argv.rend()));  // CLI11 reads from the back
    } catch (const CLI::ArgumentMismatch& e) {
        throw mismatch(argv, command, e);
    } catch (const CLI::ParseError& e) {                  // RequiresError, ExcludesError
        rejectUnknownOptions(app->remaining(), command);  // the likelier mistake: named first
        throw brokenRule(*app, command, e);
    }
    rejectUnknownOptions(app->remaining(), command);
    positional_ = app->remaining();
    for (const OptionDeclaration& o : command.options) {
        const CLI::Option* option = app->get_option(o.longName());
        if (option->count() == 0) continue;
        std::vector<std::string>& values = options_[o.longName()];
        if (o.flag()) {
            values.emplace_back();
            continue;
        }
        values = option->results();
        if (!o.choices.empty())
            for (const std::string& v : values) requireChoice(o, v);
    }
}

// Options the command does not declare are absent: render, animate and sweep share one reader.
bool Args::has(const std::string& k) const {
    const OptionDeclaration* o = command_.option(k);
    return o && options_.count(o->longName()) > 0;
}

std::string Args::get(const std::string& k, const std::string& fallback) const {
    return has(k) ? options_.at(command_.option(k)->longName()).back() : fallback;
}

std::vector<std::string> Args::all(const std::string& k) const {
    return has(k) ? options_.at(command_.option(k)->longName()) : std::vector<std::string>{};
}

const input::Range& Args::range(const std::string& k) const {
    const OptionDeclaration* o = command_.option(k);
    if (!o || !o->range) throw std::logic_error("lightcone " + command_.name + ": option " + k + " declares no range");
    return *o->range;
}

double Args::number(const std::string& k, double fallback) const {
    return has(k) ? checked(k, get(k), range(k)) : fallback;
}

int Args::integer(const std::string& k, int fallback) const {
    return has(k) ? static_cast<int>(checked(k, get(k), range(k))) : fallback;  // integer ranges fit an int
}

std::vector<double> Args::numbers(const std::string& k, std::size_t n, const input::Range* given) const {
    const input::Range& r = given ? *given : range(k);
    const std::string text = get(k);
    std::vector<double> out;
    std::size_t pos = 0;
    for (;;) {
        const std::size_t comma = text.find(',', pos);
        const std::string item = text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
        const auto v = input::parseNumber(item);
        if (!v)
            throw std::invalid_argument("option " + k + ": '" + item + "' is not a finite number (expects " +
                                        std::to_string(n) + " comma-separated numbers, got '" + text + "')");
        r.require(*v, "option " + k);
        out.push_back(*v);
        if (comma == std::string::npos) break;
        pos = comma + 1;
    }
    if (out.size() != n)
        throw std::invalid_argument("option " + k + " expects " + std::to_string(n) +
                                    " comma-separated numbers, got '" + text + "'");
    return out;
}

double parseNamedNumber(const std::string& option, const std::string& text, const input::Range& range) {
    return checked(option, text, range);
}

}  // namespace lc::cli
