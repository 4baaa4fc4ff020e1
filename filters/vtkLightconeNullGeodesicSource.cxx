// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeNullGeodesicSource.h"

#include "source_checks.hpp"

#include "core/godel/geodesic.hpp"
#include "core/godel/isometry.hpp"
#include "core/metrics/godel.hpp"

#include "core/spacetime/frame.hpp"
#include "core/spacetime/integrator.hpp"
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

#include <array>
#include <cmath>
#include <exception>
#include <functional>
#include <memory>
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
// The source's output, one polyline per ray: points in the chosen chart and the arrays the
// header documents. Keeps each ray's azimuth continuous across the axis and counts its windings
// (closest approaches to the axis closer than the tolerance).
class RayPolylines
{
public:
  RayPolylines(const lc::Spacetime& st, bool cylindrical, int chart, double axisTolerance)
    : St(st)
    , Cylindrical(cylindrical)
    , Chart(chart)
    , AxisTolerance(axisTolerance)
  {
    this->Points->SetDataTypeToDouble();
    this->T->SetName("t");
    this->Affine->SetName("affine");
    this->R->SetName("r");
    this->SignedR->SetName("signed_r");
    this->Phi->SetName("phi");
    this->Z->SetName("z");
    this->Drift->SetName("hamiltonian_drift");
    this->WindingArray->SetName("winding");
    this->Reason->SetName("stop_reason");
    this->ReasonName->SetName("stop_reason_name");
    this->Steps->SetName("steps");
    this->Psi->SetName("psi");
    this->Phi0->SetName("phi0");
  }

  void BeginRay(const lc::PhasePoint& start)
  {
    this->Ids = vtkSmartPointer<vtkIdList>::New();
    this->Winding = 0;
    this->HavePhiRef = false;
    this->PhiRef = 0.0;
    this->Emit(0.0, start);
  }

  void SetWinding(int winding) { this->Winding = winding; }

  // One point of the current ray at affine parameter l.
  void Emit(double l, const lc::PhasePoint& ps)
  {
    const lc::Vec4& x = ps.x;
    double X, Y;
    this->Planar(x, X, Y);
    const double r = std::hypot(X, Y);
    double phiRaw;
    if (this->Cylindrical)
    {
      phiRaw = x(2);
    }
    else if (r <= this->AxisTolerance && !this->HavePhiRef)
    {
      // On the axis the azimuth is that of the direction of motion (the limit along the ray).
      const lc::Vec4 v = this->St.inverseMetric(x) * ps.p;
      phiRaw = std::atan2(v(2), v(1));
    }
    else
    {
      phiRaw = std::atan2(Y, X);
    }
    const double twoPi = 2.0 * lc::kPi;
    double phi = phiRaw + lc::kPi * this->Winding;
    if (this->HavePhiRef)
    {
      phi += twoPi * std::nearbyint((this->PhiRef - phi) / twoPi);
    }
    if (r > this->AxisTolerance || !this->HavePhiRef)
    {
      this->PhiRef = phi;
      this->HavePhiRef = true;
    }
    // The shared charts; phi here is this ray's own continuous azimuth (windings included).
    const bool rphit = this->Chart == vtkLightconeOutputChart::RPHIT;
    const double p[3] = { rphit ? r : X, rphit ? phi : Y,
      this->Chart == vtkLightconeOutputChart::EMBEDDING ? x(3) : x(0) };
    this->Ids->InsertNextId(this->Points->InsertNextPoint(p));
    this->T->InsertNextValue(x(0));
    this->Affine->InsertNextValue(l);
    this->R->InsertNextValue(r);
    this->SignedR->InsertNextValue(this->Winding % 2 ? -r : r);
    this->Phi->InsertNextValue(phi);
    this->Z->InsertNextValue(x(3));
    this->WindingArray->InsertNextValue(this->Winding);
    this->Drift->InsertNextValue(this->St.hamiltonian(x, ps.p));
  }

  // The numeric tracer's visitor: samplesPerStep points per accepted step from its dense output,
  // a winding counted where the step passes its closest approach to the axis.
  lc::SegmentVisitor Visitor(int samplesPerStep, std::function<bool()> abort)
  {
    return [this, samplesPerStep, abort](const lc::Segment& seg) {
      const double lCross = this->AxisPassage(seg);
      const int nsamp = seg.at ? samplesPerStep : 1;
      bool crossed = false;
      for (int k = 1; k <= nsamp; ++k)
      {
        const double l = k == nsamp ? seg.l1 : seg.l0 + (seg.l1 - seg.l0) * k / nsamp;
        if (!crossed && l > lCross)
        {
          ++this->Winding;
          crossed = true;
        }
        this->Emit(l, k == nsamp ? seg.s1 : seg.at(l));
      }
      if (!crossed && lCross < std::numeric_limits<double>::infinity())
      {
        ++this->Winding; // the minimum sits exactly at the step's end
      }
      // More points than a source may make: the ray stops here and RequestData refuses.
      return abort() || this->TooManyPoints();
    };
  }

