// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the diagram tests check the same way in both diagrams: the plot area and the legend's
// left edge from the chart itself, and the legend entries found in the exported SVG.
#include "svg_reader.hpp"
#include "vtkLightconeGodelDiagram.h"

#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace lc::test {

inline vtkChartXY* diagramChart(vtkLightconeGodelDiagram* diagram) {
    auto* chart = vtkChartXY::SafeDownCast(diagram->GetView()->GetScene()->GetItem(0));
    if (!chart) throw std::runtime_error("the diagram's view holds no vtkChartXY");
    return chart;
}

// The chart's plot area in page pixels (VTK's y runs up from the bottom, the page's down).
inline SvgRect plotArea(vtkLightconeGodelDiagram* diagram, double pageHeight) {
    const int* p1 = diagramChart(diagram)->GetPoint1();
    const int* p2 = diagramChart(diagram)->GetPoint2();
    return {double(p1[0]), pageHeight - p2[1], double(p2[0] - p1[0]), double(p2[1] - p1[1])};
}

// The left edge of the legend's box, in pixels, as the chart laid it out.
inline double legendLeft(vtkLightconeGodelDiagram* diagram) {
    vtkChartLegend* legend = diagramChart(diagram)->GetLegend();
    const vtkRectf box = legend->GetBoundingRect(diagram->GetView()->GetContext());
    return legend->GetPointVector().GetX() + box.GetX();
}

// The SVG's texts that begin with one of the legend labels' prefixes.
inline std::vector<SvgText> legendTexts(const SvgDocument& svg, std::initializer_list<const char*> prefixes) {
    std::vector<SvgText> out;
    for (const auto& t : svg.texts)
        for (const char* p : prefixes)
            if (t.text.rfind(p, 0) == 0) {
                out.push_back(t);
                break;
            }
    return out;
}

}  // namespace lc::test
