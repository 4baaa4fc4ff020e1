// SPDX-License-Identifier: BSD-3-Clause
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

// A closed curve in the observer's sky (lightcone sweep --outline): camera angles in degrees.
struct SkyCurve {
    std::string label;
    std::vector<double> polarDegrees, azimuthDegrees;  // from forward; from the camera's right towards up
};

// With curves, a first square panel draws them in the azimuthal equidistant projection about the
// camera's forward direction (distance from the centre = angle from forward, so a shadow larger
// than a hemisphere fits), coloured from the first value (blue) to the last (red).
std::string svgPlots(const std::string& xName, const std::vector<double>& x, const std::vector<PlotColumn>& columns,
                     const std::vector<SkyCurve>& curves = {});

}  // namespace lc::cli
