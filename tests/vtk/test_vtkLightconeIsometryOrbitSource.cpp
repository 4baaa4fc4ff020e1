// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeIsometryOrbitSource: a rotation orbit is a circle, a xi4 orbit keeps the norm
// g(xi, xi) and is tangent to the field, the xi4 orbit through the axis is Y = 2a sinh(s)
// (docs/PHYSICS.md section 4); invalid input is refused with an empty output.
#include "tests/vtk/filter_helpers.hpp"
#include "vtkLightconeIsometryOrbitSource.h"

#include "core/godel/isometry.hpp"

#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>

namespace
{
using lc::kPi;
using lc::test::ExpectRefused;
using lc::test::GodelMetric;
using lc::test::kInf;
using lc::test::kNaN;
using lc::test::PointArray;
} // namespace

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
  vtkDataArray* s = PointArray(out, "s");
  vtkDataArray* t = PointArray(out, "t");
  vtkDataArray* r = PointArray(out, "r");
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
    vtkDataArray* s = PointArray(out, "s");
    vtkDataArray* t = PointArray(out, "t");
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
      const double g0 = xi0.dot(GodelMetric(a, x0) * xi0);
      double moved = 0;
      for (vtkIdType i = 0; i <= n; ++i)
      {
        const lc::Vec4 x = event(first + i);
        const lc::Vec4 xi = field(x);
        const double gg = xi.dot(GodelMetric(a, x) * xi);
        EXPECT_NEAR(gg, g0, 1e-8 * std::max(1.0, std::abs(g0)))
          << "combo " << combo << " s " << s->GetComponent(first + i, 0);
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
  vtkDataArray* s = PointArray(out, "s");
  vtkDataArray* t = PointArray(out, "t");
  vtkDataArray* r = PointArray(out, "r");
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

TEST(IsometryOrbitSource, InvalidInputIsRefusedWithEmptyOutput)
{
  vtkNew<vtkLightconeIsometryOrbitSource> src;
  src->SetCoefficients(0, 0, 0, 1, 0);
  vtkNew<vtkPoints> seeds;
  seeds->InsertNextPoint(0.5, 0, 0);
  src->SetSeeds(seeds);
  auto empty = [&] { return src->GetOutput()->GetNumberOfPoints() == 0; };
  src->Update();
  ASSERT_GT(src->GetOutput()->GetNumberOfPoints(), 0);

  src->SetCoefficients(0, 0, 0, kNaN, 0);
  ExpectRefused(src, empty, "Coefficients has a non-finite component");
  src->SetCoefficients(0, 0, 0, 1, 0);
  src->SetFlowRange(-kInf, 1);
  ExpectRefused(src, empty, "FlowRange");
  src->SetFlowRange(-1, 1);
  src->SetSeedTime(kNaN);
  ExpectRefused(src, empty, "SeedTime");
  src->SetSeedTime(0);
  seeds->SetPoint(0, kNaN, 0, 0);
  seeds->Modified();
  ExpectRefused(src, empty, "a seed point has a non-finite component (nan) (seed 0)");
  seeds->SetPoint(0, 2e4, 0, 0);
  seeds->Modified();
  ExpectRefused(src, empty, "a seed point lies at r = 20000 a");
  seeds->SetPoint(0, 0.5, 0, 0);
  seeds->Modified();
  src->SetNumberOfSamples(1 << 30);
  ExpectRefused(src, empty, "the orbits would have");

  src->SetNumberOfSamples(64);
  src->Update();
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 65);
}
