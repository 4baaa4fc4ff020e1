// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads an offscreen VTK window back as 8-bit RGB with row 0 at the top (lc::Camera's and the
// image files' convention; VTK's row 0 is the bottom). Shared by the shader renderers.
#include <string>
#include <vector>

class vtkRenderWindow;

namespace lc::views {

// Throws std::runtime_error naming `who` if the window is not width x height.
std::vector<unsigned char> readBackRgb(vtkRenderWindow* window, int width, int height, const std::string& who);

// 8-bit to [0, 1] floats.
std::vector<float> toUnitFloats(const std::vector<unsigned char>& rgb);

}  // namespace lc::views
