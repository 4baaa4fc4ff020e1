// SPDX-License-Identifier: BSD-3-Clause
#include "app/commands/outline_polydata.hpp"

#include "app/commands/vtk_xml_bytes.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <stdexcept>

namespace lc::cli {

std::string outlinePolyData(const std::string& field, const std::vector<OutlineCurve>& curves) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkDoubleArray> pointValue, lineValue;
    pointValue->SetName(field.c_str());
    lineValue->SetName(field.c_str());
    for (const OutlineCurve& c : curves) {
        if (c.directions.empty()) continue;
        const vtkIdType first = points->GetNumberOfPoints();
        for (const Vec3& d : c.directions) {
            points->InsertNextPoint(d(0), d(1), d(2));
            pointValue->InsertNextValue(c.value);
        }
        // Closed: the first point again at the end.
        lines->InsertNextCell(static_cast<vtkIdType>(c.directions.size() + 1));
        for (vtkIdType k = 0; k < static_cast<vtkIdType>(c.directions.size()); ++k) lines->InsertCellPoint(first + k);
        lines->InsertCellPoint(first);
        lineValue->InsertNextValue(c.value);
    }
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetLines(lines);
    data->GetPointData()->AddArray(pointValue);
    data->GetCellData()->AddArray(lineValue);
    vtkNew<vtkXMLPolyDataWriter> writer;
    return vtkXmlBytes(writer, data, "the outlines");
}

}  // namespace lc::cli
