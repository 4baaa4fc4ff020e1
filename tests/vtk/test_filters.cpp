// Tests of the VTK sources in filters/: the Goedel rays against the closed form of
// docs/PHYSICS.md section 2 (typed in here, with the signed radius r_max sin(omega l) that holds
// after axis passages), the horizon against r = 2a, pipeline re-execution, XML round trip.
#include "tests/common/vtk_event_counter.hpp"
#include "vtkLightconeGodelHorizonSource.h"
#include "vtkLightconeNullGeodesicSource.h"
#include "core/godel/isometry.hpp"

#include <gtest/gtest.h>

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
constexpr double kPi = 3.14159265358979323846;

// Past-directed (k0 = -1) null geodesic of the Goedel universe through the origin, local
// direction at the origin with polar angle psi from +z and azimuth phi0 (docs/PHYSICS.md 2).
// The sources start the continuous azimuth in (-pi, pi]: give phi0 there (Azimuth()).
double Azimuth(double phi0)
{
  return std::atan2(std::sin(phi0), std::cos(phi0));
}
struct GodelRay
{
  double a, psi, phi0;
  double k3() const { return std::cos(psi); }
  double omega() const { return std::sqrt(1 + k3() * k3()) / (2 * a); }
  double rMax() const { return 2 * a * std::sqrt((1 - k3() * k3()) / (1 + k3() * k3())); }
  double Phi(double l) const
  {
    const double th = omega() * l;
    return std::atan(std::sqrt(2 / (1 + k3() * k3())) * std::tan(th)) +
      kPi * std::floor(th / kPi + 0.5);
  }
  double t(double l) const { return -(2 * std::sqrt(2.0) * a * Phi(l) - l); }
  double rho(double l) const { return rMax() * std::sin(omega() * l); } // signed radius
  double phi(double l) const { return phi0 - Phi(l); }
  double X(double l) const { return rho(l) * std::cos(phi(l)); }
  double Y(double l) const { return rho(l) * std::sin(phi(l)); }
  double z(double l) const { return k3() * l; }
};

vtkDataArray* PointArray(vtkPolyData* pd, const char* name)
{
  vtkDataArray* a = pd->GetPointData()->GetArray(name);
  EXPECT_NE(a, nullptr) << "missing point array " << name;
  return a;
}

// Rays of the source, in cell order: point ids of each polyline.
std::vector<std::vector<vtkIdType>> Rays(vtkPolyData* pd)
{
  std::vector<std::vector<vtkIdType>> rays;
  vtkCellArray* lines = pd->GetLines();
  vtkNew<vtkIdList> ids;
  for (lines->InitTraversal(); lines->GetNextCell(ids);)
  {
    rays.emplace_back(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds());
  }
  return rays;
}

vtkSmartPointer<vtkLightconeNullGeodesicSource> GodelSource(double a)
{
  auto src = vtkSmartPointer<vtkLightconeNullGeodesicSource>::New();
  src->SetMetricName("godel");
  src->SetMetricParameter("a", a);
  src->SetObserver(0, 0, 0, 0);
  src->SetStepper("dopri5");
  src->SetTolerance(1e-12);
  src->SetSamplesPerStep(3);
  src->SetMethodToNumeric(); // these tests check the integrator route; see ClosedForm tests
  return src;
}

