// Tests of the symmetry, world-line and photo-object filters in filters/: Killing fields on a
// grid against the Killing equation (finite-difference Lie derivative of the Goedel metric),
// their orbits, free fall against the closed form of docs/PHYSICS.md section 2 (typed in here)
// moved by the isometry, Minkowski world lines, Goedel photo-objects against the inverse
// solution per vertex, the special-relativistic photo-object against a hand-derived quadratic,
// pipeline re-execution, empty input, .vtm round trip.
#include "tests/common/vtk_event_counter.hpp"
#include "vtkLightconeIsometryOrbitSource.h"
#include "vtkLightconeKillingFieldSource.h"
#include "vtkLightconePhotoObjectFilter.h"
#include "vtkLightconeWorldLineSource.h"

#include "core/godel/images.hpp"
#include "core/godel/isometry.hpp"
#include "core/metrics/godel.hpp"

#include <gtest/gtest.h>

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkCompositeDataSet.h>
#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLMultiBlockDataWriter.h>

#include <array>
#include <cmath>
#include <sstream>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kSqrt2 = 1.41421356237309504880;

using lc::testing::EventCounter;

vtkDataArray* PArray(vtkDataSet* ds, const char* name)
{
  vtkDataArray* a = ds->GetPointData()->GetArray(name);
  EXPECT_NE(a, nullptr) << "missing point array " << name;
  return a;
}

// Goedel metric in the Cartesian chart and its partial derivatives (central differences).
lc::Mat4 Metric(double a, const lc::Vec4& x)
{
  return lc::GodelCartesian(a).metric(x);
}
lc::Mat4 MetricDerivative(double a, const lc::Vec4& x, int rho)
{
  const double h = 1e-5;
  lc::Vec4 xp = x, xm = x;
  xp(rho) += h;
  xm(rho) -= h;
  return (Metric(a, xp) - Metric(a, xm)) / (2 * h);
}

// Killing field of a name read back from the grid: (t component, spatial vector).
lc::Vec4 FieldAt(vtkImageData* img, const std::string& name, vtkIdType id)
{
  vtkDataArray* v = img->GetPointData()->GetArray(name.c_str());
  vtkDataArray* t = img->GetPointData()->GetArray((name + "_t").c_str());
  EXPECT_TRUE(v && t) << name;
  if (!v || !t)
    return lc::Vec4::Zero();
  return lc::Vec4(t->GetComponent(id, 0), v->GetComponent(id, 0), v->GetComponent(id, 1),
    v->GetComponent(id, 2));
}

const char* kFieldNames[6] = { "xi_t", "xi_phi", "xi_z", "xi_4", "xi_5", "combination" };
} // namespace

// ---- Killing fields ---------------------------------------------------------------------

TEST(KillingFieldSource, FieldsSatisfyKillingEquation)
{
  const double a = 0.9, h = 1e-4, time = 0.7;
  vtkNew<vtkLightconeKillingFieldSource> src;
  src->SetGodelA(a);
  src->SetTime(time);
  src->SetDimensions(3, 3, 3);
  src->SetSpacing(h, h, h);
  src->SetCoefficients(0.3, -0.2, 0.5, 1.1, -0.7);
  // Interior points (the centre of a 3x3x3 grid), inside and beyond the Goedel radius 2a.
  const std::vector<std::array<double, 3>> centres = { { 0.0, 0.0, 0.0 }, { 0.4, -0.3, 1.0 },
    { -1.2, 0.8, -0.5 }, { 2.5, 1.5, 0.3 }, { -0.1, -3.0, 2.0 } };
  for (const auto& c : centres)
  {
    src->SetOrigin(c[0] - h, c[1] - h, c[2] - h);
    src->Update();
    vtkImageData* img = src->GetOutput();
    ASSERT_EQ(img->GetNumberOfPoints(), 27);
    const vtkIdType centre = 13; // (1, 1, 1)
    double p[3];
    img->GetPoint(centre, p);
    EXPECT_NEAR(p[0], c[0], 1e-12);
    EXPECT_NEAR(p[1], c[1], 1e-12);
    EXPECT_NEAR(p[2], c[2], 1e-12);
    const lc::Vec4 x(time, p[0], p[1], p[2]);
    const lc::Mat4 g = Metric(a, x);
    std::array<lc::Mat4, 4> dg;
    for (int r = 0; r < 4; ++r)
      dg[r] = MetricDerivative(a, x, r);
    for (const char* name : kFieldNames)
    {
      const lc::Vec4 xi = FieldAt(img, name, centre);
      // d_mu xi^rho: the fields do not depend on t (checked below by the time slice), the
      // spatial derivatives by central differences over the grid.
      lc::Mat4 dxi = lc::Mat4::Zero(); // dxi(rho, mu) = d_mu xi^rho
      const vtkIdType stride[3] = { 1, 3, 9 };
      for (int k = 0; k < 3; ++k)
      {
        const lc::Vec4 d =
          (FieldAt(img, name, centre + stride[k]) - FieldAt(img, name, centre - stride[k])) /
          (2 * h);
        dxi.col(k + 1) = d;
      }
      // (L_xi g)_{mu nu} = xi^rho d_rho g_{mu nu} + g_{rho nu} d_mu xi^rho + g_{mu rho} d_nu xi^rho
      lc::Mat4 L = lc::Mat4::Zero();
      for (int r = 0; r < 4; ++r)
        L += xi(r) * dg[r];
      L += dxi.transpose() * g + g * dxi;
      double scale = 0;
      for (int r = 0; r < 4; ++r)
        scale = std::max(scale, std::abs(xi(r)) * dg[r].cwiseAbs().maxCoeff());
      scale = std::max(scale, (g.cwiseAbs() * dxi.cwiseAbs()).maxCoeff());
      scale = std::max(scale, 1.0);
      EXPECT_LT(L.cwiseAbs().maxCoeff() / scale, 1e-6)
        << name << " at (" << c[0] << ", " << c[1] << ", " << c[2] << ")\n"
        << L;
      // The norm and causal character arrays against g(xi, xi).
      const double gg = xi.dot(g * xi);
      vtkDataArray* norm = PArray(img, (std::string(name) + "_norm").c_str());
      vtkDataArray* causal = PArray(img, (std::string(name) + "_causal").c_str());
      ASSERT_TRUE(norm && causal);
      EXPECT_NEAR(norm->GetComponent(centre, 0), std::sqrt(std::abs(gg)), 1e-12 * (1 + std::abs(gg)));
      EXPECT_EQ(causal->GetComponent(centre, 0), gg > 0 ? 1.0 : (gg < 0 ? -1.0 : 0.0)) << name;
    }
  }
  // The fields do not depend on the time slice.
  src->SetOrigin(0.3, 0.2, 0.1);
  src->Update();
  vtkSmartPointer<vtkImageData> before = vtkSmartPointer<vtkImageData>::New();
  before->DeepCopy(src->GetOutput());
  src->SetTime(time + 3.1);
  src->Update();
  for (const char* name : kFieldNames)
    for (vtkIdType id = 0; id < 27; ++id)
      EXPECT_LT((FieldAt(before, name, id) - FieldAt(src->GetOutput(), name, id)).norm(), 1e-15);
}

