// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeCurvatureSource: a Schwarzschild slice against 48 M^2 / r^6 (the singular point
// NaN and counted), Goedel's matter read with and without Lambda against Goedel's density, a
// formula metric through SetSpacetime (de Sitter: K = 24 H^4), re-execution on a change, and
// every invalid setting refused with an empty output.
#include "tests/vtk/filter_helpers.hpp"
#include "vtkLightconeCurvatureSource.h"

#include "core/formula/formula_metric.hpp"

#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <cmath>

namespace
{
using lc::test::ExpectRefused;
using lc::test::kInf;
using lc::test::kNaN;
using lc::test::PointArray;

vtkIdType FieldCount(vtkImageData* img, const char* name)
{
  vtkDataArray* a = img->GetFieldData()->GetArray(name);
  EXPECT_NE(a, nullptr) << name;
  return a ? static_cast<vtkIdType>(a->GetTuple1(0)) : -1;
}
} // namespace

TEST(CurvatureSource, SchwarzschildSliceIsFortyEightMSquaredOverRToTheSixth)
{
  const double M = 1.5;
  vtkNew<vtkLightconeCurvatureSource> src;
  src->SetMetricName("schwarzschild");
  src->SetMetricParameter("M", M);
  src->SetOrigin(-6, -6, 0.0);
  src->SetSpacing(0.5, 0.75, 1);
  src->SetDimensions(25, 17, 1); // (12, 8) is the origin: the singularity
  src->AddQuantity("kretschmann");
  src->AddQuantity("tidal_eigenvalues");
  src->Update();
  vtkImageData* img = src->GetOutput();
  ASSERT_EQ(img->GetNumberOfPoints(), 25 * 17);
  vtkDataArray* K = PointArray(img, "kretschmann");
  vtkDataArray* tides = PointArray(img, "tidal_eigenvalues");
  ASSERT_TRUE(K && tides);
  EXPECT_EQ(tides->GetNumberOfComponents(), 3);
  EXPECT_STREQ(img->GetPointData()->GetScalars()->GetName(), "kretschmann");
  EXPECT_EQ(FieldCount(img, "singular_points"), 1);
  for (vtkIdType id = 0; id < img->GetNumberOfPoints(); ++id)
  {
    double p[3];
    img->GetPoint(id, p);
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (r == 0)
    {
      EXPECT_TRUE(std::isnan(K->GetTuple1(id)));
      continue;
    }
    EXPECT_NEAR(K->GetTuple1(id) / (48 * M * M / std::pow(r, 6)), 1, 1e-10) << "r = " << r;
    if (r > 2 * M) // static observers: -2M/r^3 radially (MTW eq. 31.4b)
    {
      EXPECT_NEAR(tides->GetComponent(id, 0) / (-2 * M / std::pow(r, 3)), 1, 1e-9);
    }
  }
}

// Goedel (Goedel 1949): dust of density 1/(8 pi a^2) with Lambda = -1/(2 a^2); without Lambda
// the same Einstein tensor reads as a stiff fluid of density 1/(16 pi a^2). Everywhere, also
// beyond the horizon r = 2a.
TEST(CurvatureSource, GoedelMatterWithAndWithoutTheCosmologicalConstant)
{
  const double a = 0.8;
  vtkNew<vtkLightconeCurvatureSource> src;
  src->SetMetricName("godel");
  src->SetMetricParameter("a", a);
  src->SetOrigin(-2.5, -2.5, 0.3);
  src->SetSpacing(0.5, 0.5, 1);
  src->SetDimensions(11, 11, 1);
  src->AddQuantity("energy_density");
  src->AddQuantity("principal_pressures");
  src->AddQuantity("hawking_ellis_type");
  src->SetCosmologicalConstant(-1 / (2 * a * a));
  src->Update();
  vtkDataArray* rho = PointArray(src->GetOutput(), "energy_density");
  vtkDataArray* p = PointArray(src->GetOutput(), "principal_pressures");
  vtkDataArray* type = PointArray(src->GetOutput(), "hawking_ellis_type");
  ASSERT_TRUE(rho && p && type);
  for (vtkIdType id = 0; id < rho->GetNumberOfTuples(); ++id)
  {
    EXPECT_NEAR(rho->GetTuple1(id) * 8 * lc::kPi * a * a, 1, 1e-10);
    EXPECT_NEAR(p->GetComponent(id, 2) * 8 * lc::kPi * a * a, 0, 1e-10);
    EXPECT_EQ(type->GetTuple1(id), 1.0);
  }
  src->SetCosmologicalConstant(0); // re-executes
  src->Update();
  rho = PointArray(src->GetOutput(), "energy_density");
  p = PointArray(src->GetOutput(), "principal_pressures");
  ASSERT_TRUE(rho && p);
  EXPECT_NEAR(rho->GetTuple1(60) * 16 * lc::kPi * a * a, 1, 1e-10);
  EXPECT_NEAR(p->GetComponent(60, 0) * 16 * lc::kPi * a * a, 1, 1e-10);
}