// Compares every point of the Goedel rays with the closed form; rays[i] has (psi, phi0).
void CheckAgainstClosedForm(vtkPolyData* out, const std::vector<GodelRay>& expected,
  bool rphit, double maxAffine)
{
  const auto rays = Rays(out);
  ASSERT_EQ(rays.size(), expected.size());
  vtkDataArray* tA = PointArray(out, "t");
  vtkDataArray* lA = PointArray(out, "affine");
  vtkDataArray* rA = PointArray(out, "r");
  vtkDataArray* srA = PointArray(out, "signed_r");
  vtkDataArray* phiA = PointArray(out, "phi");
  vtkDataArray* zA = PointArray(out, "z");
  vtkDataArray* wA = PointArray(out, "winding");
  vtkDataArray* hA = PointArray(out, "hamiltonian_drift");
  ASSERT_TRUE(tA && lA && rA && srA && phiA && zA && wA && hA);
  vtkDataArray* reason = out->GetCellData()->GetArray("stop_reason");
  vtkDataArray* steps = out->GetCellData()->GetArray("steps");
  ASSERT_NE(reason, nullptr);
  ASSERT_NE(steps, nullptr);
  for (std::size_t i = 0; i < rays.size(); ++i)
  {
    const GodelRay& g = expected[i];
    ASSERT_GT(rays[i].size(), 10u);
    // The start point, then SamplesPerStep (3, see GodelSource) points per accepted step.
    EXPECT_EQ(rays[i].size(),
      1 + 3 * static_cast<std::size_t>(steps->GetComponent(static_cast<vtkIdType>(i), 0)));
    double lastL = -1;
    int maxWinding = 0;
    for (vtkIdType id : rays[i])
    {
      const double l = lA->GetComponent(id, 0);
      ASSERT_GE(l, lastL);
      lastL = l;
      double p[3];
      out->GetPoint(id, p);
      const double r = std::abs(g.rho(l));
      if (rphit)
      {
        EXPECT_NEAR(p[0], r, 1e-8) << "ray " << i << " l " << l;
        if (r > 1e-3)
        {
          EXPECT_NEAR(p[1], g.phi(l), 1e-6) << "ray " << i << " l " << l;
        }
        EXPECT_NEAR(p[2], g.t(l), 1e-8) << "ray " << i << " l " << l;
      }
      else
      {
        EXPECT_NEAR(p[0], g.X(l), 1e-8) << "ray " << i << " l " << l;
        EXPECT_NEAR(p[1], g.Y(l), 1e-8) << "ray " << i << " l " << l;
        EXPECT_NEAR(p[2], g.z(l), 1e-8) << "ray " << i << " l " << l;
      }
      EXPECT_NEAR(tA->GetComponent(id, 0), g.t(l), 1e-8);
      EXPECT_NEAR(zA->GetComponent(id, 0), g.z(l), 1e-8);
      EXPECT_NEAR(rA->GetComponent(id, 0), r, 1e-8);
      EXPECT_NEAR(srA->GetComponent(id, 0), g.rho(l), 1e-8) << "ray " << i << " l " << l;
      if (r > 1e-3)
      {
        EXPECT_NEAR(phiA->GetComponent(id, 0), g.phi(l), 1e-6) << "ray " << i << " l " << l;
      }
      // Axis passages so far: omega l / pi, away from the passages themselves.
      const double passes = g.omega() * l / kPi;
      if (std::abs(passes - std::nearbyint(passes)) > 1e-6)
      {
        EXPECT_EQ(static_cast<int>(wA->GetComponent(id, 0)), static_cast<int>(std::floor(passes)))
          << "ray " << i << " l " << l;
      }
      maxWinding = std::max(maxWinding, static_cast<int>(wA->GetComponent(id, 0)));
      EXPECT_LT(std::abs(hA->GetComponent(id, 0)), 1e-9) << "ray " << i << " l " << l;
    }
    EXPECT_NEAR(lastL, maxAffine, 1e-9);
    EXPECT_GE(maxWinding, 2) << "the test must cover several axis passages";
    EXPECT_EQ(static_cast<int>(reason->GetComponent(static_cast<vtkIdType>(i), 0)),
      2 /* lc::StopReason::MaxAffine */);
  }
}

using lc::testing::EventCounter;
} // namespace

TEST(NullGeodesicSource, GodelConeMatchesClosedFormEmbedding)
{
  const double a = 0.8, maxAffine = 14.0, psiDeg = 60.0;
  const int n = 5;
  auto src = GodelSource(a);
  src->SetDirectionModeToCone();
  src->SetConeAxis(0, 0, 1);
  src->SetConeAngle(psiDeg);
  src->SetNumberOfRays(n);
  src->SetMaxAffine(maxAffine);
  src->SetOutputChartToEmbedding();
  src->Update();
  std::vector<GodelRay> expected;
  for (int i = 0; i < n; ++i)
    expected.push_back({ a, psiDeg * kPi / 180, Azimuth(2 * kPi * i / n) });
  CheckAgainstClosedForm(src->GetOutput(), expected, false, maxAffine);
}

