// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeNullGeodesicSource: the Goedel rays of both routes (integrated, closed form)
// against the closed form of docs/PHYSICS.md section 2 (GodelRay in filter_helpers.hpp), the
// cylindrical and Cartesian charts against each other, pipeline re-execution, a bad metric name,
// XML round trip.
#include "tests/common/vtk_event_counter.hpp"
#include "tests/vtk/filter_helpers.hpp"
#include "vtkLightconeNullGeodesicSource.h"

#include <gtest/gtest.h>

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

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
using lc::kPi;
using lc::test::EventCounter;
using lc::test::GodelRay;
using lc::test::PointArray;

// The sources start the continuous azimuth in (-pi, pi]: give phi0 there (Azimuth()).
double Azimuth(double phi0)
{
  return std::atan2(std::sin(phi0), std::cos(phi0));
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
void CheckAgainstClosedForm(
  vtkPolyData* out, const std::vector<GodelRay>& expected, bool rphit, double maxAffine)
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
  dirs->InsertNextPoint(
    3 * std::sin(psi) * std::cos(phi0), 3 * std::sin(psi) * std::sin(phi0), 3 * std::cos(psi));
  auto src = GodelSource(a);
  src->SetDirectionModeToList();
  src->SetDirections(dirs);
  src->SetMaxAffine(maxAffine);
  src->Update();
  CheckAgainstClosedForm(src->GetOutput(), { { a, psi, phi0 } }, false, maxAffine);

  // Editing the directions in place re-executes the source (GetMTime includes them).
  const vtkIdType before = src->GetOutput()->GetNumberOfPoints();
  dirs->SetPoint(0, 0, 0, 1); // along the axis: a straight line, few steps
  dirs->Modified(); // VTK convention: SetPoint does not touch the MTime
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
  counter.watch(src, vtkCommand::EndEvent);

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

// By default a ray of an asymptotically flat metric is drawn until it escapes or meets the
// horizon (it once stopped every Kerr ray at affine length 20, "max_affine"). Oracle: a static
// observer at r = 30 M in Schwarzschild sees a ray at angle psi from the hole with impact
// parameter b = r sin(psi) / sqrt(1 - 2M/r); it falls in when b < 3 sqrt(3) M (psi < 9.63 deg).
TEST(NullGeodesicSource, DefaultsDrawFlatAtInfinityRaysUntilTheyEscapeOrMeetTheHorizon)
{
  const double r = 30, psiCritical = std::asin(3 * std::sqrt(3.0) * std::sqrt(1 - 2 / r) / r);
  vtkNew<vtkPoints> dirs;
  dirs->SetDataTypeToDouble();
  const std::vector<double> psiDeg{ 2, 5, 8, 9.4, 9.9, 11, 20, 60, 120, 170 };
  for (double deg : psiDeg)
  {
    const double psi = deg * kPi / 180;
    dirs->InsertNextPoint(-std::cos(psi), std::sin(psi), 0);
  }
  vtkNew<vtkLightconeNullGeodesicSource> src;
  src->SetMetricName("schwarzschild");
  src->SetObserver(0, r, 0, 0);
  src->SetDirectionModeToList();
  src->SetDirections(dirs);
  EXPECT_EQ(src->GetMaxAffine(), 0.0);
  src->Update();
  vtkPolyData* out = src->GetOutput();
  auto* names =
    vtkStringArray::SafeDownCast(out->GetCellData()->GetAbstractArray("stop_reason_name"));
  ASSERT_NE(names, nullptr);
  const auto rays = Rays(out);
  ASSERT_EQ(rays.size(), psiDeg.size());
  for (std::size_t i = 0; i < rays.size(); ++i)
  {
    const bool captured = psiDeg[i] * kPi / 180 < psiCritical;
    EXPECT_EQ(names->GetValue(static_cast<vtkIdType>(i)), captured ? "horizon" : "escaped")
      << "psi " << psiDeg[i] << " deg";
    if (!captured)
    { // drawn out past twice the observer's distance
      double end[3];
      out->GetPoint(rays[i].back(), end);
      EXPECT_GT(std::hypot(end[0], end[1], end[2]), 2 * r) << "psi " << psiDeg[i] << " deg";
    }
  }
  // A given MaxAffine draws every ray to it, escaping or not.
  src->SetMaxAffine(20);
  src->Update();
  auto* after = vtkStringArray::SafeDownCast(
    src->GetOutput()->GetCellData()->GetAbstractArray("stop_reason_name"));
  EXPECT_EQ(after->GetValue(static_cast<vtkIdType>(psiDeg.size() - 1)), "max_affine");
}

TEST(NullGeodesicSource, BadMetricNameReportsError)
{
  auto src = GodelSource(1.0);
  src->SetMetricName("no-such-metric");
  EventCounter errors;
  errors.watch(src);
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
    const vtkIdType e1 = a1->GetId(a1->GetNumberOfIds() - 1),
                    e2 = a2->GetId(a2->GetNumberOfIds() - 1);
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

namespace
{
// Counts past what a source may make are refused before the work (closed form: known ahead) or
// as soon as the numeric rays pass it, the output left empty: a closed-form Goedel ray to affine
// length 1e9 once overflowed the int of its sample count.
TEST(NullGeodesicSource, PointCountsPastTheLimitAreRefused)
{
  auto src = GodelSource(1.0);
  src->SetMethodToClosedForm();
  src->SetMaxAffine(1e9);
  lc::test::ExpectRefused(
    src, [&] { return src->GetOutput()->GetNumberOfPoints() == 0; }, "the rays would have");
  src->SetMaxAffine(10);
  src->SetNumberOfRays(VTK_INT_MAX);
  lc::test::ExpectRefused(
    src, [&] { return src->GetOutput()->GetNumberOfPoints() == 0; }, "the rays would have");
  src->SetNumberOfRays(8);
  src->Update();
  EXPECT_GT(src->GetOutput()->GetNumberOfPoints(), 8);
}
} // namespace
