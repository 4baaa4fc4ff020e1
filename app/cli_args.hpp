#pragma once
// Minimal "--name value" argument list; every option is declared by the command that reads it,
// so a misspelt option is an error instead of being ignored.
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace lc::cli {

class Args {
public:
    Args(int argc, char** argv, int first) {
        for (int i = first; i < argc; ++i) {
            std::string a = argv[i];
            if (a.rfind("--", 0) == 0 || (a.size() == 2 && a[0] == '-' && std::isalpha(static_cast<unsigned char>(a[1])))) {
                const auto eq = a.find('=');
                if (eq != std::string::npos) {
                    options_[a.substr(0, eq)].push_back(a.substr(eq + 1));
                } else if (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) {
                    options_[a].push_back(argv[++i]);
                } else {
                    options_[a].push_back("");
                }
            } else {
                positional_.push_back(a);
            }
        }
    }
    void allow(const std::set<std::string>& known) const {
        for (const auto& [k, v] : options_)
            if (!known.count(k)) {
                std::string list;
                for (const auto& n : known) list += " " + n;
                throw std::invalid_argument("unknown option '" + k + "' (this command takes:" + list + ")");
            }
    }
    bool has(const std::string& k) const { return options_.count(k) > 0; }
    std::string get(const std::string& k, const std::string& fallback = "") const {
        return has(k) ? options_.at(k).back() : fallback;
    }
    std::vector<std::string> all(const std::string& k) const { return has(k) ? options_.at(k) : std::vector<std::string>{}; }
    double number(const std::string& k, double fallback) const {
        if (!has(k)) return fallback;
        try {
            std::size_t used = 0;
            const double v = std::stod(get(k), &used);
            if (used != get(k).size()) throw std::invalid_argument("");
            return v;
        } catch (const std::exception&) {
            throw std::invalid_argument("option " + k + " expects a number, got '" + get(k) + "'");
        }
    }
    std::vector<double> numbers(const std::string& k, std::size_t n) const {
        std::vector<double> out;
        std::string s = get(k) + ",";
        std::size_t pos = 0, next;
        while ((next = s.find(',', pos)) != std::string::npos) {
            try {
                out.push_back(std::stod(s.substr(pos, next - pos)));
            } catch (const std::exception&) {
                throw std::invalid_argument("option " + k + " expects " + std::to_string(n) + " comma-separated numbers");
            }
            pos = next + 1;
        }
        if (out.size() != n)
            throw std::invalid_argument("option " + k + " expects " + std::to_string(n) + " comma-separated numbers, got '" + get(k) + "'");
        return out;
    }
    const std::vector<std::string>& positional() const { return positional_; }

private:
    std::map<std::string, std::vector<std::string>> options_;
    std::vector<std::string> positional_;
};

}  // namespace lc::cli
