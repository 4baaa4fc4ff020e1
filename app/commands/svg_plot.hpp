#pragma once
// Line plots of table columns as one SVG file (lightcone sweep --plot): one panel per column
// against the swept value, axes with round ticks. Written by hand because it is a few lines of
// text and must work offscreen without an X server (VTK's chart export needs an OpenGL context).
#include <string>
#include <utility>
#include <vector>

namespace lc::cli {

struct PlotColumn {
    std::string name;
    std::vector<double> values;  // NaN: no value at that row (drawn as a gap)
};

std::string svgPlots(const std::string& xName, const std::vector<double>& x, const std::vector<PlotColumn>& columns);

}  // namespace lc::cli
