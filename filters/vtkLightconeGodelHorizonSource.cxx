// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeGodelHorizonSource.h"

#include "source_checks.hpp"

#include "core/godel/geodesic.hpp"
#include "core/godel/isometry.hpp"

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
#include <string>

vtkStandardNewMacro(vtkLightconeGodelHorizonSource);

//------------------------------------------------------------------------------
vtkLightconeGodelHorizonSource::vtkLightconeGodelHorizonSource()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
int vtkLightconeGodelHorizonSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* horizon = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* cone = vtkPolyData::GetData(outputVector, 1);
  if (!horizon || !cone)
  {
    vtkErrorMacro(<< "No output polydata.");
    return 0;
  }
  const std::string problem = this->ParameterProblem();
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    horizon->Initialize();
    cone->Initialize();
    return 0;
  }
  // Observer anywhere: the surfaces are built in the observer's own chart (observer at the
  // origin) and carried to the world chart by the isometry that moves the origin to the
  // observer (the r-phi-t chart stays the observer's own).
  const lc::Vec4 observer(
    this->Observer[0], this->Observer[1], this->Observer[2], this->Observer[3]);
  const lc::godel::Isometry toWorld = lc::godel::Isometry::movingOriginTo(this->GodelA, observer);
  this->BuildHorizon(toWorld, horizon);
  this->UpdateProgress(0.5);
  if (this->GenerateLightCone)
  {
    try
    {
      this->BuildLightCone(toWorld, cone);
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro(<< e.what());
      cone->Initialize();
      return 0;
    }
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
std::string vtkLightconeGodelHorizonSource::ParameterProblem() const
{
  const double a = this->GodelA;
  const double scalars[3] = { a, this->LightConeAffineLength, this->LightConeAzimuth };
  for (const std::string& problem :
    { lc::filters::CheckFinite("GodelA, LightConeAffineLength or LightConeAzimuth", scalars, 3),
      lc::filters::CheckGodelEvent("Observer", this->Observer, a),
      lc::filters::CheckFinite("ZRange", this->ZRange, 2),
      lc::filters::CheckPointCount(
        "the horizon", (this->Resolution + 1.0) * (this->HeightResolution + 1.0)),
      lc::filters::CheckPointCount("the light cone",
        (this->LightConePsiResolution + 1.0) * (this->LightConeAffineResolution + 1.0)) })
  {
    if (!problem.empty())
    {
      return problem;
    }
  }
  if (this->OutputChart == vtkLightconeOutputChart::XYT)
  {
    return "OutputChart XYT: the horizon is drawn in EMBEDDING or RPHIT";
  }
  return "";
}

//------------------------------------------------------------------------------
void vtkLightconeGodelHorizonSource::BuildHorizon(
  const lc::godel::Isometry& toWorld, vtkPolyData* horizon) const
{
  const double rG = 2.0 * this->GodelA;
  const bool rphit = this->OutputChart == RPHIT;
  const int nphi = this->Resolution;
  const int nh = this->HeightResolution;
  const int cols = rphit ? nphi + 1 : nphi; // the cylinder is closed, the plane is not
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> rArr;
  rArr->SetName("r");
  vtkNew<vtkDoubleArray> phiArr;
  phiArr->SetName("phi");
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (int j = 0; j <= nh; ++j)
  {
    const double w = this->ZRange[0] + (this->ZRange[1] - this->ZRange[0]) * j / nh;
    for (int i = 0; i < cols; ++i)
    {
      const double phi = 2.0 * lc::kPi * i / nphi;
      const double c = std::cos(phi), s = std::sin(phi);
      if (rphit)
      {
        points->InsertNextPoint(rG, phi, w);
        normals->InsertNextTuple3(1.0, 0.0, 0.0);
      }
      else
      {
        const lc::Vec4 local(0.0, rG * c, rG * s, w);
        const lc::Vec4 x = toWorld.apply(local);
        points->InsertNextPoint(x(1), x(2), x(3));
        lc::Vec3 n = toWorld.pushForward(local, lc::Vec4(0.0, c, s, 0.0)).tail<3>();
        n.normalize();
        normals->InsertNextTuple3(n(0), n(1), n(2));
      }
      rArr->InsertNextValue(rG);
      phiArr->InsertNextValue(phi);
    }
  }
  vtkNew<vtkCellArray> polys;
  for (int j = 0; j < nh; ++j)
  {
    for (int i = 0; i < nphi; ++i)
    {
      const int i1 = rphit ? i + 1 : (i + 1) % nphi;
      const vtkIdType q[4] = { j * cols + i, j * cols + i1, (j + 1) * cols + i1,
        (j + 1) * cols + i };
      polys->InsertNextCell(4, q);
    }
  }
  horizon->SetPoints(points);
  horizon->SetPolys(polys);
  horizon->GetPointData()->AddArray(rArr);
  horizon->GetPointData()->AddArray(phiArr);
  horizon->GetPointData()->SetNormals(normals);
}

//------------------------------------------------------------------------------
void vtkLightconeGodelHorizonSource::BuildLightCone(
  const lc::godel::Isometry& toWorld, vtkPolyData* cone) const
{
  // The past light cone of the origin, closed form of docs/PHYSICS.md section 2.
  const bool rphit = this->OutputChart == RPHIT;
  const int npsi = this->LightConePsiResolution;
  const int nl = this->LightConeAffineResolution;
  const double phi0 = this->LightConeAzimuth * lc::kPi / 180.0;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> tArr;
  tArr->SetName("t");
  vtkNew<vtkDoubleArray> lArr;
  lArr->SetName("affine");
  vtkNew<vtkDoubleArray> psiArr;
  psiArr->SetName("psi");
  vtkNew<vtkDoubleArray> rArr;
  rArr->SetName("r");
  vtkNew<vtkDoubleArray> phi0Arr;
  phi0Arr->SetName("phi0");
  const bool planar = this->LightConeSheet == PLANAR;
  for (int i = 0; i <= npsi; ++i)
  {
    // PSI_LAMBDA: psi in [0, pi] at azimuth phi0; PLANAR: psi = pi/2, azimuth in [0, 2 pi].
    const double psi = planar ? 0.5 * lc::kPi : lc::kPi * i / npsi;
    const double az = planar ? 2.0 * lc::kPi * i / npsi : phi0;
    const auto ray = lc::godel::OriginGeodesic::null(this->GodelA, psi, az, -1);
    for (int j = 0; j <= nl; ++j)
    {
      const double l = this->LightConeAffineLength * j / nl;
      const lc::Vec4 x = ray.cartesian(l);
      const double rho = ray.signedRadius(l);
      if (rphit)
      {
        points->InsertNextPoint(std::abs(rho), az - ray.phase(l), x(0));
      }
      else
      {
        const lc::Vec4 w = toWorld.apply(x);
        points->InsertNextPoint(w(1), w(2), planar ? w(0) : w(3));
      }
      tArr->InsertNextValue(x(0));
      lArr->InsertNextValue(l);
      psiArr->InsertNextValue(psi);
      rArr->InsertNextValue(std::abs(rho));
      phi0Arr->InsertNextValue(az);
    }
  }
  vtkNew<vtkCellArray> polys;
  const int cols = nl + 1;
  for (int i = 0; i < npsi; ++i)
  {
    for (int j = 0; j < nl; ++j)
    {
      const vtkIdType q[4] = { i * cols + j, i * cols + j + 1, (i + 1) * cols + j + 1,
        (i + 1) * cols + j };
      polys->InsertNextCell(4, q);
    }
  }
  cone->SetPoints(points);
  cone->SetPolys(polys);
  cone->GetPointData()->AddArray(tArr);
  cone->GetPointData()->AddArray(lArr);
  cone->GetPointData()->AddArray(psiArr);
  cone->GetPointData()->AddArray(rArr);
  if (planar)
  {
    cone->GetPointData()->AddArray(phi0Arr);
  }
  cone->GetPointData()->SetActiveScalars("t");
}

//------------------------------------------------------------------------------
void vtkLightconeGodelHorizonSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GodelA: " << this->GodelA << "\n";
  os << indent << "Observer: (" << this->Observer[0] << ", " << this->Observer[1] << ", "
     << this->Observer[2] << ", " << this->Observer[3] << ")\n";
  os << indent << "ZRange: (" << this->ZRange[0] << ", " << this->ZRange[1] << ")\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "HeightResolution: " << this->HeightResolution << "\n";
  os << indent << "OutputChart: " << vtkLightconeOutputChart::GetName(this->OutputChart) << "\n";
  os << indent << "GenerateLightCone: " << (this->GenerateLightCone ? "On" : "Off") << "\n";
  os << indent << "LightConePsiResolution: " << this->LightConePsiResolution << "\n";
  os << indent << "LightConeAffineResolution: " << this->LightConeAffineResolution << "\n";
  os << indent << "LightConeAffineLength: " << this->LightConeAffineLength << "\n";
  os << indent << "LightConeAzimuth: " << this->LightConeAzimuth << "\n";
  os << indent << "LightConeSheet: " << (this->LightConeSheet == PLANAR ? "Planar" : "PsiLambda")
     << "\n";
}
