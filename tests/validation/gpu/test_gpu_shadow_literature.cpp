// SPDX-License-Identifier: BSD-3-Clause
// The validation cases on the GPU tracer (under Xvfb): lc::measureShadow's geometry with the
// edges found by the fragment-shader tracer (lc::views::gpuShadowEdges), against the closed forms
// and against the CPU's bisection. Single precision: the tolerances are what floats allow (the
// closing note and docs/PERFORMANCE.md give the errors measured).
#include "core/analysis/shadow.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "gpu_shadow_edges.hpp"
#include "tests/validation/ks_placement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace lc::validation {
namespace {

constexpr double kDeg = kPiV / 180;

double syngeRadius(double r) { return std::asin(3 * std::sqrt(3.0) * std::sqrt(1 - 2 / r) / r); }

Scene pointedAtTheHole(double a, double Q, double r, double theta) {
    Scene s;
    s.spacetime = std::make_shared<KerrNewman>(1, a, Q);
    const KsPlacement at(dynamic_cast<const KerrNewman&>(*s.spacetime), r, theta);
    s.observer = at.event;
    s.camera.forward = -at.basis[1].tail<3>();
    s.camera.up = -at.basis[2].tail<3>();
    return s;
}

void report(const char* what, double gpu, double cpu, double exact) {
    std::printf("%-44s GPU %.9g  CPU %.9g  closed form %.9g  GPU rel. error %.2e\n", what, gpu, cpu, exact,
                (gpu - exact) / exact);
}

TEST(GpuShadow, SchwarzschildOffTheEquatorIsCentredWithSyngesRadius) {
    for (const auto& [r, inc] : std::vector<std::pair<double, double>>{{6.0, 30}, {10.0, 60}, {50.0, 20}}) {
        Scene s;
        s.spacetime = std::make_shared<KerrNewman>(1, 0, 0);
        const double i = inc * kDeg;
        s.observer = Vec4(0, r * std::sin(i), 0, r * std::cos(i));
        s.camera.forward = Vec3(-std::sin(i), 0, -std::cos(i));
        s.camera.up = Vec3(-std::cos(i), 0, std::sin(i));
        const ShadowSize gpu = measureShadow(s, views::gpuShadowEdges(s));
        const ShadowSize cpu = measureShadow(s);
        const double alpha = syngeRadius(r) / kDeg;
        report(("Synge r " + std::to_string(r) + " i " + std::to_string(inc) + " width").c_str(), gpu.widthDegrees(),
               cpu.widthDegrees(), 2 * alpha);
        EXPECT_NEAR(gpu.widthDegrees(), 2 * alpha, 1e-5 * 2 * alpha);
        EXPECT_NEAR(gpu.heightDegrees, 2 * alpha, 1e-5 * 2 * alpha);
        EXPECT_NEAR(gpu.offsetDegrees(), 0, 1e-5 * alpha);
        EXPECT_NEAR(gpu.centreUpDegrees, 0, 1e-5 * alpha);
    }
}

// Inside the photon sphere a static observer's shadow is larger than a hemisphere: Synge's
// sin(alpha) = 3 sqrt(3) M sqrt(1 - 2M/r) / r with alpha = pi - asin(...) for r < 3 M. The GPU's
// strips span the great circle from the axis to its antipode, as the CPU's bisection does.
TEST(GpuShadow, StaticObserversInsideThePhotonSphereSeeMoreThanAHemisphere) {
    for (const double r : {2.5, 2.95}) {
        Scene s;
        s.spacetime = std::make_shared<KerrNewman>(1, 0, 0);
        s.observer = Vec4(0, r, 0, 0);
        s.camera.forward = Vec3(-1, 0, 0);
        s.camera.up = Vec3(0, 0, 1);
        const ShadowSize gpu = measureShadow(s, views::gpuShadowEdges(s));
        const double alpha = (kPiV - syngeRadius(r)) / kDeg;
        report(("Synge r " + std::to_string(r) + " width").c_str(), gpu.widthDegrees(), measureShadow(s).widthDegrees(),
               2 * alpha);
        EXPECT_GT(alpha, 90);
        EXPECT_NEAR(gpu.widthDegrees(), 2 * alpha, 1e-5 * 2 * alpha) << r;
        EXPECT_NEAR(gpu.heightDegrees, 2 * alpha, 1e-5 * 2 * alpha) << r;
    }
}

TEST(GpuShadow, KerrEdgesMatchTheCpuAndTheCriticalCurve) {
    for (const auto& [a, Q, r, th] : std::vector<std::array<double, 4>>{
             {0.9, 0, 10, 60}, {0.998, 0, 15, 85}, {0.998, 0, 200, 85}, {0.5, 0.5, 12, 45}}) {
        const Scene s = pointedAtTheHole(a, Q, r, th * kDeg);
        const ShadowSize gpu = measureShadow(s, views::gpuShadowEdges(s));
        const ShadowSize cpu = measureShadow(s);
        const OracleShadow want = oracleShadow(ObserverFrameBL(KerrNewmanBL{1, a, Q}, r, th * kDeg));
        const std::string name = "a " + std::to_string(a) + " Q " + std::to_string(Q) + " r " + std::to_string(r);
        report((name + " right").c_str(), gpu.rightDegrees, cpu.rightDegrees, want.right / kDeg);
        report((name + " left").c_str(), gpu.leftDegrees, cpu.leftDegrees, want.left / kDeg);
        report((name + " height").c_str(), gpu.heightDegrees, cpu.heightDegrees, want.height / kDeg);
        EXPECT_NEAR(gpu.rightDegrees * kDeg, want.right, 1e-5 * want.right) << name;
        EXPECT_NEAR(gpu.leftDegrees * kDeg, want.left, 1e-5 * want.left) << name;
        EXPECT_NEAR(gpu.heightDegrees * kDeg, want.height, 1e-5 * want.height) << name;
    }
}

// Far away the shadow is small and a float direction resolves it to about 1e-7 rad; a moving
// observer's rays start with momenta from 1/(2 gamma) to 2 gamma (rescaled by the tracer).
TEST(GpuShadow, FarAndMovingObservers) {
    {
        const Scene s = pointedAtTheHole(0.9, 0, 200, 60 * kDeg);
        const ShadowSize gpu = measureShadow(s, views::gpuShadowEdges(s));
        const OracleShadow want = oracleShadow(ObserverFrameBL(KerrNewmanBL{1, 0.9, 0}, 200, 60 * kDeg));
        report("a 0.9 r 200 width", gpu.widthDegrees(), measureShadow(s).widthDegrees(),
               (want.left + want.right) / kDeg);
        EXPECT_NEAR(gpu.widthDegrees() * kDeg, want.left + want.right, 1e-5 * (want.left + want.right));
        EXPECT_NEAR(gpu.heightDegrees * kDeg, want.height, 1e-5 * want.height);
    }
    for (double inward : {0.9, -0.5}) {
        Scene s = pointedAtTheHole(0, 0, 10, 70 * kDeg);
        const KsPlacement at(dynamic_cast<const KerrNewman&>(*s.spacetime), 10, 70 * kDeg);
        const ObserverFrameBL o(KerrNewmanBL{1, 0, 0}, 10, 70 * kDeg);
        s.observerVelocity = at.vector((o.e[0] - inward * o.e[1]) / std::sqrt(1 - inward * inward));
        const ShadowSize gpu = measureShadow(s, views::gpuShadowEdges(s));
        const double c = std::cos(syngeRadius(10));
        const double alpha = std::acos((c + inward) / (1 + inward * c)) / kDeg;
        report(("radial beta " + std::to_string(inward) + " width").c_str(), gpu.widthDegrees(),
               measureShadow(s).widthDegrees(), 2 * alpha);
        EXPECT_NEAR(gpu.widthDegrees(), 2 * alpha, 1e-5 * 2 * alpha);
        EXPECT_NEAR(gpu.heightDegrees, 2 * alpha, 1e-5 * 2 * alpha);
    }
}

}  // namespace
}  // namespace lc::validation