TEST(KillingFieldSource, TimeTranslationCombinationAndCausality)
{
  const double a = 1.0;
  vtkNew<vtkLightconeKillingFieldSource> src;
  src->SetGodelA(a);
  src->SetOrigin(-3, -3, -1);
  src->SetSpacing(0.25, 0.25, 0.5);
  src->SetDimensions(25, 25, 5);
  const double c[5] = { 0.3, -0.2, 0.5, 1.1, -0.7 };
  src->SetCoefficients(c[0], c[1], c[2], c[3], c[4]);
  src->Update();
  vtkImageData* img = src->GetOutput();
  ASSERT_EQ(img->GetNumberOfPoints(), 25 * 25 * 5);
  vtkDataArray* phiCausal = PArray(img, "xi_phi_causal");
  ASSERT_NE(phiCausal, nullptr);
  for (vtkIdType id = 0; id < img->GetNumberOfPoints(); ++id)
  {
    // d/dt exactly, unit (g_tt = 1).
    const lc::Vec4 xt = FieldAt(img, "xi_t", id);
    EXPECT_EQ(xt(0), 1.0);
    EXPECT_EQ(xt(1), 0.0);
    EXPECT_EQ(xt(2), 0.0);
    EXPECT_EQ(xt(3), 0.0);
    EXPECT_EQ(PArray(img, "xi_t_norm")->GetComponent(id, 0), 1.0);
    EXPECT_EQ(PArray(img, "xi_t_causal")->GetComponent(id, 0), 1.0);
    // The combination is the sum of the five.
    lc::Vec4 sum = lc::Vec4::Zero();
    for (int k = 0; k < 5; ++k)
      sum += c[k] * FieldAt(img, kFieldNames[k], id);
    EXPECT_LT((sum - FieldAt(img, "combination", id)).norm(), 1e-13);
    // d/dphi: -Y d/dX + X d/dY, timelike beyond r = 2a (closed timelike curves).
    double p[3];
    img->GetPoint(id, p);
    const lc::Vec4 xp = FieldAt(img, "xi_phi", id);
    EXPECT_EQ(xp(1), -p[1]);
    EXPECT_EQ(xp(2), p[0]);
    const double r = std::hypot(p[0], p[1]);
    if (std::abs(r - 2 * a) > 1e-9 && r > 0)
    {
      EXPECT_EQ(phiCausal->GetComponent(id, 0), r > 2 * a ? 1.0 : -1.0) << "r = " << r;
    }
    // xi4 at the origin is 2a d/dY (spacelike), xi5 is 2a d/dX.
    if (r == 0)
    {
      EXPECT_LT((FieldAt(img, "xi_4", id) - lc::Vec4(0, 0, 2 * a, 0)).norm(), 1e-15);
      EXPECT_LT((FieldAt(img, "xi_5", id) - lc::Vec4(0, 2 * a, 0, 0)).norm(), 1e-15);
    }
  }
}

// ---- orbits -----------------------------------------------------------------------------

