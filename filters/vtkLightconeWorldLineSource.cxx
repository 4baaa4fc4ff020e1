// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeWorldLineSource.h"

#include "source_checks.hpp"

#include "core/godel/images.hpp"
#include "core/godel/proper_time_world_line.hpp"
#include "core/godel/isometry.hpp"
#include "core/sr/lorentz.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>
#include <exception>
#include <functional>
#include <stdexcept>

vtkStandardNewMacro(vtkLightconeWorldLineSource);

//------------------------------------------------------------------------------
vtkLightconeWorldLineSource::vtkLightconeWorldLineSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
int vtkLightconeWorldLineSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* out = vtkPolyData::GetData(outputVector, 0);
  if (!out)
  {
    vtkErrorMacro(<< "No output polydata.");
    return 0;
  }
  // Bounded and finite before anything is sampled (NumberOfSamples may be INT_MAX).
  std::string problem = lc::filters::CheckFinite("ProperTimeRange", this->ProperTimeRange, 2);
  if (problem.empty())
  {
    problem = lc::filters::CheckPointCount("the world line", this->NumberOfSamples + 1.0);
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    out->Initialize();
    return 0;
  }
  WorldLine line;
  try
  {
    line = this->MakeWorldLine();
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    return 1; // empty output
  }
  this->SampleWorldLine(line, out);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
vtkLightconeWorldLineSource::WorldLine vtkLightconeWorldLineSource::MakeWorldLine() const
{
  const lc::Vec4 start(
    this->StartEvent[0], this->StartEvent[1], this->StartEvent[2], this->StartEvent[3]);
  WorldLine line;
  switch (this->Mode)
  {
    case GODEL_FREE_FALL:
    {
      const double a = this->GodelA;
      const lc::godel::FreeFall ff(lc::godel::OriginGeodesic::timelike(
                                     a, this->Energy, this->K3, this->Azimuth * lc::kPi / 180.0),
        lc::godel::Isometry::movingOriginTo(a, start));
      line.Position = [ff](double tau) { return ff.position(tau); };
      line.Velocity = [ff](double tau) { return ff.velocity(tau); };
      break;
    }
    case GODEL_PROPER_TIME:
    {
      if (!this->ProperTimeLine)
      {
        throw std::invalid_argument(
          "world line: mode GodelProperTime needs a world line (SetProperTimeWorldLine)");
      }
      const auto trip = this->ProperTimeLine;
      line.Position = [trip](double tau) { return trip->position(tau); };
      line.Velocity = [trip](double tau) { return trip->velocity(tau); };
      break;
    }
    case GODEL_REST:
      line.Position = [start](double tau) { return lc::Vec4(start + lc::Vec4(tau, 0, 0, 0)); };
      line.Velocity = [](double) { return lc::Vec4(1, 0, 0, 0); };
      break;
    default:
    {
      const lc::Vec3 beta(this->Beta[0], this->Beta[1], this->Beta[2]);
      if (!(beta.squaredNorm() < 1.0))
      {
        throw std::invalid_argument("world line: |beta| must be < 1");
      }
      const double gamma = lc::sr::lorentzGamma(beta);
      const lc::Vec4 u(gamma, gamma * beta(0), gamma * beta(1), gamma * beta(2));
      line.Position = [start, u](double tau) { return lc::Vec4(start + tau * u); };
      line.Velocity = [u](double) { return u; };
      break;
    }
  }
  return line;
}

//------------------------------------------------------------------------------
void vtkLightconeWorldLineSource::SampleWorldLine(const WorldLine& line, vtkPolyData* out)
{
  const int n = this->NumberOfSamples;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> tauArr, tArr, velArr, rArr;
  tauArr->SetName("tau");
  tArr->SetName("t");
  velArr->SetName("velocity");
  velArr->SetNumberOfComponents(4);
  rArr->SetName("r");
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(n + 1);
  vtkLightconeOutputChart::Curve chart(this->OutputChart);
  for (int i = 0; i <= n; ++i)
  {
    const double tau =
      this->ProperTimeRange[0] + (this->ProperTimeRange[1] - this->ProperTimeRange[0]) * i / n;
    const lc::Vec4 x = line.Position(tau);
    const lc::Vec4 u = line.Velocity(tau);
    double p[3];
    chart.Map(x, p);
    points->InsertNextPoint(p);
    tauArr->InsertNextValue(tau);
    tArr->InsertNextValue(x(0));
    velArr->InsertNextTuple4(u(0), u(1), u(2), u(3));
    rArr->InsertNextValue(std::hypot(x(1), x(2)));
    lines->InsertCellPoint(i);
    if (i % 64 == 0)
    {
      this->UpdateProgress(static_cast<double>(i) / n);
    }
  }
  out->SetPoints(points);
  out->SetLines(lines);
  out->GetPointData()->AddArray(tauArr);
  out->GetPointData()->AddArray(tArr);
  out->GetPointData()->AddArray(velArr);
  out->GetPointData()->AddArray(rArr);
  out->GetPointData()->SetActiveScalars("tau");
}

//------------------------------------------------------------------------------
void vtkLightconeWorldLineSource::SetProperTimeWorldLine(
  std::shared_ptr<const lc::godel::ProperTimeWorldLine> line)
{
  if (line == this->ProperTimeLine)
  {
    return;
  }
  this->ProperTimeLine = std::move(line);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightconeWorldLineSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* modes[4] = { "GodelFreeFall", "GodelRest", "Minkowski", "GodelProperTime" };
  os << indent << "Mode: " << modes[this->Mode] << "\n";
  os << indent << "GodelA: " << this->GodelA << "\n";
  os << indent << "Energy: " << this->Energy << "\n";
  os << indent << "K3: " << this->K3 << "\n";
  os << indent << "Azimuth: " << this->Azimuth << "\n";
  os << indent << "StartEvent: (" << this->StartEvent[0] << ", " << this->StartEvent[1] << ", "
     << this->StartEvent[2] << ", " << this->StartEvent[3] << ")\n";
  os << indent << "Beta: (" << this->Beta[0] << ", " << this->Beta[1] << ", " << this->Beta[2]
     << ")\n";
  os << indent << "ProperTimeRange: (" << this->ProperTimeRange[0] << ", "
     << this->ProperTimeRange[1] << ")\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "OutputChart: " << vtkLightconeOutputChart::GetName(this->OutputChart) << "\n";
}