TEST(CurvatureSource, FormulaMetricThroughSetSpacetime)
{
  lc::formula::FormulaMetricSource s;
  s.lineElement = lc::formula::FormulaText{ "ds2", "-dt^2 + exp(2*H*t)*(dx^2 + dy^2 + dz^2)" };
  s.parameters = { { "H", 1, 1e-6, 1e6, "" } };
  const double H = 0.4;
  vtkNew<vtkLightconeCurvatureSource> src;
  src->SetSpacetime(
    std::make_shared<lc::formula::FormulaMetric>(s, std::map<std::string, double>{ { "H", H } }));
  src->SetDimensions(4, 3, 2);
  src->SetOrigin(-1, -1, -1);
  src->SetTime(0.7);
  src->AddQuantity("kretschmann");
  src->AddQuantity("ricci_scalar");
  src->Update();
  vtkDataArray* K = PointArray(src->GetOutput(), "kretschmann");
  vtkDataArray* R = PointArray(src->GetOutput(), "ricci_scalar");
  ASSERT_TRUE(K && R);
  for (vtkIdType id = 0; id < K->GetNumberOfTuples(); ++id)
  {
    EXPECT_NEAR(K->GetTuple1(id) / (24 * std::pow(H, 4)), 1, 1e-12);
    EXPECT_NEAR(R->GetTuple1(id) / (-12 * H * H), 1, 1e-12);
  }
}

TEST(CurvatureSource, RefusesInvalidInputWithAnEmptyOutput)
{
  auto check = [](const std::function<void(vtkLightconeCurvatureSource*)>& spoil,
                 const char* expected) {
    vtkNew<vtkLightconeCurvatureSource> src;
    src->SetDimensions(5, 5, 1);
    spoil(src);
    ExpectRefused(
      src, [&] { return src->GetOutput()->GetNumberOfPoints() == 0; }, expected);
  };
  check(
    [](vtkLightconeCurvatureSource* s) { s->AddQuantity("curvature"); }, "'curvature' is unknown");
  check([](vtkLightconeCurvatureSource* s) { s->SetDimensions(0, 5, 1); }, "Dimensions");
  check([](vtkLightconeCurvatureSource* s) { s->SetOrigin(kNaN, 0, 0); }, "Origin");
  check([](vtkLightconeCurvatureSource* s) { s->SetSpacing(1, kInf, 1); }, "Spacing");
  check([](vtkLightconeCurvatureSource* s) { s->SetCosmologicalConstant(kNaN); },
    "CosmologicalConstant");
  check([](vtkLightconeCurvatureSource* s) { s->SetMetricName("wormhole"); }, "wormhole");
  check([](vtkLightconeCurvatureSource* s) { s->SetMetricParameter("M", -1); }, "M");
  check(
    [](vtkLightconeCurvatureSource* s) {
      s->SetDimensions(2000, 2000, 2000);
      s->AddQuantity("tidal_eigenvalues");
    },
    "points x quantity components");
}