TEST(IsometryOrbitSource, RotationOrbitIsACircle)
{
  vtkNew<vtkLightconeIsometryOrbitSource> src;
  src->SetGodelA(0.8);
  src->SetCoefficients(0, 1, 0, 0, 0);
  vtkNew<vtkPoints> seeds;
  seeds->SetDataTypeToDouble();
  seeds->InsertNextPoint(1.3, 0.4, 0.7);
  seeds->InsertNextPoint(-2.0, 1.0, -0.3); // beyond 2a: a closed timelike curve
  src->SetSeeds(seeds);
  src->SetSeedTime(2.0);
  src->SetFlowRange(0, 2 * kPi);
  src->SetNumberOfSamples(64);
  src->Update();
  vtkPolyData* out = src->GetOutput();
  ASSERT_EQ(out->GetNumberOfLines(), 2);
  ASSERT_EQ(out->GetNumberOfPoints(), 2 * 65);
  vtkDataArray* s = PArray(out, "s");
  vtkDataArray* t = PArray(out, "t");
  vtkDataArray* r = PArray(out, "r");
  ASSERT_TRUE(s && t && r);
  for (vtkIdType id = 0; id < out->GetNumberOfPoints(); ++id)
  {
    double seed[3], p[3];
    seeds->GetPoint(id / 65, seed);
    out->GetPoint(id, p);
    const double ang = s->GetComponent(id, 0);
    EXPECT_NEAR(ang, 2 * kPi * (id % 65) / 64, 1e-14);
    EXPECT_EQ(t->GetComponent(id, 0), 2.0);
    EXPECT_NEAR(r->GetComponent(id, 0), std::hypot(seed[0], seed[1]), 1e-14);
    EXPECT_NEAR(std::hypot(p[0], p[1]), std::hypot(seed[0], seed[1]), 1e-14);
    EXPECT_NEAR(p[0], std::cos(ang) * seed[0] - std::sin(ang) * seed[1], 1e-14);
    EXPECT_NEAR(p[1], std::sin(ang) * seed[0] + std::cos(ang) * seed[1], 1e-14);
    EXPECT_EQ(p[2], seed[2]);
  }
}

TEST(IsometryOrbitSource, Xi4OrbitKeepsNormAndFollowsField)
{
  const double a = 1.1;
  const double c[5] = { 0.0, 0.0, 0.0, 1.0, 0.0 };
  for (int combo = 0; combo < 2; ++combo)
  {
    double cc[5] = { c[0], c[1], c[2], c[3], c[4] };
    if (combo == 1)
    {
      // A general combination (elliptic/hyperbolic mixture with time and z shifts).
      const double mix[5] = { 0.4, 0.3, -0.2, 0.6, -0.5 };
      std::copy(mix, mix + 5, cc);
    }
    vtkNew<vtkLightconeIsometryOrbitSource> src;
    src->SetGodelA(a);
    src->SetCoefficients(cc);
    vtkNew<vtkPoints> seeds;
    seeds->SetDataTypeToDouble();
    seeds->InsertNextPoint(0.5, 0.3, 0.2);
    seeds->InsertNextPoint(-1.0, 2.5, 0.0);
    src->SetSeeds(seeds);
    src->SetSeedTime(-0.4);
    src->SetFlowRange(-1.5, 1.5);
    const int n = 3000;
    src->SetNumberOfSamples(n);
    src->Update();
    vtkPolyData* out = src->GetOutput();
    ASSERT_EQ(out->GetNumberOfPoints(), 2 * (n + 1));
    vtkDataArray* s = PArray(out, "s");
    vtkDataArray* t = PArray(out, "t");
    ASSERT_TRUE(s && t);
    auto event = [&](vtkIdType id) {
      double p[3];
      out->GetPoint(id, p);
      return lc::Vec4(t->GetComponent(id, 0), p[0], p[1], p[2]);
    };
    auto field = [&](const lc::Vec4& x) {
      const lc::godel::KillingField f[5] = { lc::godel::KillingField::T,
        lc::godel::KillingField::Phi, lc::godel::KillingField::Z, lc::godel::KillingField::Xi4,
        lc::godel::KillingField::Xi5 };
      lc::Vec4 v = lc::Vec4::Zero();
      for (int k = 0; k < 5; ++k)
        v += cc[k] * lc::godel::killingCartesian(f[k], a, x);
      return v;
    };
    for (int line = 0; line < 2; ++line)
    {
      const vtkIdType first = line * (n + 1);
      double seed[3];
      seeds->GetPoint(line, seed);
      // s = 0 at the middle sample is the seed itself.
      const lc::Vec4 x0 = event(first + n / 2);
      EXPECT_NEAR(s->GetComponent(first + n / 2, 0), 0.0, 1e-15);
      EXPECT_LT((x0 - lc::Vec4(-0.4, seed[0], seed[1], seed[2])).norm(), 1e-15);
      const lc::Vec4 xi0 = field(x0);
      const double g0 = xi0.dot(Metric(a, x0) * xi0);
      double moved = 0;
      for (vtkIdType i = 0; i <= n; ++i)
      {
        const lc::Vec4 x = event(first + i);
        const lc::Vec4 xi = field(x);
        const double gg = xi.dot(Metric(a, x) * xi);
        EXPECT_NEAR(gg, g0, 1e-8 * std::max(1.0, std::abs(g0))) << "combo " << combo << " s " << s->GetComponent(first + i, 0);
        moved = std::max(moved, (x - x0).norm());
        if (i > 0 && i < n)
        {
          // The polyline is tangent to the field: central differences along s.
          const double ds = s->GetComponent(first + i + 1, 0) - s->GetComponent(first + i - 1, 0);
          const lc::Vec4 d = (event(first + i + 1) - event(first + i - 1)) / ds;
          EXPECT_LT((d - xi).norm(), 1e-4 * std::max(1.0, xi.norm()));
        }
      }
      EXPECT_GT(moved, 1.0) << "the orbit must actually move";
    }
  }
}

