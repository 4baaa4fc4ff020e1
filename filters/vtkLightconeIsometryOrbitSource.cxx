// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeIsometryOrbitSource.h"

#include "source_checks.hpp"

#include "core/godel/isometry.hpp"
#include "core/metrics/godel.hpp"

#include <boost/numeric/odeint.hpp>

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

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLightconeIsometryOrbitSource);

namespace
{
using State = std::array<double, 4>;

// Samples x(s) of the orbit for the parameter values `ss` (all of one sign, sorted away from
// 0): dense-output dopri5 from s = 0.
void IntegrateOrbit(double a, const double c[5], const lc::Vec4& seed,
  const std::vector<double>& ss, double tol, std::vector<lc::Vec4>& out)
{
  namespace odeint = boost::numeric::odeint;
  const lc::godel::KillingField f[5] = { lc::godel::KillingField::T, lc::godel::KillingField::Phi,
    lc::godel::KillingField::Z, lc::godel::KillingField::Xi4, lc::godel::KillingField::Xi5 };
  auto rhs = [&](const State& x, State& dx, double) {
    const lc::Vec4 p(x[0], x[1], x[2], x[3]);
    lc::Vec4 v = lc::Vec4::Zero();
    for (int k = 0; k < 5; ++k)
    {
      if (c[k] != 0.0)
      {
        v += c[k] * lc::godel::killingCartesian(f[k], a, p);
      }
    }
    for (int m = 0; m < 4; ++m)
    {
      dx[m] = v(m);
    }
  };
  std::vector<double> times;
  times.reserve(ss.size() + 1);
  times.push_back(0.0);
  times.insert(times.end(), ss.begin(), ss.end());
  State x = { seed(0), seed(1), seed(2), seed(3) };
  std::size_t k = 0;
  auto observer = [&](const State& y, double) {
    if (k > 0)
    {
      out.emplace_back(y[0], y[1], y[2], y[3]);
    }
    ++k;
  };
  const double dt = ss.back() > 0 ? 1e-3 : -1e-3;
  auto stepper = odeint::make_dense_output(tol, tol, odeint::runge_kutta_dopri5<State>());
  odeint::integrate_times(stepper, rhs, x, times.begin(), times.end(), dt, observer);
}
} // namespace

//------------------------------------------------------------------------------
vtkLightconeIsometryOrbitSource::vtkLightconeIsometryOrbitSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkLightconeIsometryOrbitSource::~vtkLightconeIsometryOrbitSource() = default;

