// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeKerrHorizonSource.h"

#include "source_checks.hpp"

#include "core/metrics/kerr_newman.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <functional>

vtkStandardNewMacro(vtkLightconeKerrHorizonSource);

namespace
{
const char* const kSurfaceNames[] = { "outer_horizon", "inner_horizon", "ergosurface",
  "inner_ergosurface" };

// One surface r(theta) as a spheroid of the Kerr-Schild chart: rings of constant theta, the
// poles single points, quads between rings (triangles at the poles).
struct SurfaceWriter
{
  double Spin;
  int Polar, Azimuth;
  vtkPoints* Points;
  vtkCellArray* Polys;
  vtkDoubleArray* R;
  vtkDoubleArray* Theta;
  vtkIntArray* Surface;
  vtkStringArray* SurfaceName;

  void Add(int surface, const std::function<double(double)>& radius)
  {
    std::vector<std::vector<vtkIdType>> rings;
    for (int i = 0; i <= this->Polar; ++i)
    {
      const double theta = lc::kPi * i / this->Polar;
      const double r = radius(theta), rho = std::sqrt(r * r + this->Spin * this->Spin);
      const int count = (i == 0 || i == this->Polar) ? 1 : this->Azimuth;
      std::vector<vtkIdType> ring;
      for (int j = 0; j < count; ++j)
      {
        const double phi = 2 * lc::kPi * j / this->Azimuth;
        ring.push_back(this->Points->InsertNextPoint(rho * std::sin(theta) * std::cos(phi),
          rho * std::sin(theta) * std::sin(phi), r * std::cos(theta)));
        this->R->InsertNextValue(r);
        this->Theta->InsertNextValue(theta);
      }
      rings.push_back(std::move(ring));
    }
    for (int i = 0; i < this->Polar; ++i)
    {
      const auto& a = rings[static_cast<std::size_t>(i)];
      const auto& b = rings[static_cast<std::size_t>(i + 1)];
      for (int j = 0; j < this->Azimuth; ++j)
      {
        const auto at = [&](const std::vector<vtkIdType>& ring, int k) {
          return ring.size() == 1 ? ring[0] : ring[static_cast<std::size_t>(k % this->Azimuth)];
        };
        std::vector<vtkIdType> cell{ at(a, j), at(b, j), at(b, j + 1), at(a, j + 1) };
        cell.erase(std::unique(cell.begin(), cell.end()), cell.end());
        if (cell.size() > 2 && cell.front() == cell.back())
        {
          cell.pop_back();
        }
        this->Polys->InsertNextCell(static_cast<vtkIdType>(cell.size()), cell.data());
        this->Surface->InsertNextValue(surface);
        this->SurfaceName->InsertNextValue(kSurfaceNames[surface]);
      }
    }
  }
};
} // namespace

//------------------------------------------------------------------------------
vtkLightconeKerrHorizonSource::vtkLightconeKerrHorizonSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
int vtkLightconeKerrHorizonSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!output)
  {
    vtkErrorMacro(<< "No output polydata.");
    return 0;
  }
  const double hole[3] = { this->Mass, this->Spin, this->Charge };
  std::string problem = lc::filters::CheckFinite("Mass, Spin, Charge", hole, 3);
  if (problem.empty())
  {
    problem = lc::filters::CheckPointCount(
      "the surfaces", 4.0 * (this->PolarResolution + 1.0) * this->AzimuthResolution);
  }
  if (problem.empty())
  {
    try
    {
      lc::KerrNewman(this->Mass, this->Spin, this->Charge); // refuses naked singularities
    }
    catch (const std::exception& e)
    {
      problem = e.what();
    }
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    output->Initialize();
    return 0;
  }

  const double M = this->Mass, a = this->Spin, Q = this->Charge;
  // Rounding can leave an extremal hole's M^2 - a^2 - Q^2 a tiny negative number: 0 then.
  const double root = std::sqrt(std::max(0.0, M * M - a * a - Q * Q));
  const auto ergo = [M, a, Q](double theta) {
    const double c = std::cos(theta);
    return std::sqrt(std::max(0.0, M * M - Q * Q - a * a * c * c));
  };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkDoubleArray> r, theta;
  r->SetName("r");
  theta->SetName("theta");
  vtkNew<vtkIntArray> surface;
  surface->SetName("surface");
  vtkNew<vtkStringArray> surfaceName;
  surfaceName->SetName("surface_name");
  SurfaceWriter writer{ a, this->PolarResolution, this->AzimuthResolution, points, polys, r, theta,
    surface, surfaceName };
  const bool inner = this->GenerateInnerSurfaces && M - root > 0;
  if (this->GenerateHorizons)
  {
    writer.Add(OUTER_HORIZON, [&](double) { return M + root; });
    if (inner)
    {
      writer.Add(INNER_HORIZON, [&](double) { return M - root; });
    }
  }
  this->UpdateProgress(0.5);
  if (this->GenerateErgosurfaces)
  {
    writer.Add(ERGOSURFACE, [&](double th) { return M + ergo(th); });
    if (inner)
    {
      writer.Add(INNER_ERGOSURFACE, [&](double th) { return M - ergo(th); });
    }
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->AddArray(r);
  output->GetPointData()->AddArray(theta);
  output->GetCellData()->AddArray(surface);
  output->GetCellData()->AddArray(surfaceName);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightconeKerrHorizonSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mass: " << this->Mass << "\n";
  os << indent << "Spin: " << this->Spin << "\n";
  os << indent << "Charge: " << this->Charge << "\n";
  os << indent << "GenerateHorizons: " << this->GenerateHorizons << "\n";
  os << indent << "GenerateErgosurfaces: " << this->GenerateErgosurfaces << "\n";
  os << indent << "GenerateInnerSurfaces: " << this->GenerateInnerSurfaces << "\n";
  os << indent << "PolarResolution: " << this->PolarResolution << "\n";
  os << indent << "AzimuthResolution: " << this->AzimuthResolution << "\n";
}
