#include "core/metrics/factory.hpp"

#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"

#include <stdexcept>

namespace lc {

const std::vector<MetricDescription>& knownMetrics() {
    static const std::vector<MetricDescription> list{
        {"minkowski", {}, "flat spacetime, Cartesian"},
        {"schwarzschild", {{"M", 1.0}}, "outgoing Kerr-Schild Cartesian"},
        {"kerr", {{"M", 1.0}, {"a", 0.9}}, "outgoing Kerr-Schild Cartesian, spin along +z"},
        {"kerr-newman", {{"M", 1.0}, {"a", 0.5}, {"Q", 0.5}}, "outgoing Kerr-Schild Cartesian"},
        {"alcubierre", {{"v", 1.1}, {"R", 1.0}, {"sigma", 35.0}}, "warp bubble along +x (seed 002)"},
        {"godel", {{"a", 1.0}}, "Goedel, axis-regular chart (t, x=r cos phi, y=r sin phi, z)"},
        {"godel-cylindrical", {{"a", 1.0}}, "Goedel, chart (t, r, phi, z) of Kajari et al."},
    };
    return list;
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
    std::map<std::string, double> p;
    for (const auto& [k, v] : desc->parameters) p[k] = v;
    for (const auto& [k, v] : given) {
        if (!p.count(k)) {
            std::string names;
            for (const auto& [pk, pv] : desc->parameters) names += (names.empty() ? "" : ", ") + pk;
            throw std::invalid_argument("metric '" + name + "' has no parameter '" + k + "' (it takes: " +
                                        (names.empty() ? "none" : names) + ")");
        }
        p[k] = v;
    }
    if (name == "minkowski") return std::make_shared<Minkowski>();
    if (name == "schwarzschild") return std::make_shared<Schwarzschild>(p["M"]);
    if (name == "kerr") return std::make_shared<KerrNewman>(p["M"], p["a"], 0.0);
    if (name == "kerr-newman") return std::make_shared<KerrNewman>(p["M"], p["a"], p["Q"]);
    if (name == "alcubierre") return std::make_shared<Alcubierre>(p["v"], p["R"], p["sigma"]);
    if (name == "godel") return std::make_shared<GodelCartesian>(p["a"]);
    return std::make_shared<GodelCylindrical>(p["a"]);
}

}  // namespace lc
