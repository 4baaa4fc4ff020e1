// Invalid input to the Goedel sources that had no such test: non-finite parameters, events
// beyond the isometries' range, resolutions past the point budget. Each is reported once as a
// VTK error naming the parameter, and the outputs are empty — also after a good run (no stale
// geometry), and the next good run works again.
#include "tests/common/vtk_event_counter.hpp"

#include "vtkLightconeGodelHorizonSource.h"
#include "vtkLightconeIsometryOrbitSource.h"
#include "vtkLightconeKillingFieldSource.h"

#include <vtkImageData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>

namespace
{
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// Runs `source` with a bad setting: one error naming `expected`, empty outputs `empty()`.
void ExpectRefused(vtkAlgorithm* source, const std::function<bool()>& empty, const char* expected)
{
  lc::testing::EventCounter errors;
  errors.watch(source);
  source->Update();
  EXPECT_EQ(errors.count, 1) << expected;
  EXPECT_NE(errors.text.find(expected), std::string::npos) << "the error does not name " << expected << ": " << errors.text;
  EXPECT_TRUE(empty()) << "output left after refusing " << expected;
}
} // namespace

TEST(GodelHorizonSource, InvalidInputIsRefusedWithEmptyOutputs)
{
  vtkNew<vtkLightconeGodelHorizonSource> src;
  auto empty = [&] {
    return src->GetOutput(0)->GetNumberOfPoints() == 0 && src->GetOutput(1)->GetNumberOfPoints() == 0;
  };
  src->Update();
  ASSERT_GT(src->GetOutput(0)->GetNumberOfPoints(), 0);  // a good run first: nothing stale may remain

  src->SetObserver(0, kNaN, 0, 0);
  ExpectRefused(src, empty, "Observer has a non-finite component");
  src->SetObserver(0, 1e9, 0, 0);  // beyond the isometries' accurate range (r <= 1e4 a)
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
  EXPECT_GT(src->GetOutput(0)->GetNumberOfPoints(), 0) << "a good setting after a refusal must work again";
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
