// SPDX-License-Identifier: BSD-3-Clause
// Shadow measurement (core/analysis/shadow) against Bardeen's edge-on widths and the
// Schwarzschild shadow 3 sqrt 3 M, seen from far away; and its refusals.
#include "core/analysis/shadow.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace lc;

namespace {

Scene blackHoleFrom(double distance, double spin) {
    Scene s;
    s.spacetime = std::make_shared<KerrNewman>(1.0, spin, 0.0);
    s.observer = Vec4(0, distance, 0, 0);
    s.camera.forward = Vec3(-1, 0, 0);
    s.camera.up = Vec3(0, 0, 1);
    return s;
}

TEST(Shadow, BardeenWidthFormulaMatchesTheKnownValuesAndItsSchwarzschildLimit) {
    EXPECT_NEAR(bardeenEdgeOnWidth(1, 0.9), 9.676740633922840, 1e-12);  // docs/PHYSICS.md section 6
    EXPECT_NEAR(bardeenEdgeOnWidth(1, 0), 6 * std::sqrt(3.0), 1e-15);
    EXPECT_NEAR(bardeenEdgeOnWidth(1, 1e-6), 6 * std::sqrt(3.0), 1e-5);     // continuous at a -> 0
    EXPECT_NEAR(bardeenEdgeOnWidth(2, 1.8), 2 * 9.676740633922840, 1e-11);  // scales with M
}

TEST(Shadow, MeasuredFromFarAwayMatchesBardeenAndSchwarzschild) {
    const double D = 1e5;
    const ShadowSize schwarzschild = measureShadow(blackHoleFrom(D, 0));
    EXPECT_NEAR(schwarzschild.widthImpact(D), 6 * std::sqrt(3.0), 2e-3);  // O(M/D) corrections
    EXPECT_NEAR(schwarzschild.offsetDegrees(), 0, 1e-7);
    EXPECT_NEAR(schwarzschild.heightDegrees, schwarzschild.widthDegrees(), 1e-7);  // round
    const ShadowSize kerr = measureShadow(blackHoleFrom(D, 0.9));
    EXPECT_NEAR(kerr.widthImpact(D), bardeenEdgeOnWidth(1, 0.9), 2e-3);
    // The spin shifts the shadow sideways by about 2 M (Bardeen: centre at b = 1.99 M for a = 0.9).
    EXPECT_NEAR(std::abs(kerr.offsetDegrees()) * kPi / 180 * D, 0.5 * (6.8323 - 2.8445), 2e-3);
    // The height through the centre is 3 sqrt 3 M wide at most (less off the widest chord).
    EXPECT_LT(kerr.heightDegrees * kPi / 180 * D, 6 * std::sqrt(3.0) + 1e-3);
}

TEST(Shadow, RefusesSpacetimesWithoutAShadowAndCamerasLookingAway) {
    Scene godel;
    godel.spacetime = std::make_shared<GodelCartesian>(1.0);
    EXPECT_THROW(measureShadow(godel), std::invalid_argument);
    Scene away = blackHoleFrom(30, 0.5);
    away.camera.forward = Vec3(1, 0, 0);
    EXPECT_THROW(measureShadow(away), std::invalid_argument);
}

// Kerr whose rays are traced: the radial potential's fates withheld (as for a metric typed as text).
class TracedKerr final : public KerrNewman {
public:
    TracedKerr(double mass, double spin) : KerrNewman(mass, spin, 0.0) {}
    std::optional<KerrNewmanParameters> kerrNewmanParameters() const override { return std::nullopt; }
};

// A scene's "stepper": "auto" (the default) traces shadow edges with dopri87 (only the rays' fates
// count; docs/SCENES.md), a named stepper with itself: auto's figures are dopri87's to the bit and
// not dopri5's, though all agree to the edges' estimated error. A built-in hole's fates come from
// its radial potential, so every stepper gives its figures to the bit, within the traced ones' error.
TEST(Shadow, AutoStepperTracesTheEdgesWithDopri87) {
    Scene s = blackHoleFrom(30, 0.9);
    s.spacetime = std::make_shared<TracedKerr>(1.0, 0.9);
    // Holding the constants of motion makes the two steppers' fates agree to the bit here: without
    // it their last brackets differ, which shows which stepper ran.
    s.settings.trace.holdConstants = false;
    EXPECT_TRUE(s.settings.autoStepper);
    EXPECT_EQ(sceneStepperName(s.settings), "auto");
    const ShadowSize automatic = measureShadow(s);
    setSceneStepper(s.settings, "dopri87");
    EXPECT_EQ(sceneStepperName(s.settings), "dopri87");
    const ShadowSize dopri87 = measureShadow(s);
    setSceneStepper(s.settings, "dopri5");
    const ShadowSize dopri5 = measureShadow(s);
    auto figures = [](const ShadowSize& m) {
        return std::vector<double>{m.centreUpDegrees, m.leftDegrees, m.rightDegrees, m.heightDegrees,
                                   m.edgeErrorDegrees};
    };
    EXPECT_EQ(figures(automatic), figures(dopri87));
    EXPECT_NE(figures(automatic), figures(dopri5));  // the last brackets' fates differ somewhere
    EXPECT_NEAR(automatic.rightDegrees, dopri5.rightDegrees, automatic.edgeErrorDegrees + dopri5.edgeErrorDegrees);
    EXPECT_THROW(setSceneStepper(s.settings, "fehlberg78"), std::invalid_argument);

    Scene builtIn = blackHoleFrom(30, 0.9);
    const ShadowSize potential = measureShadow(builtIn);
    setSceneStepper(builtIn.settings, "dopri5");
    EXPECT_EQ(figures(measureShadow(builtIn)), figures(potential));
    EXPECT_NEAR(potential.rightDegrees, automatic.rightDegrees,
                automatic.edgeErrorDegrees + potential.edgeErrorDegrees);
    EXPECT_NEAR(potential.leftDegrees, automatic.leftDegrees, automatic.edgeErrorDegrees + potential.edgeErrorDegrees);
}

}  // namespace