TEST(IsometryOrbitSource, Xi4OrbitThroughAxisIsSinh)
{
  // On X = 0, xi4 = R d/dY with R = sqrt(4a^2 + Y^2) (docs/PHYSICS.md 4: purely radial at
  // phi = pi/2, no t component): the orbit through the axis is Y(s) = 2a sinh(s).
  const double a = 0.6;
  vtkNew<vtkLightconeIsometryOrbitSource> src;
  src->SetGodelA(a);
  src->SetCoefficients(0, 0, 0, 1, 0);
  vtkNew<vtkPoints> seeds;
  seeds->SetDataTypeToDouble();
  seeds->InsertNextPoint(0, 0, 0.25);
  src->SetSeeds(seeds);
  src->SetSeedTime(1.5);
  src->SetFlowRange(2.0, -2.0); // decreasing: runs backwards through s = 0
  src->SetNumberOfSamples(40);
  src->Update();
  vtkPolyData* out = src->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 41);
  vtkDataArray* s = PArray(out, "s");
  vtkDataArray* t = PArray(out, "t");
  vtkDataArray* r = PArray(out, "r");
  ASSERT_TRUE(s && t && r);
  for (vtkIdType id = 0; id <= 40; ++id)
  {
    const double ss = 2.0 - 4.0 * id / 40;
    EXPECT_NEAR(s->GetComponent(id, 0), ss, 1e-15);
    double p[3];
    out->GetPoint(id, p);
    const double Y = 2 * a * std::sinh(ss);
    EXPECT_NEAR(p[0], 0.0, 1e-12);
    EXPECT_NEAR(p[1], Y, 1e-9 * (1 + std::abs(Y))) << "s " << ss;
    EXPECT_EQ(p[2], 0.25);
    EXPECT_NEAR(t->GetComponent(id, 0), 1.5, 1e-12);
    EXPECT_NEAR(r->GetComponent(id, 0), std::abs(Y), 1e-9 * (1 + std::abs(Y)));
  }
}

// ---- world lines ------------------------------------------------------------------------

namespace
{
// Timelike geodesic through the origin, docs/PHYSICS.md section 2, with the signed radius.
struct GodelFall
{
  double a, k0, k3, phi0;
  double W() const { return k0 * k0 + 1 + k3 * k3; }
  double omega() const { return std::sqrt(W()) / (2 * a); }
  double rMax() const { return 2 * a * std::sqrt((k0 * k0 - 1 - k3 * k3) / W()); }
  double Phi(double tau) const
  {
    const double th = omega() * tau;
    return std::atan(std::sqrt(2 * k0 * k0 / W()) * std::tan(th)) + kPi * std::floor(th / kPi + 0.5);
  }
  lc::Vec4 x(double tau) const
  {
    const double sg = k0 > 0 ? 1 : -1;
    const double rho = rMax() * std::sin(omega() * tau);
    const double ph = phi0 + sg * Phi(tau);
    return lc::Vec4(sg * 2 * kSqrt2 * a * Phi(tau) - k0 * tau, rho * std::cos(ph), rho * std::sin(ph), k3 * tau);
  }
};
} // namespace

