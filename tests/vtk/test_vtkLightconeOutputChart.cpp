// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeOutputChart: one meaning of EMBEDDING, RPHIT and XYT for every source. Oracles:
// each source's own "t", "r", "phi"/"z" point arrays (the event in the metric's chart), and a
// circle traced many times (continuous azimuth grows past 2 pi instead of wrapping). The
// horizon's refusal of XYT is with the horizon's tests.
#include "vtkLightconeIsometryOrbitSource.h"
#include "vtkLightconeNullGeodesicSource.h"
#include "vtkLightconeOutputChart.h"
#include "vtkLightconeWorldLineSource.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>

TEST(OutputChart, CurveKeepsTheAzimuthContinuousAndMapsEachChart)
{
  vtkLightconeOutputChart::Curve rphit(vtkLightconeOutputChart::RPHIT);
  double p[3];
  const int n = 400;
  for (int k = 0; k <= n; ++k)
  {
    const double angle = 6 * lc::kPi * k / n; // three turns
    rphit.Map(lc::Vec4(0.1 * k, 2 * std::cos(angle), 2 * std::sin(angle), 5), p);
    EXPECT_NEAR(p[0], 2.0, 1e-12);
    EXPECT_NEAR(p[1], angle, 1e-9) << "k = " << k;
    EXPECT_DOUBLE_EQ(p[2], 0.1 * k);
  }
  vtkLightconeOutputChart::Curve xyt(vtkLightconeOutputChart::XYT),
    embedding(vtkLightconeOutputChart::EMBEDDING);
  xyt.Map(lc::Vec4(7, 1, 2, 3), p);
  EXPECT_EQ(p[0], 1);
  EXPECT_EQ(p[1], 2);
  EXPECT_EQ(p[2], 7);
  embedding.Map(lc::Vec4(7, 1, 2, 3), p);
  EXPECT_EQ(p[2], 3);
}

TEST(OutputChart, EverySourceWritesTheSameCharts)
{
  // The third coordinate is t in RPHIT and XYT, z in EMBEDDING; X, Y from r and phi.
  auto check = [](vtkPolyDataAlgorithm* src, int chart, const char* what) {
    src->Update();
    vtkPolyData* out = vtkPolyData::SafeDownCast(src->GetOutputDataObject(0));
    ASSERT_GT(out->GetNumberOfPoints(), 10) << what;
    vtkDataArray* t = out->GetPointData()->GetArray("t");
    ASSERT_NE(t, nullptr) << what;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); i += 7)
    {
      double p[3];
      out->GetPoint(i, p);
      if (chart != vtkLightconeOutputChart::EMBEDDING)
      {
        EXPECT_NEAR(p[2], t->GetComponent(i, 0), 1e-12) << what << " point " << i;
      }
      if (chart == vtkLightconeOutputChart::RPHIT)
      {
        vtkDataArray* r = out->GetPointData()->GetArray("r");
        ASSERT_NE(r, nullptr) << what;
        EXPECT_NEAR(p[0], r->GetComponent(i, 0), 1e-9) << what << " point " << i;
      }
    }
  };
  for (int chart : { vtkLightconeOutputChart::EMBEDDING, vtkLightconeOutputChart::RPHIT,
         vtkLightconeOutputChart::XYT })
  {
    SCOPED_TRACE(vtkLightconeOutputChart::GetName(chart));
    vtkNew<vtkLightconeNullGeodesicSource> rays;
    rays->SetNumberOfRays(4);
    rays->SetMaxAffine(8);
    rays->SetOutputChart(chart);
    check(rays, chart, "null geodesics");
    vtkNew<vtkLightconeWorldLineSource> line;
    line->SetOutputChart(chart);
    check(line, chart, "world line");
    vtkNew<vtkLightconeIsometryOrbitSource> orbit;
    vtkNew<vtkPoints> seeds;
    seeds->InsertNextPoint(0.7, 0.2, 0);
    orbit->SetSeeds(seeds);
    orbit->SetCoefficients(0, 1, 0, 0, 0); // rotation: a circle, phi continuous over the range
    orbit->SetFlowRange(0, 4 * lc::kPi);
    orbit->SetOutputChart(chart);
    check(orbit, chart, "isometry orbit");
  }
}
