// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeKillingFieldSource: the fields on a grid against the Killing equation
// (finite-difference Lie derivative of the Goedel metric), their norm and causal character
// against g(xi, xi), d/dt and d/dphi exactly, the combination as the sum of the five;
// invalid input is refused with an empty output.
#include "tests/vtk/filter_helpers.hpp"
#include "vtkLightconeKillingFieldSource.h"

#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace
{
using lc::test::ExpectRefused;
using lc::test::GodelMetric;
using lc::test::kInf;
using lc::test::kNaN;
using lc::test::PointArray;

// Partial derivatives of the Goedel metric in the Cartesian chart (central differences).
lc::Mat4 MetricDerivative(double a, const lc::Vec4& x, int rho)
{
  const double h = 1e-5;
  lc::Vec4 xp = x, xm = x;
  xp(rho) += h;
  xm(rho) -= h;
  return (GodelMetric(a, xp) - GodelMetric(a, xm)) / (2 * h);
}

// Killing field of a name read back from the grid: (t component, spatial vector).
lc::Vec4 FieldAt(vtkImageData* img, const std::string& name, vtkIdType id)
{
  vtkDataArray* v = img->GetPointData()->GetArray(name.c_str());
  vtkDataArray* t = img->GetPointData()->GetArray((name + "_t").c_str());
  EXPECT_TRUE(v && t) << name;
  if (!v || !t)
    return lc::Vec4::Zero();
  return lc::Vec4(
    t->GetComponent(id, 0), v->GetComponent(id, 0), v->GetComponent(id, 1), v->GetComponent(id, 2));
}

const char* kFieldNames[6] = { "xi_t", "xi_phi", "xi_z", "xi_4", "xi_5", "combination" };
} // namespace

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
    const lc::Mat4 g = GodelMetric(a, x);
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
      vtkDataArray* norm = PointArray(img, (std::string(name) + "_norm").c_str());
      vtkDataArray* causal = PointArray(img, (std::string(name) + "_causal").c_str());
      ASSERT_TRUE(norm && causal);
      EXPECT_NEAR(
        norm->GetComponent(centre, 0), std::sqrt(std::abs(gg)), 1e-12 * (1 + std::abs(gg)));
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
  vtkDataArray* phiCausal = PointArray(img, "xi_phi_causal");
  ASSERT_NE(phiCausal, nullptr);
  for (vtkIdType id = 0; id < img->GetNumberOfPoints(); ++id)
  {
    // d/dt exactly, unit (g_tt = 1).
    const lc::Vec4 xt = FieldAt(img, "xi_t", id);
    EXPECT_EQ(xt(0), 1.0);
    EXPECT_EQ(xt(1), 0.0);
    EXPECT_EQ(xt(2), 0.0);
    EXPECT_EQ(xt(3), 0.0);
    EXPECT_EQ(PointArray(img, "xi_t_norm")->GetComponent(id, 0), 1.0);
    EXPECT_EQ(PointArray(img, "xi_t_causal")->GetComponent(id, 0), 1.0);
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

TEST(KillingFieldSource, InvalidInputIsRefusedWithEmptyOutput)
{
  vtkNew<vtkLightconeKillingFieldSource> src;
  src->SetDimensions(5, 5, 2);
  auto empty = [&] { return src->GetOutput()->GetNumberOfPoints() == 0; };
  src->Update();
  ASSERT_EQ(src->GetOutput()->GetNumberOfPoints(), 50);

  src->SetTime(kNaN);
  ExpectRefused(src, empty, "GodelA or Time has a non-finite component");
  src->SetTime(0);
  src->SetSpacing(0.1, kInf, 0.1);
  ExpectRefused(src, empty, "Spacing");
  src->SetSpacing(0.1, 0.1, 0.1);
  src->SetOrigin(kNaN, 0, 0);
  ExpectRefused(src, empty, "Origin");
  src->SetOrigin(0, 0, 0);
  src->SetDimensions(5, -3, 2);
  ExpectRefused(src, empty, "Dimensions must be at least 1 each, got 5 x -3 x 2");
  src->SetDimensions(100000, 100000, 10);
  ExpectRefused(src, empty, "the grid would have 1e+11 points");

  src->SetDimensions(3, 3, 3);
  src->Update();
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 27);
}
