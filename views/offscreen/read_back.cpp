// SPDX-License-Identifier: BSD-3-Clause
#include "read_back.hpp"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <stdexcept>

namespace lc::views {

std::vector<unsigned char> readBackRgb(vtkRenderWindow* window, int width, int height, const std::string& who) {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->ShouldRerenderOff();
    grab->Update();
    vtkImageData* image = grab->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    const int w = dims[0], h = dims[1];
    if (w != width || h != height) throw std::runtime_error(who + ": the window has the wrong size");
    const auto* src = static_cast<const unsigned char*>(image->GetScalarPointer());
    std::vector<unsigned char> rgb(3 * static_cast<std::size_t>(w) * h);
    for (int j = 0; j < h; ++j)
        std::copy_n(src + 3 * static_cast<std::size_t>(h - 1 - j) * w, 3 * static_cast<std::size_t>(w),
                    rgb.begin() + 3 * static_cast<std::ptrdiff_t>(j) * w);
    return rgb;
}

std::vector<float> toUnitFloats(const std::vector<unsigned char>& rgb) {
    std::vector<float> out(rgb.size());
    for (std::size_t k = 0; k < rgb.size(); ++k) out[k] = rgb[k] / 255.0f;
    return out;
}

}  // namespace lc::views