TEST(WorldLineSource, GodelFreeFallMatchesClosedFormMovedByIsometry)
{
  const double a = 0.7;
  const double start[4] = { 0.5, 0.4, -0.3, 0.2 };
  struct Case
  {
    double k0, k3, phi0deg;
  };
  for (const Case& cs : { Case{ 1.6, 0.3, 40.0 }, Case{ -2.0, -0.5, 200.0 }, Case{ 1.05, 0.1, -75.0 } })
  {
    vtkNew<vtkLightconeWorldLineSource> src;
    src->SetModeToGodelFreeFall();
    src->SetGodelA(a);
    src->SetEnergy(cs.k0);
    src->SetK3(cs.k3);
    src->SetAzimuth(cs.phi0deg);
    src->SetStartEvent(start[0], start[1], start[2], start[3]);
    src->SetProperTimeRange(-3.0, 12.0);
    src->SetNumberOfSamples(300);
    src->SetOutputChartToXYT();
    src->Update();
    vtkPolyData* out = src->GetOutput();
    ASSERT_EQ(out->GetNumberOfPoints(), 301);
    ASSERT_EQ(out->GetNumberOfLines(), 1);
    vtkDataArray* tau = PArray(out, "tau");
    vtkDataArray* t = PArray(out, "t");
    vtkDataArray* u = PArray(out, "velocity");
    vtkDataArray* r = PArray(out, "r");
    ASSERT_TRUE(tau && t && u && r);
    ASSERT_EQ(u->GetNumberOfComponents(), 4);
    const GodelFall g{ a, cs.k0, cs.k3, cs.phi0deg * kPi / 180 };
    const lc::godel::Isometry I =
      lc::godel::Isometry::movingOriginTo(a, lc::Vec4(start[0], start[1], start[2], start[3]));
    double maxR = 0;
    for (vtkIdType id = 0; id <= 300; ++id)
    {
      const double tt = tau->GetComponent(id, 0);
      EXPECT_NEAR(tt, -3.0 + 15.0 * id / 300, 1e-13);
      const lc::Vec4 expected = I.apply(g.x(tt));
      double p[3];
      out->GetPoint(id, p);
      EXPECT_NEAR(p[0], expected(1), 1e-10) << "tau " << tt;
      EXPECT_NEAR(p[1], expected(2), 1e-10) << "tau " << tt;
      EXPECT_NEAR(p[2], expected(0), 1e-10) << "tau " << tt; // XYT chart
      EXPECT_NEAR(t->GetComponent(id, 0), expected(0), 1e-10);
      EXPECT_NEAR(r->GetComponent(id, 0), std::hypot(expected(1), expected(2)), 1e-10);
      const lc::Vec4 x(t->GetComponent(id, 0), p[0], p[1], 0);
      lc::Vec4 v;
      for (int k = 0; k < 4; ++k)
        v(k) = u->GetComponent(id, k);
      EXPECT_NEAR(v.dot(Metric(a, x) * v), 1.0, 1e-10) << "tau " << tt;
      EXPECT_EQ(v(0) > 0, cs.k0 > 0) << "time orientation";
      maxR = std::max(maxR, std::hypot(p[0], p[1]));
    }
    // tau = 0 is the start event (the closed form's origin moved by the isometry).
    EXPECT_LT((I.apply(g.x(0)) - lc::Vec4(start[0], start[1], start[2], start[3])).norm(), 1e-13);
    EXPECT_GT(maxR, 0.5);
  }
}

TEST(WorldLineSource, MinkowskiAndRest)
{
  vtkNew<vtkLightconeWorldLineSource> src;
  src->SetModeToMinkowski();
  const double b[3] = { 0.3, -0.4, 0.5 };
  src->SetBeta(b[0], b[1], b[2]);
  src->SetStartEvent(1, 2, 3, 4);
  src->SetProperTimeRange(-2, 5);
  src->SetNumberOfSamples(70);
  src->Update();
  vtkPolyData* out = src->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 71);
  const double gamma = 1 / std::sqrt(1 - (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
  vtkDataArray* tau = PArray(out, "tau");
  vtkDataArray* t = PArray(out, "t");
  vtkDataArray* u = PArray(out, "velocity");
  ASSERT_TRUE(tau && t && u);
  for (vtkIdType id = 0; id <= 70; ++id)
  {
    const double tt = -2 + 7.0 * id / 70;
    EXPECT_NEAR(tau->GetComponent(id, 0), tt, 1e-14);
    double p[3];
    out->GetPoint(id, p);
    EXPECT_NEAR(t->GetComponent(id, 0), 1 + gamma * tt, 1e-13);
    EXPECT_NEAR(p[0], 2 + gamma * b[0] * tt, 1e-13);
    EXPECT_NEAR(p[1], 3 + gamma * b[1] * tt, 1e-13);
    EXPECT_NEAR(p[2], 4 + gamma * b[2] * tt, 1e-13);
    const double u0 = u->GetComponent(id, 0), u1 = u->GetComponent(id, 1),
                 u2 = u->GetComponent(id, 2), u3 = u->GetComponent(id, 3);
    EXPECT_NEAR(u0 * u0 - u1 * u1 - u2 * u2 - u3 * u3, 1.0, 1e-13);
    EXPECT_NEAR(u1 / u0, b[0], 1e-14);
    EXPECT_NEAR(u2 / u0, b[1], 1e-14);
    EXPECT_NEAR(u3 / u0, b[2], 1e-14);
  }
  // Goedel at rest: the static observer.
  src->SetModeToGodelRest();
  src->Update();
  out = src->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 71);
  for (vtkIdType id = 0; id <= 70; ++id)
  {
    double p[3];
    out->GetPoint(id, p);
    EXPECT_EQ(p[0], 2.0);
    EXPECT_EQ(p[1], 3.0);
    EXPECT_EQ(p[2], 4.0);
    EXPECT_NEAR(PArray(out, "t")->GetComponent(id, 0), 1 - 2 + 7.0 * id / 70, 1e-14);
  }
  // |beta| >= 1: error, empty output.
  EventCounter errors;
  vtkNew<vtkCallbackCommand> cb;
  cb->SetCallback(EventCounter::Callback);
  cb->SetClientData(&errors);
  src->AddObserver(vtkCommand::ErrorEvent, cb);
  src->SetModeToMinkowski();
  src->SetBeta(0.8, 0.7, 0);
  src->Update();
  EXPECT_EQ(errors.count, 1);
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 0);
}

