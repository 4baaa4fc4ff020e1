// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeKillingFieldSource.h"

#include "source_checks.hpp"

#include "core/godel/isometry.hpp"
#include "core/metrics/godel.hpp"

#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <string>

vtkStandardNewMacro(vtkLightconeKillingFieldSource);

//------------------------------------------------------------------------------
vtkLightconeKillingFieldSource::vtkLightconeKillingFieldSource()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
int vtkLightconeKillingFieldSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  lc::filters::SetGridInformation(
    outputVector->GetInformationObject(0), this->Origin, this->Spacing, this->Dimensions);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightconeKillingFieldSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* out = vtkImageData::GetData(outputVector, 0);
  if (!out)
  {
    vtkErrorMacro(<< "No output image data.");
    return 0;
  }
  const std::string problem = this->ParameterProblem();
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
    this->SampleFields(out);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    out->Initialize();
    return 0;
  }
  out->GetPointData()->SetActiveVectors("combination");
  return 1;
}

//------------------------------------------------------------------------------
std::string vtkLightconeKillingFieldSource::ParameterProblem() const
{
  const double scalars[2] = { this->GodelA, this->Time };
  const int* d = this->Dimensions;
  std::string problem = lc::filters::CheckFinite("GodelA or Time", scalars, 2);
  if (problem.empty())
  {
    problem = lc::filters::CheckGrid(this->Origin, this->Spacing, d);
  }
  if (problem.empty())
  {
    problem = lc::filters::CheckPointCount("the grid", 1.0 * d[0] * d[1] * d[2]);
  }
  return problem;
}

//------------------------------------------------------------------------------
void vtkLightconeKillingFieldSource::SampleFields(vtkImageData* out)
{
  const int nx = this->Dimensions[0], ny = this->Dimensions[1], nz = this->Dimensions[2];
  const vtkIdType n = static_cast<vtkIdType>(nx) * ny * nz;
  // Per field (the five Killing vectors, then the combination): spatial part, time
  // component, sqrt|g(xi, xi)| and its sign (the causal character).
  const char* names[6] = { "xi_t", "xi_phi", "xi_z", "xi_4", "xi_5", "combination" };
  const lc::godel::KillingField fields[5] = { lc::godel::KillingField::T,
    lc::godel::KillingField::Phi, lc::godel::KillingField::Z, lc::godel::KillingField::Xi4,
    lc::godel::KillingField::Xi5 };
  std::array<vtkNew<vtkDoubleArray>, 6> vec, tc, norm, causal;
  for (int k = 0; k < 6; ++k)
  {
    const std::string base = names[k];
    vec[k]->SetName(base.c_str());
    vec[k]->SetNumberOfComponents(3);
    vec[k]->SetNumberOfTuples(n);
    tc[k]->SetName((base + "_t").c_str());
    tc[k]->SetNumberOfTuples(n);
    norm[k]->SetName((base + "_norm").c_str());
    norm[k]->SetNumberOfTuples(n);
    causal[k]->SetName((base + "_causal").c_str());
    causal[k]->SetNumberOfTuples(n);
  }
  const lc::GodelCartesian metric(this->GodelA);
  vtkIdType id = 0;
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i, ++id)
      {
        const lc::Vec4 x(this->Time, this->Origin[0] + i * this->Spacing[0],
          this->Origin[1] + j * this->Spacing[1], this->Origin[2] + k * this->Spacing[2]);
        const lc::Mat4 g = metric.metric(x);
        lc::Vec4 combo = lc::Vec4::Zero();
        for (int f = 0; f < 6; ++f)
        {
          lc::Vec4 xi = combo;
          if (f < 5)
          {
            xi = lc::godel::killingCartesian(fields[f], this->GodelA, x);
            combo += this->Coefficients[f] * xi;
          }
          const double gg = xi.dot(g * xi);
          vec[f]->SetTuple3(id, xi(1), xi(2), xi(3));
          tc[f]->SetValue(id, xi(0));
          norm[f]->SetValue(id, std::sqrt(std::abs(gg)));
          causal[f]->SetValue(id, gg > 0 ? 1.0 : (gg < 0 ? -1.0 : 0.0));
        }
      }
    }
    this->UpdateProgress(static_cast<double>(k + 1) / nz);
  }
  for (int f = 0; f < 6; ++f)
  {
    out->GetPointData()->AddArray(vec[f]);
    out->GetPointData()->AddArray(tc[f]);
    out->GetPointData()->AddArray(norm[f]);
    out->GetPointData()->AddArray(causal[f]);
  }
}

//------------------------------------------------------------------------------
void vtkLightconeKillingFieldSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GodelA: " << this->GodelA << "\n";
  os << indent << "Time: " << this->Time << "\n";
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
  os << indent << "Spacing: (" << this->Spacing[0] << ", " << this->Spacing[1] << ", "
     << this->Spacing[2] << ")\n";
  os << indent << "Dimensions: (" << this->Dimensions[0] << ", " << this->Dimensions[1] << ", "
     << this->Dimensions[2] << ")\n";
  os << indent << "Coefficients: (" << this->Coefficients[0] << ", " << this->Coefficients[1]
     << ", " << this->Coefficients[2] << ", " << this->Coefficients[3] << ", "
     << this->Coefficients[4] << ")\n";
}
