// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A curvature quantity (vtkLightconeCurvatureSource's output) coloured for display, and a slice of
// it as a picture: the values on the plane seen face-on, a colour bar with the quantity's name, the
// slice's extent and time as a caption. Diverging colours centred on 0 for values of both signs
// (matter: negative energy blue), sequential otherwise; log scale of the magnitude on request
// (curvature spans decades). The workbench's spacetime view colours its curvature layer with the
// same colouring. Pictures are drawn offscreen through VTK (needs an X display), 8-bit RGB.
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkDataSet;
class vtkImageData;
class vtkLookupTable;

namespace lc::views {

// What is drawn of one quantity: `shown` is the field with one scalar array (the first component,
// or log10 of its magnitude over eight decades below the largest), `colours` spans its range, and
// `title` names it for a colour bar. `valid` is false when the array is missing or has no finite
// value (nothing to draw).
struct CurvatureColouring {
    vtkSmartPointer<vtkDataSet> shown;  // the field's own kind (a slice, a ray)
    vtkSmartPointer<vtkLookupTable> colours;
    std::string title;
    bool valid = false;
};
CurvatureColouring colourCurvature(vtkDataSet* field, const std::string& array, bool logMagnitude);

struct CurvatureSliceStyle {
    int width = 900, height = 700;
    bool logMagnitude = false;  // colour log10 |value| instead of the value
    std::string caption;        // under the plot (e.g. the metric and its parameters)
};

// The axis of a grid of `dims` points that has one point; throws std::invalid_argument unless
// exactly one has (`lightcone curvature --image` checks its --dims with it before the work).
int sliceAxis(const int dims[3]);

// `slice`'s array `array` (its first component), row 0 on top. Throws std::invalid_argument when
// the image is not a slice (exactly one axis of one point), has no such array or no finite value.
std::vector<unsigned char> curvatureSliceImage(vtkImageData* slice, const std::string& array,
                                               const CurvatureSliceStyle& style);

}  // namespace lc::views