TEST(NullGeodesicSource, GodelFanMatchesClosedFormRPhiT)
{
  const double a = 1.3, maxAffine = 20.0;
  const int n = 4;
  auto src = GodelSource(a);
  src->SetDirectionModeToFan();
  src->SetFanNormal(0, 0, 1);
  src->SetFanStartAngle(10);
  src->SetFanEndAngle(370);
  src->SetNumberOfRays(n);
  src->SetMaxAffine(maxAffine);
  src->SetOutputChartToRPhiT();
  src->Update();
  std::vector<GodelRay> expected;
  for (int i = 0; i < n; ++i)
    expected.push_back({ a, kPi / 2, Azimuth((10.0 + 90.0 * i) * kPi / 180) });
  CheckAgainstClosedForm(src->GetOutput(), expected, true, maxAffine);
  // Planar rays reach the horizon r = 2a exactly and no further.
  double range[2];
  PointArray(src->GetOutput(), "r")->GetRange(range, 0);
  EXPECT_NEAR(range[1], 2 * a, 1e-6);
  EXPECT_LE(range[1], 2 * a + 1e-8);
}

TEST(NullGeodesicSource, GodelListDirections)
{
  const double a = 1.0, maxAffine = 16.0;
  vtkNew<vtkPoints> dirs;
  dirs->SetDataTypeToDouble(); // float directions would be off by 1e-8 already
  const double psi = 2.0, phi0 = -2.5; // not normalised on purpose: the source normalises
  dirs->InsertNextPoint(3 * std::sin(psi) * std::cos(phi0), 3 * std::sin(psi) * std::sin(phi0),
    3 * std::cos(psi));
  auto src = GodelSource(a);
  src->SetDirectionModeToList();
  src->SetDirections(dirs);
  src->SetMaxAffine(maxAffine);
  src->Update();
  CheckAgainstClosedForm(src->GetOutput(), { { a, psi, phi0 } }, false, maxAffine);

  // Editing the directions in place re-executes the source (GetMTime includes them).
  const vtkIdType before = src->GetOutput()->GetNumberOfPoints();
  dirs->SetPoint(0, 0, 0, 1); // along the axis: a straight line, few steps
  dirs->Modified();           // VTK convention: SetPoint does not touch the MTime
  src->Update();
  EXPECT_NE(src->GetOutput()->GetNumberOfPoints(), before);
}

// An observer off the axis: the cylindrical chart (t, r, phi, z) and the Cartesian chart
// (t, x, y, z) are two independent metric codes; at phi = 0 their static frames coincide
// (d/dx = d/dr, d/dy = d/dphi / r), so both must draw the same rays in the embedding.
TEST(NullGeodesicSource, CylindricalAndCartesianChartsAgree)
{
  const double a = 1.0, r0 = 0.6;
  vtkSmartPointer<vtkLightconeNullGeodesicSource> src[2];
  for (int c = 0; c < 2; ++c)
  {
    src[c] = GodelSource(a);
    src[c]->SetMetricName(c == 0 ? "godel" : "godel-cylindrical");
    src[c]->SetObserver(0.5, r0, 0, -0.2);
    src[c]->SetDirectionModeToCone();
    src[c]->SetConeAxis(0.2, 0.1, 1);
    src[c]->SetConeAngle(50);
    src[c]->SetNumberOfRays(6);
    src[c]->SetMaxAffine(2.5);
    src[c]->SetSamplesPerStep(1);
    src[c]->Update();
  }
  vtkPolyData* cart = src[0]->GetOutput();
  vtkPolyData* cyl = src[1]->GetOutput();
  const auto raysA = Rays(cart), raysB = Rays(cyl);
  ASSERT_EQ(raysA.size(), 6u);
  ASSERT_EQ(raysB.size(), 6u);
  vtkDataArray* lB = PointArray(cyl, "affine");
  vtkDataArray* tA = PointArray(cart, "t");
  vtkDataArray* tB = PointArray(cyl, "t");
  for (std::size_t i = 0; i < raysA.size(); ++i)
  {
    // The steps differ: compare the last points, both at MaxAffine.
    const vtkIdType ia = raysA[i].back(), ib = raysB[i].back();
    EXPECT_NEAR(lB->GetComponent(ib, 0), 2.5, 1e-12);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(cart->GetPoint(ia)[k], cyl->GetPoint(ib)[k], 1e-8) << "ray " << i;
    EXPECT_NEAR(tA->GetComponent(ia, 0), tB->GetComponent(ib, 0), 1e-8);
    EXPECT_GT(std::abs(cart->GetPoint(ia)[2] + 0.2), 0.1); // the rays left the plane z = -0.2
  }
}