  bool TooManyPoints() const
  {
    return static_cast<double>(this->Points->GetNumberOfPoints()) > lc::filters::kMaxSourcePoints;
  }

  void EndRay(const lc::TraceResult& result, const lc::Vec3& direction)
  {
    this->Lines->InsertNextCell(this->Ids);
    this->Reason->InsertNextValue(static_cast<int>(result.reason));
    this->ReasonName->InsertNextValue(lc::stopReasonName(result.reason));
    this->Steps->InsertNextValue(static_cast<int>(result.steps));
    this->Psi->InsertNextValue(std::acos(std::max(-1.0, std::min(1.0, direction.z()))));
    this->Phi0->InsertNextValue(std::atan2(direction.y(), direction.x()));
  }

  void MoveInto(vtkPolyData* output)
  {
    output->SetPoints(this->Points);
    output->SetLines(this->Lines);
    vtkPointData* pd = output->GetPointData();
    for (vtkAbstractArray* a : std::initializer_list<vtkAbstractArray*>{ this->T, this->Affine,
           this->R, this->SignedR, this->Phi, this->Z, this->WindingArray, this->Drift })
    {
      pd->AddArray(a);
    }
    pd->SetActiveScalars("t");
    vtkCellData* cd = output->GetCellData();
    for (vtkAbstractArray* a : std::initializer_list<vtkAbstractArray*>{
           this->Reason, this->ReasonName, this->Steps, this->Psi, this->Phi0 })
    {
      cd->AddArray(a);
    }
  }

private:
  // (X, Y) of the spatial embedding.
  void Planar(const lc::Vec4& x, double& X, double& Y) const
  {
    X = this->Cylindrical ? x(1) * std::cos(x(2)) : x(1);
    Y = this->Cylindrical ? x(1) * std::sin(x(2)) : x(2);
  }
  // d(X^2 + Y^2)/dl up to a factor 2.
  double RadialRate(const lc::PhasePoint& ps) const
  {
    const lc::Vec4 v = this->St.inverseMetric(ps.x) * ps.p;
    return this->Cylindrical ? ps.x(1) * v(1) : ps.x(1) * v(1) + ps.x(2) * v(2);
  }
  // Where inside the step the ray passes its closest approach to the axis, if closer than the
  // tolerance (bisection on the radial rate); infinity otherwise.
  double AxisPassage(const lc::Segment& seg) const
  {
    if (!seg.at || !(this->RadialRate(seg.s0) < 0 && this->RadialRate(seg.s1) >= 0))
    {
      return std::numeric_limits<double>::infinity();
    }
    double lo = seg.l0, hi = seg.l1;
    for (int it = 0; it < 80 && hi - lo > 0; ++it)
    {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi)
      {
        break;
      }
      (this->RadialRate(seg.at(mid)) < 0 ? lo : hi) = mid;
    }
    double X, Y;
    this->Planar(seg.at(0.5 * (lo + hi)).x, X, Y);
    return std::hypot(X, Y) < this->AxisTolerance ? 0.5 * (lo + hi)
                                                  : std::numeric_limits<double>::infinity();
  }

  const lc::Spacetime& St;
  const bool Cylindrical;
  const int Chart;
  const double AxisTolerance;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkDoubleArray> T, Affine, R, SignedR, Phi, Z, Drift, Psi, Phi0;
  vtkNew<vtkIntArray> WindingArray, Reason, Steps;
  vtkNew<vtkStringArray> ReasonName;
  vtkSmartPointer<vtkIdList> Ids;
  int Winding = 0;
  bool HavePhiRef = false;
  double PhiRef = 0.0;
};

// Goedel rays in closed form (docs/PHYSICS.md section 2): each ray in the observer's chart
// (observer at the origin), carried to the world chart by the isometry; no ODE.
class ClosedFormRays
{
public:
  // The points of one ray to maxAffine: every 0.05 a / samplesPerStep of affine length (in double:
  // RequestData bounds it with CheckPointCount before any ray is drawn).
  static double PointsPerRay(double a, double maxAffine, int samplesPerStep)
  {
    return std::max(2.0, samplesPerStep * std::ceil(maxAffine / (0.05 * a)));
  }

