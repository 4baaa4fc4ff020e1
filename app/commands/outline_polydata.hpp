// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The shadow outlines of lightcone sweep --outline-vtk as VTK XML polydata: one closed polyline
// per swept value on the unit sphere of viewing directions, in the camera's axes (x right, y up,
// z forward), with the swept value on each line and point, for ParaView.
#include <string>
#include <vector>

#include "core/numerics/types.hpp"

namespace lc::cli {

struct OutlineCurve {
    double value;                  // the swept field's value
    std::vector<Vec3> directions;  // unit, camera components (right, up, forward)
};

// The .vtp file's bytes (binary XML), named `field` for the swept value's array.
std::string outlinePolyData(const std::string& field, const std::vector<OutlineCurve>& curves);

}  // namespace lc::cli