TEST(NullGeodesicSource, ParameterChangeReexecutesAndUnchangedDoesNot)
{
  auto src = GodelSource(1.0);
  src->SetNumberOfRays(3);
  src->SetMaxAffine(3.0);
  EventCounter counter;
  vtkNew<vtkCallbackCommand> cb;
  cb->SetCallback(EventCounter::Callback);
  cb->SetClientData(&counter);
  src->AddObserver(vtkCommand::EndEvent, cb);

  src->Update();
  EXPECT_EQ(counter.count, 1);
  src->Update();
  EXPECT_EQ(counter.count, 1) << "unchanged pipeline must not re-execute";

  const vtkMTimeType m0 = src->GetMTime();
  src->SetTolerance(1e-12); // same value: no change
  EXPECT_EQ(src->GetMTime(), m0);
  src->Update();
  EXPECT_EQ(counter.count, 1);

  src->SetTolerance(1e-9);
  EXPECT_GT(src->GetMTime(), m0);
  src->Update();
  EXPECT_EQ(counter.count, 2);

  src->SetMetricParameter("a", 1.0); // same as before: nothing
  src->Update();
  EXPECT_EQ(counter.count, 2);
  src->SetMetricParameter("a", 2.0);
  src->Update();
  EXPECT_EQ(counter.count, 3);
  src->SetOutputChartToRPhiT();
  src->Update();
  EXPECT_EQ(counter.count, 4);
}

TEST(NullGeodesicSource, BadMetricNameReportsError)
{
  auto src = GodelSource(1.0);
  src->SetMetricName("no-such-metric");
  EventCounter errors;
  vtkNew<vtkCallbackCommand> cb;
  cb->SetCallback(EventCounter::Callback);
  cb->SetClientData(&errors);
  src->AddObserver(vtkCommand::ErrorEvent, cb);
  src->Update();
  EXPECT_GE(errors.count, 1);
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(NullGeodesicSource, XmlRoundTripIsExact)
{
  auto src = GodelSource(1.0);
  src->SetDirectionModeToCone();
  src->SetNumberOfRays(4);
  src->SetMaxAffine(8.0);
  src->Update();
  vtkPolyData* out = src->GetOutput();
  ASSERT_GT(out->GetNumberOfPoints(), 0);

  const std::string file =
    (std::filesystem::temp_directory_path() / "lightcone_vtk_roundtrip.vtp").string();
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(src->GetOutputPort());
  writer->SetFileName(file.c_str());
  writer->SetDataModeToBinary();
  ASSERT_EQ(writer->Write(), 1);

  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* in = reader->GetOutput();
  std::filesystem::remove(file);

  ASSERT_EQ(in->GetNumberOfPoints(), out->GetNumberOfPoints());
  ASSERT_EQ(in->GetNumberOfLines(), out->GetNumberOfLines());
  EXPECT_EQ(in->GetPoints()->GetDataType(), VTK_DOUBLE);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    out->GetPoint(i, p);
    in->GetPoint(i, q);
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(p[k], q[k]) << "point " << i;
  }
  EXPECT_EQ(Rays(in), Rays(out));
  ASSERT_EQ(in->GetPointData()->GetNumberOfArrays(), out->GetPointData()->GetNumberOfArrays());
  for (int k = 0; k < out->GetPointData()->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* a = out->GetPointData()->GetArray(k);
    vtkDataArray* b = in->GetPointData()->GetArray(a->GetName());
    ASSERT_NE(b, nullptr) << a->GetName();
    EXPECT_EQ(a->GetDataType(), b->GetDataType()) << a->GetName();
    ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples());
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      ASSERT_EQ(a->GetComponent(i, 0), b->GetComponent(i, 0)) << a->GetName() << " " << i;
  }
  for (const char* name : { "stop_reason", "steps", "psi", "phi0" })
  {
    vtkDataArray* a = out->GetCellData()->GetArray(name);
    vtkDataArray* b = in->GetCellData()->GetArray(name);
    ASSERT_TRUE(a && b) << name;
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      EXPECT_EQ(a->GetComponent(i, 0), b->GetComponent(i, 0)) << name;
  }
  auto* sa = vtkStringArray::SafeDownCast(out->GetCellData()->GetAbstractArray("stop_reason_name"));
  auto* sb = vtkStringArray::SafeDownCast(in->GetCellData()->GetAbstractArray("stop_reason_name"));
  ASSERT_TRUE(sa && sb);
  ASSERT_EQ(sa->GetNumberOfValues(), sb->GetNumberOfValues());
  for (vtkIdType i = 0; i < sa->GetNumberOfValues(); ++i)
    EXPECT_EQ(sa->GetValue(i), sb->GetValue(i));
}

