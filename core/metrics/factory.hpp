// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Build a spacetime from its name and named parameters (scene files, CLI).
#include "core/input/ranges.hpp"
#include "core/spacetime/spacetime.hpp"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace lc {

// One parameter of a metric: its default and the range a scene or the command line may set.
struct MetricParameter {
    std::string name;
    double fallback;
    double min, max;
    std::string why;  // reason for the range, for docs/SCENES.md
    input::Range range() const { return {name.c_str(), min, max, false, "", why.c_str()}; }
};

struct MetricDescription {
    std::string name;
    std::vector<MetricParameter> parameters;
    std::string summary;
};

// A parameter value a metric refuses (unknown name, or outside its range): which one, and why.
class ParameterError : public std::invalid_argument {
public:
    ParameterError(std::string parameterName, const std::string& message)
        : std::invalid_argument(message), parameter(std::move(parameterName)) {}
    std::string parameter;
};

// Every parameter of `metric` at its default, then the values given, each checked: a name the
// metric has and a value inside its range. Throws ParameterError naming the metric and the
// parameter, and listing what the metric takes. Built-in and typed metrics alike.
std::map<std::string, double> checkedParameterValues(const std::string& metric,
                                                     const std::vector<MetricParameter>& parameters,
                                                     const std::map<std::string, double>& given);

const std::vector<MetricDescription>& knownMetrics();
// Their parameters' ranges as Markdown rows (| metric | parameter | default | accepted | why |),
// as docs/SCENES.md shows them.
std::string metricParametersMarkdown();

// Throws std::invalid_argument naming the bad metric or parameter (unknown, or outside its
// range, which the message gives) and listing what is valid.
SpacetimePtr makeSpacetime(const std::string& name, const std::map<std::string, double>& params);

}  // namespace lc
