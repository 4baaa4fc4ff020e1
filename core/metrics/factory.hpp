#pragma once
// Build a spacetime from its name and named parameters (scene files, CLI).
#include "core/spacetime.hpp"

#include <map>
#include <string>
#include <vector>

namespace lc {

struct MetricDescription {
    std::string name;
    std::vector<std::pair<std::string, double>> parameters;  // name and default value
    std::string summary;
};

const std::vector<MetricDescription>& knownMetrics();

// Throws std::invalid_argument naming the bad metric or parameter and listing what is valid.
SpacetimePtr makeSpacetime(const std::string& name, const std::map<std::string, double>& params);

}  // namespace lc