TEST(GodelHorizonSource, HorizonIsTheCylinderOfRadius2a)
{
  const double a = 0.75;
  vtkNew<vtkLightconeGodelHorizonSource> src;
  src->SetGodelA(a);
  src->SetZRange(-2, 3);
  src->SetResolution(37);
  src->SetHeightResolution(5);
  src->Update();
  vtkPolyData* h = src->GetHorizonOutput();
  ASSERT_EQ(h->GetNumberOfPoints(), 37 * 6);
  EXPECT_EQ(h->GetNumberOfPolys(), 37 * 5);
  for (vtkIdType i = 0; i < h->GetNumberOfPoints(); ++i)
  {
    double p[3];
    h->GetPoint(i, p);
    EXPECT_NEAR(std::hypot(p[0], p[1]), 2 * a, 1e-14) << i;
    EXPECT_GE(p[2], -2.0);
    EXPECT_LE(p[2], 3.0);
  }
  double b[6];
  h->GetBounds(b);
  EXPECT_DOUBLE_EQ(b[4], -2.0);
  EXPECT_DOUBLE_EQ(b[5], 3.0);

  src->SetOutputChartToRPhiT();
  src->Update();
  h = src->GetHorizonOutput();
  for (vtkIdType i = 0; i < h->GetNumberOfPoints(); ++i)
    EXPECT_EQ(h->GetPoint(i)[0], 2 * a);
}

