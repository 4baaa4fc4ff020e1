// SPDX-License-Identifier: BSD-3-Clause
#include "core/metrics/factory.hpp"

#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"

#include "core/input/ranges.hpp"

#include <algorithm>
#include <stdexcept>

namespace lc {

const std::vector<MetricDescription>& knownMetrics() {
    static const MetricParameter mass{"M", 1.0, 1e-6, 1e6, "mass; lengths are in units of M"};
    static const std::string spin = "and a^2 + Q^2 <= M^2 (no naked singularity)";
    static const MetricParameter godelA{"a", 1.0, 1e-3, 1e6, "the horizon of an observer lies at r = 2a"};
    static const std::vector<MetricDescription> list{
        {"minkowski", {}, "flat spacetime, Cartesian"},
        {"schwarzschild", {mass}, "outgoing Kerr-Schild Cartesian"},
        {"kerr", {mass, {"a", 0.9, -1e6, 1e6, spin}}, "outgoing Kerr-Schild Cartesian, spin along +z"},
        {"kerr-newman",
         {mass, {"a", 0.5, -1e6, 1e6, spin}, {"Q", 0.5, -1e6, 1e6, spin}},
         "outgoing Kerr-Schild Cartesian"},
        {"alcubierre",
         {{"v", 1.1, -100, 100, "bubble speed in units of c; superluminal allowed"},
          {"R", 1.0, 1e-3, 1e6, "bubble radius"},
          {"sigma", 35.0, 1e-3, 1e3, "wall sharpness; tanh(sigma R) must stay resolvable"}},
         "warp bubble along +x (seed 002)"},
        {"godel", {godelA}, "Goedel, axis-regular chart (t, x=r cos phi, y=r sin phi, z)"},
        {"godel-cylindrical", {godelA}, "Goedel, chart (t, r, phi, z) of Kajari et al."},
    };
    return list;
}

std::string metricParametersMarkdown() {
    std::string md = "| metric | parameter | default | accepted | why |\n|---|---|---|---|---|\n";
    for (const auto& m : knownMetrics())
        for (const auto& p : m.parameters)
            md += "| " + m.name + " | " + p.name + " | " + input::formatBound(p.fallback) + " | [" +
                  input::formatBound(p.min) + ", " + input::formatBound(p.max) + "] | " + p.why + " |\n";
    return md;
}

std::map<std::string, double> checkedParameterValues(const std::string& metric,
                                                     const std::vector<MetricParameter>& parameters,
                                                     const std::map<std::string, double>& given) {
    std::map<std::string, double> p;
    for (const auto& q : parameters) p[q.name] = q.fallback;
    for (const auto& [k, v] : given) {
        const auto q = std::find_if(parameters.begin(), parameters.end(),
                                    [&k = k](const MetricParameter& d) { return d.name == k; });
        if (q == parameters.end()) {
            std::string names;
            for (const auto& d : parameters) names += (names.empty() ? "" : ", ") + d.name;
            throw ParameterError(k, "metric '" + metric + "' has no parameter '" + k +
                                        "' (it takes: " + (names.empty() ? "none" : names) + ")");
        }
        const input::Range range = q->range();
        if (!range.contains(v))
            throw ParameterError(k, "metric '" + metric + "' parameter '" + k + "': " + range.problem(v));
        p[k] = v;
    }
    return p;
}

SpacetimePtr makeSpacetime(const std::string& name, const std::map<std::string, double>& given) {
    const MetricDescription* desc = nullptr;
    for (const auto& d : knownMetrics())
        if (d.name == name) desc = &d;
    if (!desc) {
        std::string names;
        for (const auto& d : knownMetrics()) names += (names.empty() ? "" : ", ") + d.name;
        throw std::invalid_argument("unknown metric '" + name + "' (expected one of: " + names + ")");
    }
    std::map<std::string, double> p = checkedParameterValues(name, desc->parameters, given);
    if (name == "minkowski") return std::make_shared<Minkowski>();
    if (name == "schwarzschild") return std::make_shared<Schwarzschild>(p["M"]);
    if (name == "kerr") return std::make_shared<KerrNewman>(p["M"], p["a"], 0.0);
    if (name == "kerr-newman") return std::make_shared<KerrNewman>(p["M"], p["a"], p["Q"]);
    if (name == "alcubierre") return std::make_shared<Alcubierre>(p["v"], p["R"], p["sigma"]);
    if (name == "godel") return std::make_shared<GodelCartesian>(p["a"]);
    return std::make_shared<GodelCylindrical>(p["a"]);
}

}  // namespace lc