// ---- photo-objects ----------------------------------------------------------------------

namespace
{
vtkSmartPointer<vtkPolyData> SmallSphere(double radius)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(10);
  sphere->SetPhiResolution(8);
  sphere->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  sphere->Update();
  vtkSmartPointer<vtkPolyData> pd = sphere->GetOutput();
  return pd;
}

std::string BlockName(vtkMultiBlockDataSet* mb, unsigned int i)
{
  if (!mb->HasMetaData(i) || !mb->GetMetaData(i)->Has(vtkCompositeDataSet::NAME()))
    return "";
  return mb->GetMetaData(i)->Get(vtkCompositeDataSet::NAME());
}
} // namespace

TEST(PhotoObjectFilter, GodelDirectionsMatchInverseSolution)
{
  const double a = 1.0;
  const lc::Vec4 obs(0.2, 0.1, -0.2, 0.1), centre(0.0, 0.9, 0.3, 0.2);
  auto mesh = SmallSphere(0.3);
  vtkNew<vtkLightconePhotoObjectFilter> f;
  f->SetInputData(mesh);
  f->SetGodelA(a);
  f->SetObserver(obs(0), obs(1), obs(2), obs(3));
  f->SetCentreEvent(centre(0), centre(1), centre(2), centre(3));
  f->SetMaxWinding(1);
  f->StitchOff();
  f->Update();
  vtkMultiBlockDataSet* out = f->GetOutput();
  ASSERT_EQ(out->GetNumberOfBlocks(), 4u);
  const lc::godel::Isometry place = lc::godel::Isometry::movingOriginTo(a, centre);
  const lc::godel::ObserverView view(a, obs);
  int checked = 0;
  for (unsigned int bi = 0; bi < 4; ++bi)
  {
    const int n = static_cast<int>(bi / 2), b = static_cast<int>(bi % 2);
    EXPECT_EQ(BlockName(out, bi), "winding " + std::to_string(n) + (b ? " inbound" : " outbound"));
    auto* pd = vtkPolyData::SafeDownCast(out->GetBlock(bi));
    ASSERT_NE(pd, nullptr);
    ASSERT_GT(pd->GetNumberOfPolys(), 0) << "block " << bi;
    vtkDataArray* dir = PArray(pd, "direction");
    vtkDataArray* depth = PArray(pd, "depth");
    vtkDataArray* te = PArray(pd, "emission_time");
    vtkDataArray* vid = PArray(pd, "vertex_id");
    vtkDataArray* welded = PArray(pd, "welded");
    ASSERT_TRUE(dir && depth && te && vid && welded);
    vtkDataArray* wind = pd->GetCellData()->GetArray("winding");
    vtkDataArray* br = pd->GetCellData()->GetArray("branch");
    ASSERT_TRUE(wind && br);
    for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
    {
      EXPECT_EQ(wind->GetComponent(c, 0), n);
      EXPECT_EQ(br->GetComponent(c, 0), b);
    }
    for (vtkIdType id = 0; id < pd->GetNumberOfPoints(); ++id)
    {
      double v[3];
      mesh->GetPoint(static_cast<vtkIdType>(vid->GetComponent(id, 0)), v);
      const lc::Vec4 world = place.apply(lc::Vec4(0, v[0], v[1], v[2]));
      const lc::godel::ImageSet set = view.images(world.segment<3>(1), 1);
      ASSERT_EQ(set.status, lc::godel::ImageStatus::Ok);
      const lc::godel::Image* match = nullptr;
      for (const auto& im : set.images)
        if (im.winding == n && static_cast<int>(im.branch == lc::godel::Branch::Inbound) == b)
          match = &im;
      ASSERT_NE(match, nullptr) << "vertex " << vid->GetComponent(id, 0) << " block " << bi;
      double p[3];
      pd->GetPoint(id, p);
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_NEAR(dir->GetComponent(id, k), match->direction(k), 1e-10);
        EXPECT_NEAR(p[k], match->direction(k), 1e-10); // unit-sphere placement
      }
      EXPECT_NEAR(depth->GetComponent(id, 0), match->lambda, 1e-10);
      EXPECT_NEAR(te->GetComponent(id, 0), match->emissionTime, 1e-9);
      EXPECT_EQ(welded->GetComponent(id, 0), 0.0);
      ++checked;
    }
  }
  EXPECT_GT(checked, 4 * 50);
  vtkDataArray* beyond = out->GetFieldData()->GetArray("beyond_horizon");
  ASSERT_NE(beyond, nullptr);
  EXPECT_EQ(beyond->GetNumberOfTuples(), 0);

  // Depth placement: points at depth * direction.
  f->SetPointPlacementToDepth();
  f->Update();
  auto* pd = vtkPolyData::SafeDownCast(f->GetOutput()->GetBlock(1));
  ASSERT_NE(pd, nullptr);
  for (vtkIdType id = 0; id < pd->GetNumberOfPoints(); ++id)
  {
    double p[3];
    pd->GetPoint(id, p);
    const double l = PArray(pd, "depth")->GetComponent(id, 0);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(p[k], l * PArray(pd, "direction")->GetComponent(id, k), 1e-12);
  }

  // Stitching on: still one block per layer, welded flags present.
  f->StitchOn();
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 4u);

  // A mesh beyond the horizon (r = 5 > 2a from the observer): no image at all, reported.
  f->SetObserver(0, 0, 0, 0);
  f->SetCentreEvent(0, 5, 0, 0);
  f->Update();
  beyond = f->GetOutput()->GetFieldData()->GetArray("beyond_horizon");
  ASSERT_NE(beyond, nullptr);
  EXPECT_EQ(beyond->GetNumberOfTuples(), mesh->GetNumberOfPoints());
  for (unsigned int bi = 0; bi < f->GetOutput()->GetNumberOfBlocks(); ++bi)
  {
    auto* blk = vtkPolyData::SafeDownCast(f->GetOutput()->GetBlock(bi));
    ASSERT_NE(blk, nullptr);
    EXPECT_EQ(blk->GetNumberOfCells(), 0);
  }
}

