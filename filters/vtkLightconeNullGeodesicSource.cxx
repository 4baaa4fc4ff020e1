#include "vtkLightconeNullGeodesicSource.h"

#include "core/godel/geodesic.hpp"
#include "core/godel/isometry.hpp"
#include "core/metrics/godel.hpp"

#include "core/frame.hpp"
#include "core/integrator.hpp"
#include "core/metrics/factory.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <cmath>
#include <exception>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkLightconeNullGeodesicSource);

namespace
{
constexpr double kDeg = lc::kPi / 180.0;

// Orthonormal basis (e1, e2) of the plane normal to n: e1 is the unit vector of the plane
// closest to +x (to +y when n is close to x), e2 = n x e1.
bool PlaneBasis(const double nIn[3], lc::Vec3& e1, lc::Vec3& e2, lc::Vec3& n)
{
  n = lc::Vec3(nIn[0], nIn[1], nIn[2]);
  if (!(n.norm() > 0))
  {
    return false;
  }
  n.normalize();
  const lc::Vec3 a = std::abs(n.x()) < 0.9 ? lc::Vec3::UnitX() : lc::Vec3::UnitY();
  e1 = (a - a.dot(n) * n).normalized();
  e2 = n.cross(e1);
  return true;
}
} // namespace

//------------------------------------------------------------------------------
vtkLightconeNullGeodesicSource::vtkLightconeNullGeodesicSource()
{
  this->SetNumberOfInputPorts(0);
  this->SetMetricName("godel");
  this->SetStepper("dopri5");
}

