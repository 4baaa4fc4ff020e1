// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeKerrHorizonSource against the metric itself (lc::KerrNewman, the chart every Kerr
// tracer uses): a horizon is a null surface, so the gradient of the Boyer-Lindquist radius
// there is a null covector, g^{mu nu} d_mu r d_nu r = 0 (Delta = r^2 - 2Mr + a^2 + Q^2 = 0,
// MTW 33.3); an ergosurface is where g_tt = 0. Also extremal holes, Schwarzschild's single
// sphere r = 2M, the inner surfaces on request, and refused parameters.
#include "tests/vtk/filter_helpers.hpp"
#include "vtkLightconeKerrHorizonSource.h"

#include "core/metrics/kerr_newman.hpp"

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace
{
using lc::Vec4;

// The surface each point belongs to (the cells name it), by name.
std::map<vtkIdType, std::string> SurfaceOfPoints(vtkPolyData* pd)
{
  std::map<vtkIdType, std::string> out;
  auto* names = vtkStringArray::SafeDownCast(pd->GetCellData()->GetAbstractArray("surface_name"));
  EXPECT_NE(names, nullptr);
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    pd->GetCellPoints(c, n, ids);
    for (vtkIdType k = 0; k < n; ++k)
    {
      out[ids[k]] = names->GetValue(c);
    }
  }
  return out;
}

// g^{mu nu} d_mu r d_nu r at a point, r(x, y, z) differentiated centrally (r is static: d_t r = 0),
// divided by |grad r|^2 so that it is a relative figure.
double NullnessOfRadius(const lc::KerrNewman& hole, const Vec4& x)
{
  const double h = 1e-6;
  Vec4 grad = Vec4::Zero();
  for (int i = 1; i < 4; ++i)
  {
    Vec4 up = x, down = x;
    up(i) += h;
    down(i) -= h;
    grad(i) = (hole.radius(up(1), up(2), up(3)) - hole.radius(down(1), down(2), down(3))) / (2 * h);
  }
  return grad.dot(hole.inverseMetric(x) * grad) / grad.squaredNorm();
}

TEST(KerrHorizonSource, HorizonsAreNullSurfacesAndErgosurfacesWhereGttVanishes)
{
  const double M = 1, a = 0.7, Q = 0.3;
  const lc::KerrNewman hole(M, a, Q);
  vtkNew<vtkLightconeKerrHorizonSource> src;
  src->SetMass(M);
  src->SetSpin(a);
  src->SetCharge(Q);
  src->GenerateInnerSurfacesOn();
  src->Update();
  vtkPolyData* out = src->GetOutput();
  const auto surfaceOf = SurfaceOfPoints(out);
  std::set<std::string> seen;
  vtkDataArray* rA = lc::test::PointArray(out, "r");
  const double root = std::sqrt(M * M - a * a - Q * Q);
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    double q[3];
    out->GetPoint(p, q);
    const Vec4 x(0, q[0], q[1], q[2]);
    const std::string& name = surfaceOf.at(p);
    seen.insert(name);
    // The point lies where its "r" says (the chart's own radius function).
    EXPECT_NEAR(hole.radius(q[0], q[1], q[2]), rA->GetTuple1(p), 1e-12) << name;
    if (name == "outer_horizon" || name == "inner_horizon")
    {
      EXPECT_NEAR(rA->GetTuple1(p), name == "outer_horizon" ? M + root : M - root, 1e-14);
      if (std::abs(q[2]) < 0.999 * rA->GetTuple1(p)) // the poles' gradient is fine too, but
      { // the difference quotient there is not
        EXPECT_NEAR(NullnessOfRadius(hole, x), 0, 1e-7) << name << " at " << x.transpose();
      }
    }
    else
    {
      // 1e-10: the inner ergosurface's equator passes r = 0.046 M beside the ring, where the
      // chart's radius loses digits to x^2 + y^2 - a^2 (1.7e-12 seen).
      EXPECT_NEAR(hole.metric(x)(0, 0), 0, 1e-10) << name << " at " << x.transpose();
    }
  }
  EXPECT_EQ(seen,
    (std::set<std::string>{
      "outer_horizon", "inner_horizon", "ergosurface", "inner_ergosurface" }));
  // A closed surface per name: 32 x 64 cells each, quads and the polar triangles.
  EXPECT_EQ(out->GetNumberOfCells(), 4 * 32 * 64);
  // Just outside the outer horizon the radius's gradient is spacelike (g^rr = Delta/rho^2 < 0 in
  // (+,-,-,-)), inside between the horizons timelike: the test above can tell them apart.
  EXPECT_LT(NullnessOfRadius(hole, Vec4(0, 0, 0, M + root + 0.1)), -1e-3);
  EXPECT_GT(NullnessOfRadius(hole, Vec4(0, 0, 0, M)), 1e-3);
}

TEST(KerrHorizonSource, SchwarzschildHasOneSphereAndExtremalHolesOneHorizon)
{
  vtkNew<vtkLightconeKerrHorizonSource> src;
  src->SetMass(2);
  src->GenerateInnerSurfacesOn(); // r_- = 0: no inner surfaces to draw
  src->Update();
  for (vtkIdType p = 0; p < src->GetOutput()->GetNumberOfPoints(); ++p)
  {
    double q[3];
    src->GetOutput()->GetPoint(p, q);
    EXPECT_NEAR(std::hypot(q[0], q[1], q[2]), 4, 1e-12); // r = 2M for horizon and static limit
  }
  EXPECT_EQ(src->GetOutput()->GetNumberOfCells(), 2 * 32 * 64);

  src->SetMass(1);
  src->SetSpin(0.6);
  src->SetCharge(0.8); // a^2 + Q^2 = M^2: rounding makes M^2 - a^2 - Q^2 = -1.1e-16
  src->SetGenerateErgosurfaces(false);
  src->Update();
  vtkDataArray* rA = lc::test::PointArray(src->GetOutput(), "r");
  ASSERT_GT(rA->GetNumberOfTuples(), 0);
  for (vtkIdType p = 0; p < rA->GetNumberOfTuples(); ++p)
  {
    EXPECT_EQ(rA->GetTuple1(p), 1.0); // r_+ = r_- = M, both drawn
  }
  EXPECT_EQ(src->GetOutput()->GetNumberOfCells(), 2 * 32 * 64);
}

TEST(KerrHorizonSource, RefusesNakedSingularitiesAndNonFiniteParameters)
{
  vtkNew<vtkLightconeKerrHorizonSource> src;
  src->SetSpin(1.2);
  lc::test::ExpectRefused(
    src, [&] { return src->GetOutput()->GetNumberOfPoints() == 0; }, "accepted |a| <= 1");
  src->SetSpin(0.5);
  src->SetMass(lc::test::kNaN);
  lc::test::ExpectRefused(
    src, [&] { return src->GetOutput()->GetNumberOfPoints() == 0; }, "non-finite");
  src->SetMass(1);
  src->SetAzimuthResolution(100000);
  src->SetPolarResolution(100000);
  lc::test::ExpectRefused(
    src, [&] { return src->GetOutput()->GetNumberOfPoints() == 0; }, "the surfaces");
  std::ostringstream printed;
  src->Print(printed);
  EXPECT_NE(printed.str().find("Spin: 0.5"), std::string::npos) << printed.str();
}
} // namespace
