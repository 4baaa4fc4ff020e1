// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeCurvatureAlongPath.h"

#include "curvature_reading.hpp"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <stdexcept>
#include <vector>

vtkStandardNewMacro(vtkLightconeCurvatureAlongPath);

//------------------------------------------------------------------------------
vtkLightconeCurvatureAlongPath::vtkLightconeCurvatureAlongPath()
{
  this->SetQuantity("kretschmann");
  this->SetTimeArrayName("t");
}

//------------------------------------------------------------------------------
vtkLightconeCurvatureAlongPath::~vtkLightconeCurvatureAlongPath()
{
  this->SetQuantity(nullptr);
  this->SetTimeArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightconeCurvatureAlongPath::SetSpacetime(lc::SpacetimePtr spacetime)
{
  if (spacetime != this->Spacetime)
  {
    this->Spacetime = std::move(spacetime);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkLightconeCurvatureAlongPath::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* in = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* out = vtkPolyData::GetData(outputVector, 0);
  if (!in || !out)
  {
    vtkErrorMacro(<< "No input or output polydata.");
    return 0;
  }
  const auto quantity = lc::curvatureQuantityNamed(this->Quantity ? this->Quantity : "");
  vtkDataArray* time = in->GetPointData()->GetArray(this->TimeArrayName ? this->TimeArrayName : "");
  std::string problem;
  if (!this->Spacetime)
  {
    problem = "No spacetime: SetSpacetime is required.";
  }
  else if (!quantity)
  {
    problem = std::string("Quantity '") + (this->Quantity ? this->Quantity : "") +
      "' is unknown; known: kretschmann, ricci_scalar, ... (lc::curvatureQuantities())";
  }
  else if (in->GetNumberOfPoints() > 0 && (!time || time->GetNumberOfComponents() != 1))
  {
    problem = std::string("The input has no one-component point array '") +
      (this->TimeArrayName ? this->TimeArrayName : "") + "' of chart times.";
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    out->Initialize();
    return 0;
  }
  out->ShallowCopy(in);
  const vtkIdType n = in->GetNumberOfPoints();
  std::vector<lc::Vec4> events(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    in->GetPoint(i, p);
    events[static_cast<std::size_t>(i)] = lc::Vec4(time->GetTuple1(i), p[0], p[1], p[2]);
  }
  const lc::CurvatureReading reading =
    lc::filters::CoreCurvatureReading(this->CosmologicalConstant, this->ObserverField);
  lc::CurvatureField field;
  try
  {
    field = lc::sampleCurvatureAtEvents(*this->Spacetime, events, { *quantity }, reading);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    out->Initialize();
    return 0;
  }
  const lc::CurvatureQuantityInfo& info = lc::curvatureQuantityInfo(*quantity);
  vtkNew<vtkDoubleArray> values;
  values->SetName(info.name);
  values->SetNumberOfComponents(info.components);
  values->SetNumberOfTuples(n);
  std::copy(field.values[0].begin(), field.values[0].end(), values->GetPointer(0));
  out->GetPointData()->AddArray(values);
  out->GetPointData()->SetActiveScalars(info.name);
  lc::filters::AddSamplingCounts(out->GetFieldData(), field);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightconeCurvatureAlongPath::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent
     << "Spacetime: " << (this->Spacetime ? this->Spacetime->name() : std::string("(none)"))
     << "\n";
  os << indent << "Quantity: " << (this->Quantity ? this->Quantity : "(none)") << "\n";
  os << indent << "TimeArrayName: " << (this->TimeArrayName ? this->TimeArrayName : "(none)")
     << "\n";
  os << indent << "CosmologicalConstant: " << this->CosmologicalConstant << "\n";
  os << indent << "ObserverField: " << this->ObserverField << "\n";
}