  ClosedFormRays(double a, const lc::Vec4& observer, const lc::LocalFrame& frame)
    : A(a)
    , ToObserver(lc::godel::Isometry::movingToOrigin(a, observer))
    , ToWorld(ToObserver.inverse())
  {
    for (int i = 0; i < 3; ++i)
    {
      this->Axes[static_cast<std::size_t>(i)] =
        this->ToObserver.pushForward(observer, frame.e[i + 1]).tail<3>();
    }
  }

  // PointsPerRay samples up to maxAffine; the winding is the number of returns to the observer's
  // axis, omega l / pi.
  lc::TraceResult Trace(
    const lc::Vec3& n, double maxAffine, int samplesPerStep, RayPolylines& out) const
  {
    const lc::Vec3 d =
      (n(0) * this->Axes[0] + n(1) * this->Axes[1] + n(2) * this->Axes[2]).normalized();
    const auto cf = lc::godel::OriginGeodesic::nullFromDirection(
      this->A, d(2), std::hypot(d(0), d(1)), std::atan2(d(1), d(0)), -1);
    const int count = static_cast<int>(PointsPerRay(this->A, maxAffine, samplesPerStep));
    for (int k = 1; k <= count; ++k)
    {
      const double l = maxAffine * k / count;
      const lc::Vec4 xl = cf.cartesian(l);
      out.SetWinding(static_cast<int>(std::min(1e9, std::floor(cf.omega() * l / lc::kPi))));
      out.Emit(l,
        lc::PhasePoint{ this->ToWorld.apply(xl),
          this->ToWorld.pushForwardCovector(xl, cf.momentumCartesian(l)) });
    }
    lc::TraceResult result;
    result.reason = lc::StopReason::MaxAffine;
    result.steps = static_cast<std::size_t>(count / samplesPerStep); // intervals of 0.05 a
    return result;
  }

private:
  double A;
  lc::godel::Isometry ToObserver, ToWorld;
  std::array<lc::Vec3, 3> Axes; // the static frame's spatial vectors, seen at the origin
};
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
bool vtkLightconeNullGeodesicSource::InitialDirections(std::vector<lc::Vec3>& dirs)
{
  if (this->DirectionMode == LIST)
  {
    for (vtkIdType i = 0; this->Directions && i < this->Directions->GetNumberOfPoints(); ++i)
    {
      double d[3];
      this->Directions->GetPoint(i, d);
      const lc::Vec3 v(d[0], d[1], d[2]);
      if (!(v.norm() > 0) || !v.allFinite())
      {
        vtkErrorMacro(<< "Direction " << i << " is the zero vector or not finite.");
        return false;
      }
      dirs.push_back(v.normalized());
    }
    return true;
  }
  lc::Vec3 e1, e2, n;
  const double* normal = this->DirectionMode == FAN ? this->FanNormal : this->ConeAxis;
  if (!PlaneBasis(normal, e1, e2, n))
  {
    vtkErrorMacro(<< (this->DirectionMode == FAN ? "FanNormal" : "ConeAxis") << " is zero.");
    return false;
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
    return true;
  }
  const double psi = this->ConeAngle * kDeg;
  for (int i = 0; i < count; ++i)
  {
    const double beta = 2.0 * lc::kPi * i / count;
    dirs.push_back(std::cos(psi) * n + std::sin(psi) * (std::cos(beta) * e1 + std::sin(beta) * e2));
  }
  return true;
}

//------------------------------------------------------------------------------
// The affine length a drawn ray runs: MaxAffine, or with MaxAffine = 0 what fits the metric
// (infinite where the ray ends by escaping, see the header).
static double DrawnAffineLength(vtkLightconeNullGeodesicSource* self, const lc::Spacetime& st)
{
  if (self->GetMaxAffine() > 0)
  {
    return self->GetMaxAffine();
  }
  if (st.asymptoticallyFlat())
  {
    return std::numeric_limits<double>::infinity();
  }
  return 20.0 * st.godelRadius().value_or(1.0);
}

