// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeWorldLineSource: Goedel free fall against the closed form of docs/PHYSICS.md
// section 2 (typed in here) moved by the isometry, with unit four-velocity; Minkowski constant
// velocity and the Goedel static observer; |beta| >= 1 is refused with an empty output.
#include "tests/common/vtk_event_counter.hpp"
#include "tests/vtk/filter_helpers.hpp"
#include "vtkLightconeWorldLineSource.h"

#include "core/godel/isometry.hpp"
#include "core/godel/proper_time_world_line.hpp"

#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>

namespace
{
using lc::kPi;
using lc::kSqrt2;
using lc::test::EventCounter;
using lc::test::GodelMetric;
using lc::test::PointArray;

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
    return std::atan(std::sqrt(2 * k0 * k0 / W()) * std::tan(th)) +
      kPi * std::floor(th / kPi + 0.5);
  }
  lc::Vec4 x(double tau) const
  {
    const double sg = k0 > 0 ? 1 : -1;
    const double rho = rMax() * std::sin(omega() * tau);
    const double ph = phi0 + sg * Phi(tau);
    return lc::Vec4(
      sg * 2 * kSqrt2 * a * Phi(tau) - k0 * tau, rho * std::cos(ph), rho * std::sin(ph), k3 * tau);
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
  for (const Case& cs :
    { Case{ 1.6, 0.3, 40.0 }, Case{ -2.0, -0.5, 200.0 }, Case{ 1.05, 0.1, -75.0 } })
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
    vtkDataArray* tau = PointArray(out, "tau");
    vtkDataArray* t = PointArray(out, "t");
    vtkDataArray* u = PointArray(out, "velocity");
    vtkDataArray* r = PointArray(out, "r");
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
      EXPECT_NEAR(v.dot(GodelMetric(a, x) * v), 1.0, 1e-10) << "tau " << tt;
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
  vtkDataArray* tau = PointArray(out, "tau");
  vtkDataArray* t = PointArray(out, "t");
  vtkDataArray* u = PointArray(out, "velocity");
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
    EXPECT_NEAR(PointArray(out, "t")->GetComponent(id, 0), 1 - 2 + 7.0 * id / 70, 1e-14);
  }
  // |beta| >= 1: error, empty output.
  EventCounter errors;
  errors.watch(src);
  src->SetModeToMinkowski();
  src->SetBeta(0.8, 0.7, 0);
  src->Update();
  EXPECT_EQ(errors.count, 1);
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 0);
}

// A traveller's trip (world line by proper time): the points are the trip's events, t runs back
// along the circle beyond the horizon, the velocity stays unit; without a trip the output is
// empty with an error.
TEST(WorldLineSource, GodelProperTimeFollowsTheTripBackInCoordinateTime)
{
  std::vector<lc::godel::WorldLineSegment> s(3);
  s[0].kind = lc::godel::WorldLineSegment::Kind::Radial, s[0].speed = 0.9, s[0].toRadius = 3;
  s[1].kind = lc::godel::WorldLineSegment::Kind::Circle, s[1].dtDphi = -0.8, s[1].turns = 1;
  s[2].kind = lc::godel::WorldLineSegment::Kind::Radial, s[2].speed = 0.9, s[2].toRadius = 0.5;
  const auto trip =
    std::make_shared<const lc::godel::ProperTimeWorldLine>(1.0, lc::Vec4(2, 0.5, 0, 0), s);
  vtkNew<vtkLightconeWorldLineSource> src;
  src->SetModeToGodelProperTime();
  EventCounter errors;
  errors.watch(src);
  src->Update();
  EXPECT_EQ(errors.count, 1);
  EXPECT_NE(errors.text.find("SetProperTimeWorldLine"), std::string::npos) << errors.text;
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 0);
  src->SetProperTimeWorldLine(trip);
  src->SetProperTimeRange(0, trip->duration());
  src->SetNumberOfSamples(500);
  src->Update();
  vtkPolyData* out = src->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 501);
  vtkDataArray* t = PointArray(out, "t");
  vtkDataArray* u = PointArray(out, "velocity");
  ASSERT_TRUE(t && u);
  double earliest = 1e9;
  for (vtkIdType id = 0; id <= 500; ++id)
  {
    const lc::Vec4 x = trip->position(trip->duration() * id / 500);
    double p[3];
    out->GetPoint(id, p);
    EXPECT_NEAR(p[0], x(1), 1e-13);
    EXPECT_NEAR(t->GetComponent(id, 0), x(0), 1e-13);
    lc::Vec4 v;
    for (int k = 0; k < 4; ++k)
      v(k) = u->GetComponent(id, k);
    EXPECT_NEAR(v.dot(GodelMetric(1.0, x) * v), 1.0, 1e-10);
    earliest = std::min(earliest, x(0));
  }
  // The circle's end: the leg out gains dt = 2a (asinh(1.5) - asinh(0.25)) / beta, one turn
  // at dt/dphi = -0.8 loses 0.8 * 2 pi; the samples, 0.02 of proper time apart with |dt/dtau|
  // up to gamma = 2.3, come within 0.05 of it.
  EXPECT_NEAR(
    earliest, 2 + 2 * (std::asinh(1.5) - std::asinh(0.25)) / 0.9 - 0.8 * 2 * lc::kPi, 0.05);
}

// NumberOfSamples is clamped to [1, INT_MAX] by its macro: at the top the cell's n + 1 overflowed
// and the loop never ended; a non-finite proper time range sampled NaN events. Both are refused
// before anything is allocated, the output left empty.
TEST(WorldLineSource, HugeSampleCountsAndNonFiniteRangesAreRefused)
{
  vtkNew<vtkLightconeWorldLineSource> src;
  src->SetModeToGodelRest();
  src->SetNumberOfSamples(VTK_INT_MAX);
  lc::test::ExpectRefused(
    src, [&] { return src->GetOutput()->GetNumberOfPoints() == 0; }, "the world line would have");
  src->SetNumberOfSamples(100);
  src->SetProperTimeRange(0, lc::test::kInf);
  lc::test::ExpectRefused(
    src, [&] { return src->GetOutput()->GetNumberOfPoints() == 0; }, "ProperTimeRange");
  src->SetProperTimeRange(0, 1);
  src->Update();
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 101);
}