TEST(PhotoObjectFilter, SpecialRelativityCubeOnLightCone)
{
  const double beta = 0.95;
  vtkNew<vtkCubeSource> cube; // quads: the filter triangulates them
  cube->SetXLength(1.0);
  cube->SetYLength(0.6);
  cube->SetZLength(0.8);
  cube->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  cube->Update();
  vtkPolyData* mesh = cube->GetOutput();
  vtkNew<vtkLightconePhotoObjectFilter> f;
  f->SetInputData(mesh);
  f->SetModeToSpecialRelativity();
  f->SetBeta(beta, 0, 0);
  const double t0 = 0.5, x0[3] = { -1.0, 2.0, 0.5 }; // the cube's centre passes x0 at t0
  f->SetObjectOrigin(t0, x0[0], x0[1], x0[2]);
  f->SetObserver(0, 0, 0, 0);
  f->Update();
  vtkMultiBlockDataSet* out = f->GetOutput();
  ASSERT_EQ(out->GetNumberOfBlocks(), 1u);
  auto* pd = vtkPolyData::SafeDownCast(out->GetBlock(0));
  ASSERT_NE(pd, nullptr);
  ASSERT_EQ(pd->GetNumberOfPoints(), mesh->GetNumberOfPoints());
  EXPECT_EQ(pd->GetNumberOfPolys(), 12); // 6 quads -> 12 triangles
  vtkDataArray* te = PArray(pd, "emission_time");
  vtkDataArray* D = PArray(pd, "doppler");
  ASSERT_TRUE(te && D);
  const double gamma = 1 / std::sqrt(1 - beta * beta);
  for (vtkIdType id = 0; id < pd->GetNumberOfPoints(); ++id)
  {
    double v[3], p[3];
    mesh->GetPoint(id, v);
    pd->GetPoint(id, p);
    // Position at t = 0 in S: the centre at x0 - beta t0, the rest shape contracted along x.
    const double q[3] = { x0[0] - beta * t0 + v[0] / gamma, x0[1] + v[1], x0[2] + v[2] };
    // |q + beta t| = -t, t < 0:  (1 - beta^2) t^2 - 2 (q.beta) t - |q|^2 = 0.
    const double B = q[0] * beta, q2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    const double disc = std::sqrt(B * B + (1 - beta * beta) * q2);
    const double te0 = B > 0 ? -q2 / (B + disc) : (B - disc) / (1 - beta * beta);
    const double xa[3] = { q[0] + beta * te0, q[1], q[2] };
    const double scale = 1 + std::abs(te0);
    EXPECT_NEAR(te->GetComponent(id, 0), te0, 1e-12 * scale);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(p[k], xa[k], 1e-12 * scale) << "vertex " << id;
    // The light-cone equation itself.
    EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), -te->GetComponent(id, 0), 1e-12 * scale);
    // Doppler factor towards the observer at the origin: n = -x_app / |x_app|.
    const double len = std::sqrt(xa[0] * xa[0] + xa[1] * xa[1] + xa[2] * xa[2]);
    EXPECT_NEAR(D->GetComponent(id, 0), 1 / (gamma * (1 + beta * xa[0] / len)), 1e-12);
  }
}

