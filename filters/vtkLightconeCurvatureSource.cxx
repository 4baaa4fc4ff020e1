// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeCurvatureSource.h"

#include "curvature_reading.hpp"

#include "source_checks.hpp"

#include "core/curvature/curvature_field.hpp"
#include "core/metrics/factory.hpp"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <exception>
#include <string>

vtkStandardNewMacro(vtkLightconeCurvatureSource);

namespace
{
// Every quantity's name, for messages.
std::string QuantityNames()
{
  std::string names;
  for (const auto& q : lc::curvatureQuantities())
  {
    names += (names.empty() ? "" : ", ") + std::string(q.name);
  }
  return names;
}

} // namespace

//------------------------------------------------------------------------------
vtkLightconeCurvatureSource::vtkLightconeCurvatureSource()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
  this->SetMetricName("schwarzschild");
}

//------------------------------------------------------------------------------
vtkLightconeCurvatureSource::~vtkLightconeCurvatureSource()
{
  this->SetMetricName(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightconeCurvatureSource::SetMetricParameter(const std::string& name, double value)
{
  auto it = this->MetricParameters.find(name);
  if (it != this->MetricParameters.end() && it->second == value)
  {
    return;
  }
  this->MetricParameters[name] = value;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightconeCurvatureSource::ClearMetricParameters()
{
  if (!this->MetricParameters.empty())
  {
    this->MetricParameters.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightconeCurvatureSource::SetSpacetime(lc::SpacetimePtr spacetime)
{
  if (this->Spacetime != spacetime)
  {
    this->Spacetime = std::move(spacetime);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightconeCurvatureSource::AddQuantity(const char* name)
{
  this->Quantities.emplace_back(name ? name : "");
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightconeCurvatureSource::RemoveAllQuantities()
{
  if (!this->Quantities.empty())
  {
    this->Quantities.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
const char* vtkLightconeCurvatureSource::GetQuantity(int i) const
{
  if (i < 0 || i >= this->GetNumberOfQuantities())
  {
    return nullptr;
  }
  return this->Quantities[static_cast<std::size_t>(i)].c_str();
}

//------------------------------------------------------------------------------
int vtkLightconeCurvatureSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  lc::filters::SetGridInformation(
    outputVector->GetInformationObject(0), this->Origin, this->Spacing, this->Dimensions);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightconeCurvatureSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* out = vtkImageData::GetData(outputVector, 0);
  if (!out)
  {
    vtkErrorMacro(<< "No output image data.");
    return 0;
  }
  std::string problem = this->ParameterProblem();
  lc::SpacetimePtr spacetime;
  if (problem.empty())
  {
    try
    {
      spacetime = this->ResolveSpacetime();
    }
    catch (const std::exception& e)
    {
      problem = e.what();
    }
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    out->Initialize();
    return 0;
  }
  const int* d = this->Dimensions;
  out->SetExtent(0, d[0] - 1, 0, d[1] - 1, 0, d[2] - 1);
  out->SetOrigin(this->Origin);
  out->SetSpacing(this->Spacing);
  try
  {
    this->SampleQuantities(*spacetime, out);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    out->Initialize();
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
std::string vtkLightconeCurvatureSource::ParameterProblem() const
{
  const double scalars[2] = { this->Time, this->CosmologicalConstant };
  const int* d = this->Dimensions;
  std::string problem = lc::filters::CheckFinite("Time or CosmologicalConstant", scalars, 2);
  if (problem.empty())
  {
    problem = lc::filters::CheckGrid(this->Origin, this->Spacing, d);
  }
  int components = 0;
  for (const std::string& name : this->Quantities)
  {
    const auto q = lc::curvatureQuantityNamed(name);
    if (!q && problem.empty())
    {
      problem = "Quantity '" + name + "' is unknown; known: " + QuantityNames();
    }
    components += q ? lc::curvatureQuantityInfo(*q).components : 0;
  }
  if (problem.empty())
  {
    // Every component is one double per point: bound the values, not just the points.
    problem = lc::filters::CheckPointCount("the grid (points x quantity components)",
      1.0 * d[0] * d[1] * d[2] * std::max(components, 1));
  }
  return problem;
}

//------------------------------------------------------------------------------
lc::SpacetimePtr vtkLightconeCurvatureSource::ResolveSpacetime() const
{
  if (this->Spacetime)
  {
    return this->Spacetime;
  }
  return lc::makeSpacetime(this->MetricName ? this->MetricName : "", this->MetricParameters);
}

//------------------------------------------------------------------------------
void vtkLightconeCurvatureSource::SampleQuantities(
  const lc::Spacetime& spacetime, vtkImageData* out)
{
  std::vector<lc::CurvatureQuantity> quantities;
  for (const std::string& name : this->Quantities)
  {
    quantities.push_back(*lc::curvatureQuantityNamed(name));
  }
  if (quantities.empty())
  {
    quantities.push_back(lc::CurvatureQuantity::Kretschmann);
  }
  lc::ChartGrid grid;
  grid.time = this->Time;
  grid.origin = lc::Vec3(this->Origin[0], this->Origin[1], this->Origin[2]);
  grid.spacing = lc::Vec3(this->Spacing[0], this->Spacing[1], this->Spacing[2]);
  grid.dimensions = { this->Dimensions[0], this->Dimensions[1], this->Dimensions[2] };
  const lc::CurvatureReading reading =
    lc::filters::CoreCurvatureReading(this->CosmologicalConstant, this->ObserverField);

  lc::CurvatureField field =
    lc::sampleCurvatureField(spacetime, grid, quantities, reading, [this](double fraction) {
      this->UpdateProgress(fraction);
      return !this->GetAbortExecute();
    });

  const auto n = static_cast<vtkIdType>(grid.points());
  for (std::size_t q = 0; q < quantities.size(); ++q)
  {
    const lc::CurvatureQuantityInfo& info = lc::curvatureQuantityInfo(quantities[q]);
    vtkNew<vtkDoubleArray> values;
    values->SetName(info.name);
    values->SetNumberOfComponents(info.components);
    values->SetNumberOfTuples(n);
    std::copy(field.values[q].begin(), field.values[q].end(), values->GetPointer(0));
    out->GetPointData()->AddArray(values);
  }
  out->GetPointData()->SetActiveScalars(lc::curvatureQuantityInfo(quantities.front()).name);

  lc::filters::AddSamplingCounts(out->GetFieldData(), field);
  vtkNew<vtkStringArray> metric;
  metric->SetName("metric");
  metric->InsertNextValue(spacetime.name());
  out->GetFieldData()->AddArray(metric);
}

//------------------------------------------------------------------------------
void vtkLightconeCurvatureSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MetricName: " << (this->MetricName ? this->MetricName : "(none)") << "\n";
  os << indent << "MetricParameters:";
  for (const auto& kv : this->MetricParameters)
  {
    os << " " << kv.first << "=" << kv.second;
  }
  os << "\n";
  os << indent << "Spacetime: " << (this->Spacetime ? this->Spacetime->name() : "(none)") << "\n";
  os << indent << "Time: " << this->Time << "\n";
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
  os << indent << "Spacing: (" << this->Spacing[0] << ", " << this->Spacing[1] << ", "
     << this->Spacing[2] << ")\n";
  os << indent << "Dimensions: (" << this->Dimensions[0] << ", " << this->Dimensions[1] << ", "
     << this->Dimensions[2] << ")\n";
  os << indent << "Quantities:";
  for (const std::string& q : this->Quantities)
  {
    os << " " << q;
  }
  os << "\n";
  os << indent << "CosmologicalConstant: " << this->CosmologicalConstant << "\n";
  os << indent << "ObserverField: " << this->ObserverField << "\n";
}
