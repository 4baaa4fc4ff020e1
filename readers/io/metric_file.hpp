// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Metrics written as formulas (docs/METRICS.md), in a scene's "metric" block or a file of their
// own: the JSON side of lc::formula. Errors name the file, the line of the field and, inside a
// formula, the column with a caret.
#include "core/formula/formula_metric.hpp"
#include "readers/io/json_document.hpp"

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lc::io {

// Whether a scene's "metric" block names a formula ("formula" inline or "file") rather than a
// built-in metric by "name".
bool isFormulaMetricBlock(const JsonNode& metric);

// A scene's "metric": {"formula": {...}, <parameter>: value, ...} or {"file": "kerr.json", ...};
// the file is relative to baseDir. Throws InputError.
std::shared_ptr<const formula::FormulaMetric> readFormulaMetric(const JsonNode& metric, const std::string& baseDir);

// A metric file alone (lightcone metric check, Python): its parameters from `values`.
// The catalogue's metric files (`lightcone metric list`, Python's metrics()): the .json files of
// each folder of the data search path for metric files (io/install_layout), sorted, each file
// name once (the first found, as a metric given by name is); scenes (documents with a "metric"
// block) left out, files that do not parse kept, for their reader to say why.
std::vector<std::filesystem::path> catalogueFiles();

std::shared_ptr<const formula::FormulaMetric> loadFormulaMetric(const std::string& file,
                                                                const std::map<std::string, double>& values);
// The same from text (Python's Metric.from_formula); `name` labels messages.
std::shared_ptr<const formula::FormulaMetric> parseFormulaMetric(const std::string& json, const std::string& name,
                                                                 const std::map<std::string, double>& values);

}  // namespace lc::io
