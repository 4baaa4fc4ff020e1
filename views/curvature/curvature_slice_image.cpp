// SPDX-License-Identifier: BSD-3-Clause
#include "curvature_slice_image.hpp"

#include "offscreen_parts.hpp"
#include "read_back.hpp"

#include <vtkCamera.h>
#include <vtkDataSet.h>
#include <vtkDataSetMapper.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace lc::views {
namespace {

// Blue through white to red (the spacetime view's diverging map), or dark blue to yellow.
void fillCurvatureColours(vtkLookupTable* lut, bool diverging) {
    const int n = 256;
    lut->SetNumberOfTableValues(n);
    const double blue[3] = {0.0, 0.45, 0.70}, red[3] = {0.84, 0.37, 0.0};
    for (int k = 0; k < n; ++k) {
        const double s = static_cast<double>(k) / (n - 1);
        if (diverging) {
            const double d = 2 * s - 1, w = 1 - std::abs(d);
            const double* end = d < 0 ? blue : red;
            lut->SetTableValue(k, w + (1 - w) * end[0], w + (1 - w) * end[1], w + (1 - w) * end[2]);
        } else {
            lut->SetTableValue(k, 0.15 + 0.85 * s, 0.1 + 0.8 * s * s, 0.35 * (1 - s) + 0.1 * s);
        }
    }
    lut->SetNanColor(0.25, 0.25, 0.25, 1);
    lut->Build();
}

std::string captionNumber(double v) {
    std::ostringstream o;
    o.precision(4);
    o << v;
    return o.str();
}

}  // namespace

CurvatureColouring colourCurvature(vtkDataSet* field, const std::string& array, bool logMagnitude) {
    CurvatureColouring c;
    vtkDataArray* values = field->GetPointData()->GetArray(array.c_str());
    if (!values) return c;
    c.shown = vtkSmartPointer<vtkDataSet>::Take(field->NewInstance());
    c.shown->CopyStructure(field);  // the geometry only: the field's own arrays stay untouched
    vtkNew<vtkDoubleArray> coloured;
    coloured->SetName("shown");
    coloured->SetNumberOfTuples(values->GetNumberOfTuples());
    double lo = INFINITY, hi = -INFINITY;
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i) {
        double v = values->GetComponent(i, 0);
        if (logMagnitude) v = std::abs(v) > 0 ? std::log10(std::abs(v)) : NAN;
        coloured->SetValue(i, v);
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    if (!(lo <= hi)) return c;
    c.shown->GetPointData()->SetScalars(coloured);
    // Near a zero of the value log10 |value| dives without bound: show eight decades below the top.
    if (logMagnitude) lo = std::max(lo, hi - 8);
    const bool diverging = !logMagnitude && lo < 0 && hi > 0;
    if (diverging) hi = std::max(-lo, hi), lo = -hi;
    if (lo == hi) lo -= 1, hi += 1;
    c.colours = vtkSmartPointer<vtkLookupTable>::New();
    fillCurvatureColours(c.colours, diverging);
    c.colours->SetTableRange(lo, hi);
    c.title = logMagnitude ? "log10 |" + array + "|" : array;
    c.valid = true;
    return c;
}

int sliceAxis(const int dims[3]) {
    if ((dims[0] == 1) + (dims[1] == 1) + (dims[2] == 1) != 1)
        throw std::invalid_argument("--image draws a slice: exactly one axis of --dims must have one point, got " +
                                    std::to_string(dims[0]) + "," + std::to_string(dims[1]) + "," +
                                    std::to_string(dims[2]));
    return dims[0] == 1 ? 0 : dims[1] == 1 ? 1 : 2;
}

std::vector<unsigned char> curvatureSliceImage(vtkImageData* slice, const std::string& array,
                                               const CurvatureSliceStyle& style) {
    int dims[3];
    slice->GetDimensions(dims);
    const int flat = sliceAxis(dims);
    if (!slice->GetPointData()->GetArray(array.c_str()))
        throw std::invalid_argument("--image: the slice has no array '" + array + "'");
    const CurvatureColouring colouring = colourCurvature(slice, array, style.logMagnitude);
    if (!colouring.valid) throw std::invalid_argument("--image: '" + array + "' has no finite value on the slice");
    vtkNew<vtkDataSetMapper> mapper;
    mapper->SetInputData(colouring.shown);
    mapper->SetLookupTable(colouring.colours);
    mapper->UseLookupTableScalarRangeOn();
    mapper->InterpolateScalarsBeforeMappingOn();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);

    vtkSmartPointer<vtkRenderWindow> window = offscreenWindow(style.width, style.height);
    vtkRenderer* renderer = rendererOf(window);
    renderer->SetBackground(0.1, 0.1, 0.12);
    renderer->AddActor(actor);
    // The plot on the left four fifths, the colour bar on the right.
    renderer->SetViewport(0, 0.08, 0.82, 1);
    vtkNew<vtkRenderer> legend;
    legend->SetViewport(0, 0, 1, 1);
    legend->SetBackground(0.1, 0.1, 0.12);
    legend->SetLayer(0);
    renderer->SetLayer(1);
    window->SetNumberOfLayers(2);
    window->AddRenderer(legend);
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(colouring.colours);
    bar->SetTitle(colouring.title.c_str());
    bar->SetNumberOfLabels(5);
    bar->SetPosition(0.83, 0.12);
    bar->SetWidth(0.14);
    bar->SetHeight(0.8);
    bar->UnconstrainedFontSizeOn();
    bar->GetTitleTextProperty()->SetFontSize(13);
    bar->GetLabelTextProperty()->SetFontSize(14);
    legend->AddActor2D(bar);

    // Axes of the slice: the two that vary, with their range, and the fixed one.
    const char* names[3] = {"x1", "x2", "x3"};
    double b[6];
    slice->GetBounds(b);
    std::string caption;
    for (int axis = 0; axis < 3; ++axis)
        caption += std::string(axis ? ", " : "") + names[axis] +
                   (axis == flat ? " = " + captionNumber(b[2 * axis])
                                 : " from " + captionNumber(b[2 * axis]) + " to " + captionNumber(b[2 * axis + 1]));
    if (!style.caption.empty()) caption = style.caption + "; " + caption;
    vtkNew<vtkTextActor> text;
    text->SetInput(caption.c_str());
    text->SetPosition(10, 10);
    text->GetTextProperty()->SetFontSize(15);
    text->GetTextProperty()->SetColor(0.9, 0.9, 0.9);
    legend->AddActor2D(text);

    // Face-on, the first varying axis to the right and the second up, filling the viewport.
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    const int right = flat == 0 ? 1 : 0, up = flat == 2 ? 1 : 2;
    double centre[3] = {(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2};
    double eye[3] = {centre[0], centre[1], centre[2]};
    eye[flat] += flat == 1 ? -1 : 1;  // so that right x up points at the eye
    double upVector[3] = {0, 0, 0};
    upVector[up] = 1;
    camera->SetFocalPoint(centre);
    camera->SetPosition(eye);
    camera->SetViewUp(upVector);
    renderer->ResetCamera();
    const double width = b[2 * right + 1] - b[2 * right], height = b[2 * up + 1] - b[2 * up];
    const double aspect = (0.82 * style.width) / (0.92 * style.height);
    camera->SetParallelScale(0.52 * std::max(height, width / aspect));
    window->Render();
    return readBackRgb(window, style.width, style.height, "curvature slice");
}

}  // namespace lc::views
