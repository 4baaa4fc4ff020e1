// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeCurvatureAlongPath: the Kretschmann scalar along a light ray that grazes a Kerr hole
// (vtkLightconeNullGeodesicSource's output) against the closed form of Henry (2000),
// K = 48 M^2 (r^6 - 15 a^2 r^4 c^2 + 15 a^4 r^2 c^4 - a^6 c^6) / (r^2 + a^2 c^2)^6, c = cos(theta),
// at every point; the singular point NaN and counted; the input passed through; and every
// invalid setting refused with an empty output.
#include "tests/vtk/filter_helpers.hpp"
#include "vtkLightconeCurvatureAlongPath.h"
#include "vtkLightconeNullGeodesicSource.h"

#include "core/metrics/kerr_newman.hpp"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>
#include <memory>

namespace
{
using lc::test::ExpectRefused;
using lc::test::PointArray;

double KerrKretschmann(double M, double a, double r, double c)
{
  const double r2 = r * r, a2c2 = a * a * c * c;
  return 48 * M * M *
    (r2 * r2 * r2 - 15 * a * a * r2 * r2 * c * c + 15 * a2c2 * a * a * r2 * c * c -
      a2c2 * a2c2 * a2c2) /
    std::pow(r2 + a2c2, 6);
}

// A polyline through the given events (t, x, y, z) with their times in "t".
vtkSmartPointer<vtkPolyData> Path(const std::vector<lc::Vec4>& events)
{
  auto path = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> t;
  t->SetName("t");
  vtkNew<vtkCellArray> line;
  line->InsertNextCell(static_cast<vtkIdType>(events.size()));
  for (const lc::Vec4& e : events)
  {
    line->InsertCellPoint(points->InsertNextPoint(e(1), e(2), e(3)));
    t->InsertNextValue(e(0));
  }
  path->SetPoints(points);
  path->SetLines(line);
  path->GetPointData()->AddArray(t);
  return path;
}
} // namespace

TEST(CurvatureAlongPath, KerrRayMeetsHenrysKretschmannAtEveryPoint)
{
  const double M = 1, a = 0.9;
  auto kerr = std::make_shared<lc::KerrNewman>(M, a, 0.0);
  vtkNew<vtkLightconeNullGeodesicSource> ray;
  ray->SetSpacetime(kerr);
  ray->SetObserver(0, 20, 0, 4);
  ray->SetDirectionModeToList();
  vtkNew<vtkPoints> direction;
  direction->InsertNextPoint(-1, 0.2, -0.15); // passes the hole at a few M, off the equator
  ray->SetDirections(direction);
  vtkNew<vtkLightconeCurvatureAlongPath> along;
  along->SetInputConnection(ray->GetOutputPort());
  along->SetSpacetime(kerr);
  along->Update();
  vtkPolyData* out = along->GetOutput();
  ASSERT_GT(out->GetNumberOfPoints(), 20);
  EXPECT_EQ(out->GetNumberOfCells(), ray->GetOutput()->GetNumberOfCells()); // passed through
  EXPECT_NE(out->GetPointData()->GetArray("affine"), nullptr);
  vtkDataArray* K = PointArray(out, "kretschmann");
  ASSERT_NE(K, nullptr);
  EXPECT_STREQ(out->GetPointData()->GetScalars()->GetName(), "kretschmann");
  double largest = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    const double r = kerr->radius(p[0], p[1], p[2]);
    const double expected = KerrKretschmann(M, a, r, p[2] / r);
    EXPECT_NEAR(K->GetTuple1(i), expected, 1e-9 * std::abs(expected) + 1e-14) << "r = " << r;
    largest = std::max(largest, K->GetTuple1(i));
  }
  EXPECT_GT(largest, 0.01); // it came close: K(20 M) is 3e-7
}

TEST(CurvatureAlongPath, SingularEventIsNaNAndCounted)
{
  vtkNew<vtkLightconeCurvatureAlongPath> along;
  along->SetSpacetime(std::make_shared<lc::KerrNewman>(1.0, 0.0, 0.0));
  along->SetInputData(Path({ lc::Vec4(0, 3, 0, 0), lc::Vec4(1, 0, 0, 0), lc::Vec4(2, 0, 4, 0) }));
  along->Update();
  vtkDataArray* K = PointArray(along->GetOutput(), "kretschmann");
  ASSERT_NE(K, nullptr);
  EXPECT_NEAR(K->GetTuple1(0), 48.0 / std::pow(3.0, 6), 1e-12);
  EXPECT_TRUE(std::isnan(K->GetTuple1(1)));
  EXPECT_NEAR(K->GetTuple1(2), 48.0 / std::pow(4.0, 6), 1e-12);
  EXPECT_EQ(along->GetOutput()->GetFieldData()->GetArray("singular_points")->GetTuple1(0), 1);
}

TEST(CurvatureAlongPath, InvalidSettingsAreRefusedWithAnEmptyOutput)
{
  const auto path = Path({ lc::Vec4(0, 5, 0, 0), lc::Vec4(1, 6, 0, 0) });
  vtkNew<vtkLightconeCurvatureAlongPath> along;
  along->SetInputData(path);
  auto empty = [&] { return along->GetOutput()->GetNumberOfPoints() == 0; };
  ExpectRefused(along, empty, "SetSpacetime");
  along->SetSpacetime(std::make_shared<lc::KerrNewman>(1.0, 0.5, 0.0));
  along->SetQuantity("curliness");
  ExpectRefused(along, empty, "curliness");
  along->SetQuantity("tidal_eigenvalues");
  along->SetTimeArrayName("time");
  ExpectRefused(along, empty, "'time'");
  along->SetTimeArrayName("t");
  along->Update();
  ASSERT_EQ(along->GetOutput()->GetNumberOfPoints(), 2);
  EXPECT_EQ(PointArray(along->GetOutput(), "tidal_eigenvalues")->GetNumberOfComponents(), 3);
}