TEST(PhotoObjectFilter, ReexecutesOnlyOnChangeAndEmptyInput)
{
  auto mesh = SmallSphere(0.2);
  vtkNew<vtkLightconePhotoObjectFilter> f;
  f->SetInputData(mesh);
  f->SetMaxWinding(0);
  EventCounter ends;
  vtkNew<vtkCallbackCommand> cb;
  cb->SetCallback(EventCounter::Callback);
  cb->SetClientData(&ends);
  f->AddObserver(vtkCommand::EndEvent, cb);
  f->Update();
  EXPECT_EQ(ends.count, 1);
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 2u);
  f->Update();
  EXPECT_EQ(ends.count, 1);
  f->SetMaxWinding(0); // same value: no re-execution
  f->Update();
  EXPECT_EQ(ends.count, 1);
  f->SetMaxWinding(2);
  f->Update();
  EXPECT_EQ(ends.count, 2);
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 6u);
  f->SetCentreEvent(0, 0.5, 0.5, 0);
  f->Update();
  EXPECT_EQ(ends.count, 3);

  // Empty mesh: empty output, a warning, no crash.
  EventCounter warnings;
  vtkNew<vtkCallbackCommand> wcb;
  wcb->SetCallback(EventCounter::Callback);
  wcb->SetClientData(&warnings);
  f->AddObserver(vtkCommand::WarningEvent, wcb);
  vtkNew<vtkPolyData> empty;
  f->SetInputData(empty);
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 0u);
  EXPECT_EQ(warnings.count, 1);
  f->SetModeToSpecialRelativity();
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 0u);
  EXPECT_EQ(warnings.count, 2);

  // Sources re-execute on a change too.
  vtkNew<vtkLightconeKillingFieldSource> k;
  EventCounter kends;
  vtkNew<vtkCallbackCommand> kcb;
  kcb->SetCallback(EventCounter::Callback);
  kcb->SetClientData(&kends);
  k->AddObserver(vtkCommand::EndEvent, kcb);
  k->Update();
  k->Update();
  EXPECT_EQ(kends.count, 1);
  k->SetCoefficients(1, 0, 0, 0, 0);
  k->Update();
  EXPECT_EQ(kends.count, 2);
  vtkNew<vtkLightconeIsometryOrbitSource> o;
  vtkNew<vtkPoints> seeds;
  seeds->InsertNextPoint(1, 0, 0);
  o->SetSeeds(seeds);
  o->Update();
  const vtkMTimeType m0 = o->GetOutput()->GetMTime();
  seeds->SetPoint(0, 0.5, 0, 0);
  seeds->Modified();
  o->Update();
  EXPECT_GT(o->GetOutput()->GetMTime(), m0);
  EXPECT_NEAR(o->GetOutput()->GetPoint(0)[0], 0.5, 1e-15);
}

TEST(PhotoObjectFilter, VtmRoundTripKeepsPoints)
{
  auto mesh = SmallSphere(0.25);
  vtkNew<vtkLightconePhotoObjectFilter> f;
  f->SetInputData(mesh);
  f->SetObserver(0, 0, 0, 0);
  f->SetCentreEvent(0, 0.8, -0.2, 0.1);
  f->SetMaxWinding(1);
  f->SetPointPlacementToDepth();
  f->Update();
  vtkMultiBlockDataSet* out = f->GetOutput();
  ASSERT_EQ(out->GetNumberOfBlocks(), 4u);
  const auto dir = std::filesystem::temp_directory_path() / "lightcone_photo_object_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "photo.vtm").string();
  vtkNew<vtkXMLMultiBlockDataWriter> w;
  w->SetInputData(out);
  w->SetFileName(file.c_str());
  w->SetDataModeToBinary();
  ASSERT_EQ(w->Write(), 1);
  vtkNew<vtkXMLMultiBlockDataReader> r;
  r->SetFileName(file.c_str());
  r->Update();
  auto* back = vtkMultiBlockDataSet::SafeDownCast(r->GetOutput());
  ASSERT_NE(back, nullptr);
  ASSERT_EQ(back->GetNumberOfBlocks(), 4u);
  for (unsigned int bi = 0; bi < 4; ++bi)
  {
    auto* a = vtkPolyData::SafeDownCast(out->GetBlock(bi));
    auto* b = vtkPolyData::SafeDownCast(back->GetBlock(bi));
    ASSERT_TRUE(a && b);
    ASSERT_GT(a->GetNumberOfPoints(), 0);
    EXPECT_EQ(BlockName(back, bi), BlockName(out, bi));
    ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
    ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
    for (vtkIdType id = 0; id < a->GetNumberOfPoints(); ++id)
    {
      double p[3], q[3];
      a->GetPoint(id, p);
      b->GetPoint(id, q);
      EXPECT_EQ(p[0], q[0]);
      EXPECT_EQ(p[1], q[1]);
      EXPECT_EQ(p[2], q[2]);
    }
    for (const char* name : { "direction", "depth", "emission_time", "welded" })
    {
      vtkDataArray* x = a->GetPointData()->GetArray(name);
      vtkDataArray* y = b->GetPointData()->GetArray(name);
      ASSERT_TRUE(x && y) << name;
      for (vtkIdType id = 0; id < x->GetNumberOfTuples(); ++id)
        for (int k = 0; k < x->GetNumberOfComponents(); ++k)
          EXPECT_EQ(x->GetComponent(id, k), y->GetComponent(id, k));
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(PhotoObjectFilter, PrintSelfOfAllNewClasses)
{
  std::ostringstream os;
  vtkNew<vtkLightconeKillingFieldSource> k;
  k->Print(os);
  vtkNew<vtkLightconeIsometryOrbitSource> o;
  o->Print(os);
  vtkNew<vtkLightconeWorldLineSource> w;
  w->Print(os);
  vtkNew<vtkLightconePhotoObjectFilter> f;
  f->Print(os);
  const std::string text = os.str();
  for (const char* key : { "Coefficients: (0, 1, 0, 0, 0)", "FlowRange:", "Mode: GodelFreeFall",
         "MaxWinding: 2", "PointPlacement: Direction" })
    EXPECT_NE(text.find(key), std::string::npos) << key;
}