//------------------------------------------------------------------------------
// The tracer's settings for a drawn ray; throws on an unknown stepper name.
static lc::TraceOptions DrawnRayOptions(
  vtkLightconeNullGeodesicSource* self, const lc::Spacetime& st, const lc::Vec4& observer)
{
  lc::TraceOptions opt;
  opt.stepper = lc::parseStepper(self->GetStepper() ? self->GetStepper() : "");
  opt.absTol = self->GetTolerance();
  opt.relTol = self->GetTolerance();
  opt.maxAffine = DrawnAffineLength(self, st);
  // A given MaxAffine draws to it (or a horizon): a renderer stops an escaping ray early
  // because only its direction matters, but a drawn ray would end at the observer in flat
  // space. Without one, a ray of a flat-at-infinity metric is drawn until it has escaped.
  opt.escapeRadius = std::numeric_limits<double>::infinity();
  if (self->GetMaxAffine() <= 0 && st.asymptoticallyFlat())
  {
    opt.escapeRadius = self->GetEscapeRadius() > 0 ? self->GetEscapeRadius()
                                                   : std::max(20.0, 2 * observer.tail<3>().norm());
    opt.escapeAngle = self->GetEscapeAngle();
  }
  opt.maxSteps = static_cast<std::size_t>(self->GetMaxSteps());
  opt.initialStep = self->GetInitialStep();
  return opt;
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
    opt = DrawnRayOptions(this, *st, x0);
    frame = lc::LocalFrame::staticObserver(*st, x0);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }

  // Model only what is needed: closed-form rays for the Goedel metric (axis-regular chart).
  const auto* godel = dynamic_cast<const lc::GodelCartesian*>(st.get());
  if (this->Method == CLOSED_FORM && !godel)
  {
    vtkErrorMacro(<< "closed-form rays need the 'godel' metric (got '" << st->name() << "')");
    return 0;
  }
  const bool closedForm = godel && this->Method != NUMERIC;
  // Bounded before anything is allocated: the rays, and the closed form's points, whose count is
  // known ahead (a numeric ray's is not: the tracer stops at kMaxSourcePoints, see below).
  std::string problem = this->DirectionMode == LIST
    ? ""
    : lc::filters::CheckPointCount("the rays", static_cast<double>(this->NumberOfRays));
  if (problem.empty() && closedForm)
  {
    const double perRay =
      ClosedFormRays::PointsPerRay(godel->a(), opt.maxAffine, this->SamplesPerStep);
    problem = lc::filters::CheckPointCount("the rays",
      perRay *
        (this->DirectionMode == LIST && this->Directions
            ? static_cast<double>(this->Directions->GetNumberOfPoints())
            : static_cast<double>(this->NumberOfRays)));
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    output->Initialize();
    return 0;
  }
  std::vector<lc::Vec3> dirs;
  if (!this->InitialDirections(dirs))
  {
    return 0;
  }

  const auto names = st->coordinateNames();
  RayPolylines out(
    *st, names[1] == "r" && names[2] == "phi", this->OutputChart, this->AxisTolerance);
  std::unique_ptr<ClosedFormRays> godelRays;
  if (closedForm)
  {
    godelRays = std::make_unique<ClosedFormRays>(godel->a(), x0, frame);
  }
  for (std::size_t ray = 0; ray < dirs.size() && !this->GetAbortExecute(); ++ray)
  {
    const lc::Vec3& n = dirs[ray];
    const lc::PhasePoint start{ x0, frame.pastNullMomentum(*st, n) };
    out.BeginRay(start);
    lc::TraceResult result;
    if (godelRays)
    {
      result = godelRays->Trace(n, opt.maxAffine, this->SamplesPerStep, out);
    }
    else
    {
      try
      {
        result = lc::traceGeodesic(*st, start, opt,
          out.Visitor(this->SamplesPerStep, [this] { return this->GetAbortExecute() != 0; }));
      }
      catch (const std::exception& e)
      {
        vtkErrorMacro(<< "ray " << ray << ": " << e.what());
        return 0;
      }
    }
    out.EndRay(result, n);
    if (out.TooManyPoints())
    {
      vtkErrorMacro(<< "the rays would have more than " << lc::filters::kMaxSourcePoints
                    << " points (ray " << ray << " of " << dirs.size()
                    << "): fewer rays, a smaller SamplesPerStep or MaxAffine");
      output->Initialize();
      return 0;
    }
    this->UpdateProgress(static_cast<double>(ray + 1) / static_cast<double>(dirs.size()));
  }
  out.MoveInto(output);
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
     << (this->DirectionMode == FAN       ? "Fan"
            : this->DirectionMode == CONE ? "Cone"
                                          : "List")
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
  os << indent << "MaxAffine: " << this->MaxAffine
     << (this->MaxAffine > 0 ? "" : " (fits the metric)") << "\n";
  os << indent << "EscapeRadius: " << this->EscapeRadius << "\n";
  os << indent << "EscapeAngle: " << this->EscapeAngle << "\n";
  os << indent << "MaxSteps: " << this->MaxSteps << "\n";
  os << indent << "InitialStep: " << this->InitialStep << "\n";
  os << indent << "SamplesPerStep: " << this->SamplesPerStep << "\n";
  os << indent << "AxisTolerance: " << this->AxisTolerance << "\n";
  os << indent << "Method: "
     << (this->Method == AUTO         ? "Auto"
            : this->Method == NUMERIC ? "Numeric"
                                      : "ClosedForm")
     << "\n";
  os << indent << "OutputChart: " << vtkLightconeOutputChart::GetName(this->OutputChart) << "\n";
}
