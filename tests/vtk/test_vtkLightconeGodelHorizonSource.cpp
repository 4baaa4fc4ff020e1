// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeGodelHorizonSource: the horizon against r = 2a, also for an observer off the
// axis (in its own chart, through the isometry), the light cone against the closed form of
// docs/PHYSICS.md section 2 (GodelRay in filter_helpers.hpp); invalid input is refused with
// empty outputs.
#include "tests/vtk/filter_helpers.hpp"
#include "vtkLightconeGodelHorizonSource.h"

#include "core/godel/isometry.hpp"

#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>

namespace
{
using lc::kPi;
using lc::test::ExpectRefused;
using lc::test::GodelRay;
using lc::test::kInf;
using lc::test::kNaN;
using lc::test::PointArray;
} // namespace

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

TEST(GodelHorizonSource, InvalidInputIsRefusedWithEmptyOutputs)
{
  vtkNew<vtkLightconeGodelHorizonSource> src;
  auto empty = [&] {
    return src->GetOutput(0)->GetNumberOfPoints() == 0 &&
      src->GetOutput(1)->GetNumberOfPoints() == 0;
  };
  src->Update();
  ASSERT_GT(
    src->GetOutput(0)->GetNumberOfPoints(), 0); // a good run first: nothing stale may remain

  src->SetObserver(0, kNaN, 0, 0);
  ExpectRefused(src, empty, "Observer has a non-finite component");
  src->SetObserver(0, 1e9, 0, 0); // beyond the isometries' accurate range (r <= 1e4 a)
  ExpectRefused(src, empty, "Observer lies at r = 1e+09 a");
  src->SetObserver(0, 0, 0, 0);
  src->SetZRange(-1, kInf);
  ExpectRefused(src, empty, "ZRange");
  src->SetZRange(-1, 1);
  src->SetLightConeAzimuth(kNaN);
  ExpectRefused(src, empty, "LightConeAzimuth");
  src->SetLightConeAzimuth(0);
  src->SetResolution(1 << 20);
  src->SetHeightResolution(1 << 20);
  ExpectRefused(src, empty, "the horizon would have");

  src->SetResolution(16);
  src->SetHeightResolution(2);
  src->Update();
  EXPECT_GT(src->GetOutput(0)->GetNumberOfPoints(), 0)
    << "a good setting after a refusal must work again";
}

// The horizon is drawn in EMBEDDING or RPHIT; the other OutputChart tests are in
// test_vtkLightconeOutputChart.cpp.
TEST(OutputChart, HorizonRefusesXYT)
{
  vtkNew<vtkLightconeGodelHorizonSource> src;
  src->SetOutputChartToXYT();
  ExpectRefused(
    src, [&] { return src->GetOutput(0)->GetNumberOfPoints() == 0; }, "OutputChart XYT");
}
