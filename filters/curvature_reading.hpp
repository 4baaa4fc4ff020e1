// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What vtkLightconeCurvatureSource and vtkLightconeCurvatureAlongPath share of a curvature
// sampling: the core's reading by their settings (Lambda and ObserverField: AUTO 0, STATIC 1,
// NORMAL 2), and the counts it leaves as field data.
#include "core/curvature/curvature_field.hpp"

#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>

// Two namespace blocks: VTK 9.1's wrapper parser reads no nested namespace definitions.
namespace lc
{
namespace filters
{
inline CurvatureReading CoreCurvatureReading(double cosmologicalConstant, int observerField)
{
  CurvatureReading reading;
  reading.cosmologicalConstant = cosmologicalConstant;
  reading.observers = observerField == 1 ? ObserverField::Static
    : observerField == 2                 ? ObserverField::Normal
                                         : ObserverField::StaticElseNormal;
  return reading;
}

// "singular_points" and "points_without_observer", one value each.
inline void AddSamplingCounts(vtkFieldData* data, const CurvatureField& field)
{
  auto count = [data](const char* name, std::size_t value) {
    vtkNew<vtkIdTypeArray> a;
    a->SetName(name);
    a->InsertNextValue(static_cast<vtkIdType>(value));
    data->AddArray(a);
  };
  count("singular_points", field.singularPoints);
  count("points_without_observer", field.pointsWithoutObserver);
}
} // namespace filters
} // namespace lc