TEST(GodelHorizonSource, LightConeMatchesClosedFormAndStaysInsideHorizon)
{
  const double a = 1.1, length = 9.0, azimuthDeg = 30.0;
  for (int chart = 0; chart < 2; ++chart)
  {
    vtkNew<vtkLightconeGodelHorizonSource> src;
    src->SetGodelA(a);
    src->SetOutputChart(chart);
    src->SetLightConePsiResolution(12);
    src->SetLightConeAffineResolution(40);
    src->SetLightConeAffineLength(length);
    src->SetLightConeAzimuth(azimuthDeg);
    src->Update();
    vtkPolyData* c = src->GetLightConeOutput();
    ASSERT_EQ(c->GetNumberOfPoints(), 13 * 41);
    EXPECT_EQ(c->GetNumberOfPolys(), 12 * 40);
    vtkDataArray* psiA = PointArray(c, "psi");
    vtkDataArray* lA = PointArray(c, "affine");
    vtkDataArray* tA = PointArray(c, "t");
    ASSERT_TRUE(psiA && lA && tA);
    for (vtkIdType i = 0; i < c->GetNumberOfPoints(); ++i)
    {
      const GodelRay g{ a, psiA->GetComponent(i, 0), azimuthDeg * kPi / 180 };
      const double l = lA->GetComponent(i, 0);
      double p[3];
      c->GetPoint(i, p);
      EXPECT_NEAR(tA->GetComponent(i, 0), g.t(l), 1e-10);
      if (chart == 0)
      {
        EXPECT_NEAR(p[0], g.X(l), 1e-10);
        EXPECT_NEAR(p[1], g.Y(l), 1e-10);
        EXPECT_NEAR(p[2], g.z(l), 1e-10);
        EXPECT_LE(std::hypot(p[0], p[1]), 2 * a * (1 + 1e-12));
      }
      else
      {
        EXPECT_NEAR(p[0], std::abs(g.rho(l)), 1e-10);
        EXPECT_NEAR(p[1], g.phi(l), 1e-10);
        EXPECT_NEAR(p[2], g.t(l), 1e-10);
      }
    }
  }
  // The planar sheet: (X, Y, t) of the rays with psi = pi/2 over (phi0, lambda).
  vtkNew<vtkLightconeGodelHorizonSource> planar;
  planar->SetGodelA(a);
  planar->SetLightConeSheetToPlanar();
  planar->SetLightConePsiResolution(16);
  planar->SetLightConeAffineResolution(30);
  planar->SetLightConeAffineLength(length);
  planar->Update();
  vtkPolyData* pc = planar->GetLightConeOutput();
  ASSERT_EQ(pc->GetNumberOfPoints(), 17 * 31);
  vtkDataArray* phi0A = PointArray(pc, "phi0");
  vtkDataArray* plA = PointArray(pc, "affine");
  ASSERT_TRUE(phi0A && plA);
  for (vtkIdType i = 0; i < pc->GetNumberOfPoints(); ++i)
  {
    const int ring = static_cast<int>(i / 31);
    EXPECT_NEAR(phi0A->GetComponent(i, 0), 2 * kPi * ring / 16, 1e-14);
    const GodelRay g{ a, kPi / 2, 2 * kPi * ring / 16 };
    const double l = plA->GetComponent(i, 0);
    double p[3];
    pc->GetPoint(i, p);
    EXPECT_NEAR(p[0], g.X(l), 1e-10);
    EXPECT_NEAR(p[1], g.Y(l), 1e-10);
    EXPECT_NEAR(p[2], g.t(l), 1e-10);
  }
  // Back on the axis after lambda = 2 pi a at t = -2 pi a (sqrt2 - 1) (docs/PHYSICS.md 2).
  const double tBack = -2 * kPi * a * (std::sqrt(2.0) - 1);
  const GodelRay planarRay{ a, kPi / 2, 0 };
  EXPECT_NEAR(planarRay.t(2 * kPi * a), tBack, 1e-12);
  EXPECT_NEAR(planarRay.rho(2 * kPi * a), 0.0, 1e-12);

  vtkNew<vtkLightconeGodelHorizonSource> off;
  off->GenerateLightConeOff();
  off->Update();
  EXPECT_EQ(off->GetLightConeOutput()->GetNumberOfPoints(), 0);
  EXPECT_GT(off->GetHorizonOutput()->GetNumberOfPoints(), 0);
}

