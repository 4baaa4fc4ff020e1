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

}  // namespace