//------------------------------------------------------------------------------
vtkLightconeNullGeodesicSource::~vtkLightconeNullGeodesicSource()
{
  this->SetMetricName(nullptr);
  this->SetStepper(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightconeNullGeodesicSource::SetMetricParameter(const std::string& name, double value)
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
void vtkLightconeNullGeodesicSource::ClearMetricParameters()
{
  if (!this->MetricParameters.empty())
  {
    this->MetricParameters.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightconeNullGeodesicSource::SetSpacetime(lc::SpacetimePtr spacetime)
{
  if (this->Spacetime != spacetime)
  {
    this->Spacetime = std::move(spacetime);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightconeNullGeodesicSource::SetDirections(vtkPoints* directions)
{
  if (this->Directions != directions)
  {
    this->Directions = directions;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkPoints* vtkLightconeNullGeodesicSource::GetDirections()
{
  return this->Directions;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLightconeNullGeodesicSource::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->Directions)
  {
    mtime = std::max(mtime, this->Directions->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
int vtkLightconeNullGeodesicSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!output)
  {
    vtkErrorMacro(<< "No output polydata.");
    return 0;
  }

  // Spacetime, stepper, observer frame: the core throws on bad input.
  lc::SpacetimePtr st = this->Spacetime;
  lc::TraceOptions opt;
  lc::LocalFrame frame;
  const lc::Vec4 x0(this->Observer[0], this->Observer[1], this->Observer[2], this->Observer[3]);
  try
  {
    if (!st)
    {
      st = lc::makeSpacetime(this->MetricName ? this->MetricName : "", this->MetricParameters);
    }
    opt.stepper = lc::parseStepper(this->Stepper ? this->Stepper : "");
    frame = lc::LocalFrame::staticObserver(*st, x0);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  opt.absTol = this->Tolerance;
  opt.relTol = this->Tolerance;
  opt.maxAffine = this->MaxAffine;
  opt.maxSteps = static_cast<std::size_t>(this->MaxSteps);
  opt.initialStep = this->InitialStep;
  const auto names = st->coordinateNames();
  const bool cylindrical = names[1] == "r" && names[2] == "phi";

  // Model only what is needed: closed-form rays for the Goedel metric (axis-regular chart).
  const auto* godel = dynamic_cast<const lc::GodelCartesian*>(st.get());
  if (this->Method == CLOSED_FORM && !godel)
  {
    vtkErrorMacro(<< "closed-form rays need the 'godel' metric (got '" << st->name() << "')");
    return 0;
  }
  const bool closedForm = godel && this->Method != NUMERIC;
  const double godelA = godel ? godel->a() : 1.0;
  const lc::godel::Isometry toObserver = lc::godel::Isometry::movingToOrigin(godelA, x0);
  const lc::godel::Isometry toWorld = toObserver.inverse();
  std::array<lc::Vec3, 3> axes; // the static frame's spatial vectors, seen at the origin
  for (int i = 0; i < 3; ++i)
  {
    axes[i] = closedForm ? lc::Vec3(toObserver.pushForward(x0, frame.e[i + 1]).tail<3>()) : lc::Vec3::Unit(i);
  }

  // Initial directions in the static observer's frame.
  std::vector<lc::Vec3> dirs;
  if (this->DirectionMode == LIST)
  {
    if (this->Directions)
    {
      for (vtkIdType i = 0; i < this->Directions->GetNumberOfPoints(); ++i)
      {
        double d[3];
        this->Directions->GetPoint(i, d);
        const lc::Vec3 v(d[0], d[1], d[2]);
        if (!(v.norm() > 0))
        {
          vtkErrorMacro(<< "Direction " << i << " is the zero vector.");
          return 0;
        }
        dirs.push_back(v.normalized());
      }
    }
  }
  else
  {
    lc::Vec3 e1, e2, n;
    const double* normal = this->DirectionMode == FAN ? this->FanNormal : this->ConeAxis;
    if (!PlaneBasis(normal, e1, e2, n))
    {
      vtkErrorMacro(<< (this->DirectionMode == FAN ? "FanNormal" : "ConeAxis") << " is zero.");
      return 0;
    }
    const int count = this->NumberOfRays;
    if (this->DirectionMode == FAN)
    {
      const double span = this->FanEndAngle - this->FanStartAngle;
      const double step =
        std::abs(span) >= 360.0 ? span / count : (count > 1 ? span / (count - 1) : 0.0);
      for (int i = 0; i < count; ++i)
      {
        const double th = (this->FanStartAngle + i * step) * kDeg;
        dirs.push_back(std::cos(th) * e1 + std::sin(th) * e2);
      }
    }
    else
    {
      const double psi = this->ConeAngle * kDeg;
      for (int i = 0; i < count; ++i)
      {
        const double beta = 2.0 * lc::kPi * i / count;
        dirs.push_back(
          std::cos(psi) * n + std::sin(psi) * (std::cos(beta) * e1 + std::sin(beta) * e2));
      }
    }
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  auto makeArray = [](const char* name) {
    vtkSmartPointer<vtkDoubleArray> a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name);
    return a;
  };
  auto tArr = makeArray("t");
  auto lArr = makeArray("affine");
  auto rArr = makeArray("r");
  auto srArr = makeArray("signed_r");
  auto phiArr = makeArray("phi");
  auto zArr = makeArray("z");
  auto hArr = makeArray("hamiltonian_drift");
  vtkNew<vtkIntArray> wArr;
  wArr->SetName("winding");
  vtkNew<vtkIntArray> reasonArr;
  reasonArr->SetName("stop_reason");
  vtkNew<vtkStringArray> reasonNameArr;
  reasonNameArr->SetName("stop_reason_name");
  vtkNew<vtkIntArray> stepsArr;
  stepsArr->SetName("steps");
  auto psiArr = makeArray("psi");
  auto phi0Arr = makeArray("phi0");

  const double axisTol = this->AxisTolerance;
  const int samples = this->SamplesPerStep;
  const bool rphit = this->OutputChart == RPHIT;
  const double twoPi = 2.0 * lc::kPi;

  // (X, Y) of the spatial embedding and the rate of X^2 + Y^2 (up to a factor 2).
  auto planar = [&](const lc::Vec4& x, double& X, double& Y) {
    if (cylindrical)
    {
      X = x(1) * std::cos(x(2));
      Y = x(1) * std::sin(x(2));
    }
    else
    {
      X = x(1);
      Y = x(2);
    }
  };
  auto radialRate = [&](const lc::PhasePoint& ps) {
    const lc::Vec4 v = st->inverseMetric(ps.x) * ps.p;
    return cylindrical ? ps.x(1) * v(1) : ps.x(1) * v(1) + ps.x(2) * v(2);
  };

  const std::size_t nrays = dirs.size();
  for (std::size_t ray = 0; ray < nrays && !this->GetAbortExecute(); ++ray)
  {
    const lc::Vec3& n = dirs[ray];
    const lc::PhasePoint start{ x0, frame.pastNullMomentum(*st, n) };
    vtkNew<vtkIdList> ids;
    int winding = 0;
    bool havePhiRef = false;
    double phiRef = 0.0;

    auto emit = [&](double l, const lc::PhasePoint& ps) {
      const lc::Vec4& x = ps.x;
      double X, Y;
      planar(x, X, Y);
      const double r = std::hypot(X, Y);
      double phiRaw;
      if (cylindrical)
      {
        phiRaw = x(2);
      }
      else if (r <= axisTol && !havePhiRef)
      {
        // On the axis the azimuth is that of the direction of motion (the limit along the ray).
        const lc::Vec4 v = st->inverseMetric(x) * ps.p;
        phiRaw = std::atan2(v(2), v(1));
      }
      else
      {
        phiRaw = std::atan2(Y, X);
      }
      double phi = phiRaw + lc::kPi * winding;
      if (havePhiRef)
      {
        phi += twoPi * std::nearbyint((phiRef - phi) / twoPi);
      }
      if (r > axisTol || !havePhiRef)
      {
        phiRef = phi;
        havePhiRef = true;
      }
      const double p[3] = { rphit ? r : X, rphit ? phi : Y, rphit ? x(0) : x(3) };
      ids->InsertNextId(points->InsertNextPoint(p));
      tArr->InsertNextValue(x(0));
      lArr->InsertNextValue(l);
      rArr->InsertNextValue(r);
      srArr->InsertNextValue(winding % 2 ? -r : r);
      phiArr->InsertNextValue(phi);
      zArr->InsertNextValue(x(3));
      wArr->InsertNextValue(winding);
      hArr->InsertNextValue(st->hamiltonian(x, ps.p));
    };

    emit(0.0, start);
    const lc::SegmentVisitor visitor = [&](const lc::Segment& seg) {
      // Closest approach to the axis inside this step: d(X^2+Y^2)/dl goes from < 0 to >= 0.
      double lCross = std::numeric_limits<double>::infinity();
      if (seg.at && radialRate(seg.s0) < 0 && radialRate(seg.s1) >= 0)
      {
        double lo = seg.l0, hi = seg.l1;
        for (int it = 0; it < 80 && hi - lo > 0; ++it)
        {
          const double mid = 0.5 * (lo + hi);
          if (mid <= lo || mid >= hi)
          {
            break;
          }
          (radialRate(seg.at(mid)) < 0 ? lo : hi) = mid;
        }
        double X, Y;
        planar(seg.at(0.5 * (lo + hi)).x, X, Y);
        if (std::hypot(X, Y) < axisTol)
        {
          lCross = 0.5 * (lo + hi);
        }
      }
      const int nsamp = seg.at ? samples : 1;
      bool crossed = false;
      for (int k = 1; k <= nsamp; ++k)
      {
        const double l = k == nsamp ? seg.l1 : seg.l0 + (seg.l1 - seg.l0) * k / nsamp;
        if (!crossed && l > lCross)
        {
          ++winding;
          crossed = true;
        }
        emit(l, k == nsamp ? seg.s1 : seg.at(l));
      }
      if (!crossed && lCross < std::numeric_limits<double>::infinity())
      {
        ++winding; // the minimum sits exactly at the step's end
      }
      return this->GetAbortExecute() != 0;
    };

    lc::TraceResult result;
    if (closedForm)
    {
      // Goedel: the ray in closed form in the observer's chart (observer at the origin),
      // carried to the world chart by the isometry; no ODE. Winding = returns to the
      // observer's axis, w l / pi.
      const lc::Vec3 d = (n(0) * axes[0] + n(1) * axes[1] + n(2) * axes[2]).normalized();
      const auto cf = lc::godel::OriginGeodesic::nullFromDirection(
        godelA, d(2), std::hypot(d(0), d(1)), std::atan2(d(1), d(0)), -1);
      const int count = std::max(2, samples * static_cast<int>(std::ceil(this->MaxAffine / (0.05 * godelA))));
      for (int k = 1; k <= count; ++k)
      {
        const double l = this->MaxAffine * k / count;
        const lc::Vec4 xl = cf.cartesian(l);
        winding = static_cast<int>(std::floor(cf.omega() * l / lc::kPi));
        emit(l, lc::PhasePoint{ toWorld.apply(xl), toWorld.pushForwardCovector(xl, cf.momentumCartesian(l)) });
      }
      result.reason = lc::StopReason::MaxAffine;
      result.steps = static_cast<std::size_t>(count / samples); // intervals of 0.05 a
    }
    else
    {
      try
      {
        result = lc::traceGeodesic(*st, start, opt, visitor);
      }
      catch (const std::exception& e)
      {
        vtkErrorMacro(<< "ray " << ray << ": " << e.what());
        return 0;
      }
    }
    lines->InsertNextCell(ids);
    reasonArr->InsertNextValue(static_cast<int>(result.reason));
    reasonNameArr->InsertNextValue(lc::stopReasonName(result.reason));
    stepsArr->InsertNextValue(static_cast<int>(result.steps));
    psiArr->InsertNextValue(std::acos(std::max(-1.0, std::min(1.0, n.z()))));
    phi0Arr->InsertNextValue(std::atan2(n.y(), n.x()));
    this->UpdateProgress(static_cast<double>(ray + 1) / static_cast<double>(nrays));
  }

  output->SetPoints(points);
  output->SetLines(lines);
  vtkPointData* pd = output->GetPointData();
  pd->AddArray(tArr);
  pd->AddArray(lArr);
  pd->AddArray(rArr);
  pd->AddArray(srArr);
  pd->AddArray(phiArr);
  pd->AddArray(zArr);
  pd->AddArray(wArr);
  pd->AddArray(hArr);
  pd->SetActiveScalars("t");
  vtkCellData* cd = output->GetCellData();
  cd->AddArray(reasonArr);
  cd->AddArray(reasonNameArr);
  cd->AddArray(stepsArr);
  cd->AddArray(psiArr);
  cd->AddArray(phi0Arr);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightconeNullGeodesicSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Observer: (" << this->Observer[0] << ", " << this->Observer[1] << ", "
     << this->Observer[2] << ", " << this->Observer[3] << ")\n";
  os << indent << "MetricName: " << (this->MetricName ? this->MetricName : "(none)") << "\n";
  os << indent << "MetricParameters:";
  for (const auto& kv : this->MetricParameters)
  {
    os << " " << kv.first << "=" << kv.second;
  }
  os << "\n";
  os << indent << "Spacetime: " << (this->Spacetime ? this->Spacetime->name() : "(none)") << "\n";
  os << indent << "DirectionMode: "
     << (this->DirectionMode == FAN ? "Fan" : this->DirectionMode == CONE ? "Cone" : "List")
     << "\n";
  os << indent << "NumberOfRays: " << this->NumberOfRays << "\n";
  os << indent << "FanNormal: (" << this->FanNormal[0] << ", " << this->FanNormal[1] << ", "
     << this->FanNormal[2] << ")\n";
  os << indent << "FanStartAngle: " << this->FanStartAngle << "\n";
  os << indent << "FanEndAngle: " << this->FanEndAngle << "\n";
  os << indent << "ConeAxis: (" << this->ConeAxis[0] << ", " << this->ConeAxis[1] << ", "
     << this->ConeAxis[2] << ")\n";
  os << indent << "ConeAngle: " << this->ConeAngle << "\n";
  os << indent << "Directions: " << this->Directions.GetPointer() << "\n";
  os << indent << "Stepper: " << (this->Stepper ? this->Stepper : "(none)") << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaxAffine: " << this->MaxAffine << "\n";
  os << indent << "MaxSteps: " << this->MaxSteps << "\n";
  os << indent << "InitialStep: " << this->InitialStep << "\n";
  os << indent << "SamplesPerStep: " << this->SamplesPerStep << "\n";
  os << indent << "AxisTolerance: " << this->AxisTolerance << "\n";
  os << indent << "Method: " << (this->Method == AUTO ? "Auto" : this->Method == NUMERIC ? "Numeric" : "ClosedForm") << "\n";
  os << indent << "OutputChart: " << (this->OutputChart == EMBEDDING ? "Embedding" : "RPhiT")
     << "\n";
}