namespace
{
// An observer off the axis: its horizon, carried to the world chart by the isometry, is the
// cylinder of radius exactly 2a about the observer in the observer's own chart (docs/PHYSICS.md
// section 4: map it back with the isometry that moves the observer to the origin). In the
// world chart the same surface is no longer a circle of radius 2a about the observer.
TEST(GodelHorizonSource, MovedObserverHorizonHasRadius2aInItsOwnChart)
{
  const double a = 0.8;
  const double obs[4] = { 0.4, 0.9, -0.3, 0.2 };
  vtkNew<vtkLightconeGodelHorizonSource> src;
  src->SetGodelA(a);
  src->SetObserver(obs[0], obs[1], obs[2], obs[3]);
  src->SetZRange(-0.5, 0.5);
  src->Update();
  vtkPolyData* h = src->GetHorizonOutput();
  ASSERT_GT(h->GetNumberOfPoints(), 100);
  const lc::godel::Isometry toObserver =
    lc::godel::Isometry::movingToOrigin(a, lc::Vec4(obs[0], obs[1], obs[2], obs[3]));
  double worst = 0, worldSpread = 0;
  for (vtkIdType i = 0; i < h->GetNumberOfPoints(); ++i)
  {
    double p[3];
    h->GetPoint(i, p);
    // Surface events sit at the observer's time in its own chart (t = 0 there); the world
    // event's time follows from the isometry, so recover it by mapping (t, p) for the t that
    // gives 0: the time shift is independent of t, so t = -t'(0, p) works.
    const lc::Vec4 probe = toObserver.apply(lc::Vec4(0, p[0], p[1], p[2]));
    const lc::Vec4 local = toObserver.apply(lc::Vec4(-probe(0), p[0], p[1], p[2]));
    worst = std::max(worst, std::abs(std::hypot(local(1), local(2)) - 2 * a));
    EXPECT_NEAR(local(0), 0, 1e-12);
    worldSpread = std::max(worldSpread, std::abs(std::hypot(p[0] - obs[1], p[1] - obs[2]) - 2 * a));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(worldSpread, 0.1); // the world-chart picture is not a plain circle about the observer
}
} // namespace

namespace
{
// The closed-form route (the default for 'godel') against the same typed oracle.
TEST(NullGeodesicSource, ClosedFormRouteMatchesOracle)
{
  const double a = 0.8, maxAffine = 14.0, psiDeg = 60.0;
  const int n = 5;
  auto src = GodelSource(a);
  src->SetMethodToAuto();
  src->SetDirectionModeToCone();
  src->SetConeAxis(0, 0, 1);
  src->SetConeAngle(psiDeg);
  src->SetNumberOfRays(n);
  src->SetMaxAffine(maxAffine);
  src->Update();
  std::vector<GodelRay> expected;
  for (int i = 0; i < n; ++i)
    expected.push_back({ a, psiDeg * kPi / 180, Azimuth(2 * kPi * i / n) });
  CheckAgainstClosedForm(src->GetOutput(), expected, false, maxAffine);
}

// Observer off the axis: closed form through the isometry and numeric integration of the
// metric end at the same events.
TEST(NullGeodesicSource, ClosedFormAndNumericAgreeForObserverOffAxis)
{
  const double a = 1.0;
  vtkSmartPointer<vtkLightconeNullGeodesicSource> src[2];
  for (int m = 0; m < 2; ++m)
  {
    src[m] = GodelSource(a);
    src[m]->SetObserver(0.2, 0.5, -0.3, 0.1);
    src[m]->SetDirectionModeToCone();
    src[m]->SetConeAngle(70);
    src[m]->SetNumberOfRays(6);
    src[m]->SetMaxAffine(9.0);
    if (m == 0)
      src[m]->SetMethodToClosedForm();
    src[m]->Update();
  }
  vtkPolyData* cf = src[0]->GetOutput();
  vtkPolyData* nu = src[1]->GetOutput();
  ASSERT_EQ(cf->GetNumberOfCells(), 6);
  ASSERT_EQ(nu->GetNumberOfCells(), 6);
  vtkDataArray* tcf = cf->GetPointData()->GetArray("t");
  vtkDataArray* tnu = nu->GetPointData()->GetArray("t");
  for (vtkIdType c = 0; c < 6; ++c)
  {
    vtkNew<vtkIdList> a1, a2;
    cf->GetCellPoints(c, a1);
    nu->GetCellPoints(c, a2);
    const vtkIdType e1 = a1->GetId(a1->GetNumberOfIds() - 1), e2 = a2->GetId(a2->GetNumberOfIds() - 1);
    double p1[3], p2[3];
    cf->GetPoint(e1, p1);
    nu->GetPoint(e2, p2);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(p1[k], p2[k], 1e-8) << c;
    EXPECT_NEAR(tcf->GetComponent(e1, 0), tnu->GetComponent(e2, 0), 1e-8) << c;
  }
  vtkNew<vtkLightconeNullGeodesicSource> kerr;
  kerr->SetMetricName("kerr");
  kerr->SetMethodToClosedForm();
  kerr->SetObserver(0, 20, 0, 0);
  kerr->Update();
  EXPECT_EQ(kerr->GetOutput()->GetNumberOfPoints(), 0); // refused: no closed form there
}
} // namespace
