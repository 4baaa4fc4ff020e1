#include "app/cli_args.hpp"

namespace lc::cli {
namespace {

bool looksLikeOption(const std::string& a) {
    return a.rfind("--", 0) == 0 || (a.size() == 2 && a[0] == '-' && std::isalpha(static_cast<unsigned char>(a[1])));
}

std::string list(const std::set<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += " " + n;
    return s;
}

double checked(const std::string& option, const std::string& text, const input::Range& range) {
    const auto v = input::parseNumber(text);
    if (!v) throw std::invalid_argument("option " + option + " expects " + range.describe() + ", got '" + text + "'");
    range.require(*v, "option " + option);
    return *v;
}

}  // namespace

Args::Args(const std::vector<std::string>& argv, const CommandSpec& spec) {
    for (std::size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        if (!looksLikeOption(a)) {
            positional_.push_back(a);
            continue;
        }
        const auto eq = a.find('=');
        const std::string name = a.substr(0, eq);
        if (spec.flags.count(name)) {
            if (eq != std::string::npos)
                throw std::invalid_argument("option " + name + " is a flag and takes no value");
            options_[name].push_back("");
        } else if (spec.valued.count(name)) {
            if (eq != std::string::npos)
                options_[name].push_back(a.substr(eq + 1));
            else if (i + 1 < argv.size())
                options_[name].push_back(argv[++i]);
            else
                throw std::invalid_argument("option " + name + " needs a value");
        } else {
            throw std::invalid_argument("unknown option '" + name + "' (this command takes:" + list(spec.valued) +
                                        list(spec.flags) + ")");
        }
    }
}

double Args::number(const std::string& k, double fallback, const input::Range& range) const {
    return has(k) ? checked(k, get(k), range) : fallback;
}

int Args::integer(const std::string& k, int fallback, const input::Range& range) const {
    return has(k) ? static_cast<int>(checked(k, get(k), range)) : fallback;  // integer ranges fit an int
}

std::vector<double> Args::numbers(const std::string& k, std::size_t n, const input::Range& range) const {
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
        range.require(*v, "option " + k);
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
