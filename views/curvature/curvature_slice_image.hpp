#pragma once
// A slice of a curvature quantity (vtkLightconeCurvatureSource with one grid axis of one point)
// as a picture: the values coloured on the plane seen face-on, a colour bar with the quantity's
// name, the slice's extent and time as a caption. Diverging colours centred on 0 for values of
// both signs (matter: negative energy blue), sequential otherwise; log scale of the magnitude on
// request (curvature spans decades). Drawn offscreen through VTK (needs an X display), 8-bit RGB.
#include <string>
#include <vector>

class vtkImageData;

namespace lc::views {

struct CurvatureSliceStyle {
    int width = 900, height = 700;
    bool logMagnitude = false;  // colour log10 |value| instead of the value
    std::string caption;        // under the plot (e.g. the metric and its parameters)
};

// `slice`'s array `array` (its first component), row 0 on top. Throws std::invalid_argument when
// the image is not a slice (exactly one axis of one point), has no such array or no finite value.
std::vector<unsigned char> curvatureSliceImage(vtkImageData* slice, const std::string& array,
                                               const CurvatureSliceStyle& style);

}  // namespace lc::views