//------------------------------------------------------------------------------
void vtkLightconeIsometryOrbitSource::SetSeeds(vtkPoints* seeds)
{
  if (this->Seeds.GetPointer() != seeds)
  {
    this->Seeds = seeds;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkPoints* vtkLightconeIsometryOrbitSource::GetSeeds()
{
  return this->Seeds.GetPointer();
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLightconeIsometryOrbitSource::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->Seeds && this->Seeds->GetMTime() > t)
  {
    t = this->Seeds->GetMTime();
  }
  return t;
}

//------------------------------------------------------------------------------
struct vtkLightconeIsometryOrbitSource::OrbitArrays
{
  OrbitArrays();
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkDoubleArray> S, T, R, Z, Norm;
  vtkNew<vtkIntArray> Seed;
};

vtkLightconeIsometryOrbitSource::OrbitArrays::OrbitArrays()
{
  this->Points->SetDataTypeToDouble();
  this->S->SetName("s");
  this->T->SetName("t");
  this->R->SetName("r");
  this->Z->SetName("z");
  this->Norm->SetName("g_xi_xi");
  this->Seed->SetName("seed");
}

//------------------------------------------------------------------------------
int vtkLightconeIsometryOrbitSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* out = vtkPolyData::GetData(outputVector, 0);
  if (!out)
  {
    vtkErrorMacro(<< "No output polydata.");
    return 0;
  }
  const std::string problem = this->ParameterProblem();
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    out->Initialize();
    return 0;
  }
  const int ns = this->NumberOfSamples;
  std::vector<double> s(ns + 1);
  for (int i = 0; i <= ns; ++i)
  {
    s[i] = this->FlowRange[0] + (this->FlowRange[1] - this->FlowRange[0]) * i / ns;
  }
  const std::vector<lc::Vec4> seeds = this->SeedEvents();
  OrbitArrays arrays;
  try
  {
    for (std::size_t k = 0; k < seeds.size(); ++k)
    {
      this->AppendOrbit(s, this->SampleOrbit(seeds[k], s), static_cast<int>(k), arrays);
      this->UpdateProgress(static_cast<double>(k + 1) / seeds.size());
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  out->SetPoints(arrays.Points);
  out->SetLines(arrays.Lines);
  for (vtkDoubleArray* array :
    { arrays.S.Get(), arrays.T.Get(), arrays.R.Get(), arrays.Z.Get(), arrays.Norm.Get() })
  {
    out->GetPointData()->AddArray(array);
  }
  out->GetPointData()->SetActiveScalars("s");
  out->GetCellData()->AddArray(arrays.Seed);
  return 1;
}

//------------------------------------------------------------------------------
std::string vtkLightconeIsometryOrbitSource::ParameterProblem() const
{
  const double a = this->GodelA;
  const double scalars[2] = { a, this->SeedTime };
  const vtkIdType nSeeds = this->Seeds ? this->Seeds->GetNumberOfPoints() : 1;
  for (const std::string& problem : { lc::filters::CheckFinite("GodelA or SeedTime", scalars, 2),
         lc::filters::CheckFinite("Coefficients", this->Coefficients, 5),
         lc::filters::CheckFinite("FlowRange", this->FlowRange, 2),
         lc::filters::CheckPointCount(
           "the orbits", (this->NumberOfSamples + 1.0) * static_cast<double>(nSeeds)) })
  {
    if (!problem.empty())
    {
      return problem;
    }
  }
  for (vtkIdType i = 0; this->Seeds && i < this->Seeds->GetNumberOfPoints(); ++i)
  {
    double p[3];
    this->Seeds->GetPoint(i, p);
    const double event[4] = { this->SeedTime, p[0], p[1], p[2] };
    const std::string problem = lc::filters::CheckGodelEvent("a seed point", event, a);
    if (!problem.empty())
    {
      return problem + " (seed " + std::to_string(i) + ")";
    }
  }
  return "";
}

//------------------------------------------------------------------------------
std::vector<lc::Vec4> vtkLightconeIsometryOrbitSource::SeedEvents() const
{
  std::vector<lc::Vec4> seeds;
  for (vtkIdType i = 0; this->Seeds && i < this->Seeds->GetNumberOfPoints(); ++i)
  {
    double p[3];
    this->Seeds->GetPoint(i, p);
    seeds.emplace_back(this->SeedTime, p[0], p[1], p[2]);
  }
  if (seeds.empty())
  {
    seeds.emplace_back(this->SeedTime, 1.0, 0.0, 0.0);
  }
  return seeds;
}

//------------------------------------------------------------------------------
std::vector<lc::Vec4> vtkLightconeIsometryOrbitSource::SampleOrbit(
  const lc::Vec4& x0, const std::vector<double>& s) const
{
  const double* c = this->Coefficients;
  std::vector<lc::Vec4> xs(s.size());
  if (c[3] == 0.0 && c[4] == 0.0)
  {
    // xi_t, xi_phi and xi_z commute: the flow is a time shift, a rotation and a z shift.
    for (std::size_t i = 0; i < s.size(); ++i)
    {
      const double ang = c[1] * s[i], cs = std::cos(ang), sn = std::sin(ang);
      xs[i] = lc::Vec4(
        x0(0) + c[0] * s[i], cs * x0(1) - sn * x0(2), sn * x0(1) + cs * x0(2), x0(3) + c[2] * s[i]);
    }
    return xs;
  }
  // Integrated from s = 0 in each direction, samples sorted away from 0 (FlowRange may be
  // given in either order).
  std::vector<std::size_t> forward, backward;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    if (s[i] == 0.0)
    {
      xs[i] = x0;
    }
    else
    {
      (s[i] > 0.0 ? forward : backward).push_back(i);
    }
  }
  for (std::vector<std::size_t>* indices : { &forward, &backward })
  {
    if (indices->empty())
    {
      continue;
    }
    std::sort(indices->begin(), indices->end(),
      [&](std::size_t p, std::size_t q) { return std::abs(s[p]) < std::abs(s[q]); });
    std::vector<double> sorted;
    for (std::size_t i : *indices)
    {
      sorted.push_back(s[i]);
    }
    std::vector<lc::Vec4> res;
    IntegrateOrbit(this->GodelA, c, x0, sorted, this->Tolerance, res);
    for (std::size_t i = 0; i < indices->size() && i < res.size(); ++i)
    {
      xs[(*indices)[i]] = res[i];
    }
  }
  return xs;
}

//------------------------------------------------------------------------------
void vtkLightconeIsometryOrbitSource::AppendOrbit(const std::vector<double>& s,
  const std::vector<lc::Vec4>& xs, int seed, OrbitArrays& arrays) const
{
  const double a = this->GodelA;
  const lc::GodelCartesian metric(a);
  const lc::godel::KillingField f[5] = { lc::godel::KillingField::T, lc::godel::KillingField::Phi,
    lc::godel::KillingField::Z, lc::godel::KillingField::Xi4, lc::godel::KillingField::Xi5 };
  const vtkIdType first = arrays.Points->GetNumberOfPoints();
  vtkLightconeOutputChart::Curve chart(this->OutputChart);
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    const lc::Vec4& x = xs[i];
    double p[3];
    chart.Map(x, p);
    arrays.Points->InsertNextPoint(p);
    arrays.S->InsertNextValue(s[i]);
    arrays.T->InsertNextValue(x(0));
    arrays.R->InsertNextValue(std::hypot(x(1), x(2)));
    arrays.Z->InsertNextValue(x(3));
    lc::Vec4 xi = lc::Vec4::Zero();
    for (int m = 0; m < 5; ++m)
    {
      xi += this->Coefficients[m] * lc::godel::killingCartesian(f[m], a, x);
    }
    arrays.Norm->InsertNextValue(xi.dot(metric.metric(x) * xi));
  }
  arrays.Lines->InsertNextCell(static_cast<vtkIdType>(s.size()));
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    arrays.Lines->InsertCellPoint(first + static_cast<vtkIdType>(i));
  }
  arrays.Seed->InsertNextValue(seed);
}

//------------------------------------------------------------------------------
void vtkLightconeIsometryOrbitSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GodelA: " << this->GodelA << "\n";
  os << indent << "Coefficients: (" << this->Coefficients[0] << ", " << this->Coefficients[1]
     << ", " << this->Coefficients[2] << ", " << this->Coefficients[3] << ", "
     << this->Coefficients[4] << ")\n";
  os << indent << "Seeds: " << (this->Seeds ? this->Seeds->GetNumberOfPoints() : 0) << "\n";
  os << indent << "SeedTime: " << this->SeedTime << "\n";
  os << indent << "FlowRange: (" << this->FlowRange[0] << ", " << this->FlowRange[1] << ")\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "OutputChart: " << vtkLightconeOutputChart::GetName(this->OutputChart) << "\n";
}
