// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a scene field means to a person: its meaning, its unit (for an event, a velocity or a
// direction: the chart of the scene's metric, with the coordinates' names and their unit), the
// words it accepts, and the section of the user guide (docs/guide/) that explains it. The
// workbench's property tooltips and its F1 help read this one table; the ranges a number may
// take stay in core/input/ranges (the reader's), which the tooltips add.
#include "core/spacetime/spacetime.hpp"

#include <json/json.h>

#include <array>
#include <string>
#include <vector>

namespace lc::io {

// The scene's chart, as the guide and the tooltips name it.
struct ChartGuide {
    std::string metric;                                          // "kerr", or a typed metric's name
    std::array<std::string, 4> coordinates{"t", "x", "y", "z"};  // as scene positions are written
    std::string chart;                                           // "outgoing Kerr-Schild Cartesian chart"
    std::string unit;                                            // "lengths and times in units of M (G = c = 1)"
    std::string lengthUnit;                                      // "units of M"
    std::string page;                                            // the guide page of this kind of scene

    // "(t, x, y, z)"
    std::string coordinateList() const;
};

// From the scene's metric block (name, file or formula) and the spacetime read from it.
ChartGuide chartGuideOf(const Json::Value& metricBlock, const Spacetime& spacetime);
// The page for a scene whose metric is not known (the guide's index).
ChartGuide defaultChartGuide();

struct FieldGuide {
    std::string field;                 // as asked: "objects[2].centre"
    std::string meaning;               // empty: the table has no entry for this field
    std::string unit;                  // with the chart for events, velocities and directions
    std::vector<std::string> choices;  // the words the field takes, the default first where it has one
    std::string page, section;         // docs/guide/<page>, its "## section" heading

    // The tooltip: meaning, unit, choices, `accepted` (a number's range, when given), and where the
    // guide explains it (F1).
    std::string tooltip(const std::string& accepted = {}) const;
};

// Help on a scene field by its path; `meaning` empty for a field the table does not know.
FieldGuide fieldGuide(const std::string& field, const ChartGuide& chart, const Json::Value& scene);

// Every guide page (file names in docs/guide/), the index first.
const std::vector<std::string>& guidePages();

}  // namespace lc::io
