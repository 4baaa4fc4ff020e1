// SPDX-License-Identifier: BSD-3-Clause
// The tolerance means what it says: on every hard case of tests/common/hard_rays.hpp (warp walls
// with sigma from 8 to 200 and v from 0.5 to 5, a photon-sphere grazer, a ray from 10^10 M,
// Kerr a = 0.998 turning just outside the horizon, a Goedel ray over ten windings), every adaptive
// stepper's error relative to the independent reference is at most 1e-8 at tolerance 1e-12 and
// 1e-9 at 1e-14 (docs/PHYSICS.md section 7; docs/PERFORMANCE.md has the work-precision table).
#include "tests/common/hard_rays.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace lc;

namespace {

const std::vector<std::string> kAdaptiveSteppers{"cash_karp54", "dopri5", "dopri87", "bulirsch_stoer"};

class ToleranceConvergence : public ::testing::TestWithParam<std::string> {};

TEST_P(ToleranceConvergence, ErrorFollowsTheToleranceOnEveryHardCase) {
    const StepperKind stepper = parseStepper(GetParam());
    for (const test::HardRay& ray : test::hardRays()) {
        const double at12 = ray.relativeError(test::hardRayOptions(stepper, 1e-12));
        const double at14 = ray.relativeError(test::hardRayOptions(stepper, 1e-14));
        std::printf("%-16s %-60s %.2e %.2e\n", GetParam().c_str(), ray.name.c_str(), at12, at14);
        EXPECT_LE(at12, 1e-8) << ray.name << " at tolerance 1e-12";
        EXPECT_LE(at14, 1e-9) << ray.name << " at tolerance 1e-14";
    }
}

INSTANTIATE_TEST_SUITE_P(AdaptiveSteppers, ToleranceConvergence, ::testing::ValuesIn(kAdaptiveSteppers),
                         [](const auto& stepperParam) { return stepperParam.param; });

TEST(HardRayOracles, MatchIndependentEvaluations) {
    // Schwarzschild b = 10: 0.5903957876058273 (mpmath, docs/PHYSICS.md section 7); Kerr a = 0.998's
    // prograde photon turning at r = 1.2 has L = 2.2103791996357257 and winds 19.58538867100802 rad
    // (mpmath at 30 digits of the same integral, an independent evaluation).
    EXPECT_NEAR(test::kerrEquatorialDeflection(0, 10).alpha, 0.5903957876058273, 1e-14);
    const double L = test::kerrEquatorialAngularMomentum(0.998, 1.2, +1);
    EXPECT_NEAR(L, 2.2103791996357257, 1e-13);
    EXPECT_NEAR(test::kerrEquatorialDeflection(0.998, L).alpha, 19.58538867100802, 1e-11);
    EXPECT_TRUE(std::isnan(test::kerrEquatorialDeflection(0.998, 2.0).alpha));  // captured
    // A bubble at rest (v = 0) is flat: light moves at 1, t(xi) = -xi.
    EXPECT_NEAR(test::alcubierreAxisTime(0, 1, 35, -3), 3, 1e-14);
    // Deep inside (f = 1) the photon moves at -1 in xi for any v; across the wall (mpmath, 30 digits).
    EXPECT_NEAR(test::alcubierreAxisTime(5, 1, 200, -0.5), 0.5, 1e-13);
    EXPECT_NEAR(test::alcubierreAxisTime(5, 1, 200, -3), 1.3296005011057748854, 1e-14);
}

}  // namespace
