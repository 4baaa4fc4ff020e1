// SPDX-License-Identifier: BSD-3-Clause
// The render's error estimate (core/render/error_estimate) against a high-accuracy integration of
// the same sampled rays (tolerance 1e-13, an escape test 1e-6 of a pixel): the estimated error of
// the escape directions is within a factor of 10 of the true one, at loose and tight tolerances,
// for a static observer beside Schwarzschild and an inclined one beside Kerr a = 0.9.
#include "core/metrics/kerr_newman.hpp"
#include "core/render/error_estimate.hpp"
#include "core/render/render.hpp"
#include "core/scene/frame_camera.hpp"
#include "tests/common/test_camera.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace lc;

namespace {

Scene besideHole(double a, const Vec4& observer, StepperKind stepper, double tolerance) {
    Scene s;
    s.spacetime = std::make_shared<KerrNewman>(1.0, a, 0.0);
    s.observer = observer;
    s.camera = test::testCamera(Camera::Projection::Pinhole, 160, 80, 70, 35, -observer.tail<3>(), Vec3(0, 0, 1));
    s.settings.method = RenderSettings::Method::Numeric;
    s.settings.trace.stepper = stepper;
    s.settings.trace.absTol = s.settings.trace.relTol = tolerance;
    return s;
}

// The true error of each sampled ray's escape direction, in pixels.
double trueWorstPixels(const Scene& s, const RenderErrorEstimate& e) {
    const Spacetime& st = *s.spacetime;
    const LocalFrame frame = observerFrame(s);
    const Camera cam = frameCamera(s.camera, st, frame);
    const TraceOptions opt = traceOptionsFor(s);
    TraceOptions exact = opt;
    exact.absTol = exact.relTol = 1e-13;
    exact.stepper = StepperKind::Dopri87;
    const double pixel = std::min(cam.fovXDeg / cam.width, cam.fovYDeg / cam.height) * kPi / 180;
    exact.escapeAngle = 1e-6 * pixel;
    double worst = 0;
    for (const auto& [i, j] : e.pixels) {
        PhasePoint start{s.observer, frame.pastNullMomentum(st, cam.direction(i, j))};
        start.p /= std::abs(start.p(0));
        const TraceResult a = traceGeodesic(st, start, opt), b = traceGeodesic(st, start, exact);
        EXPECT_EQ(b.reason, StopReason::Escaped);
        const Vec3 da = (st.inverseMetric(a.end.x) * a.end.p).tail<3>().normalized();
        const Vec3 db = (st.inverseMetric(b.end.x) * b.end.p).tail<3>().normalized();
        worst = std::max(worst, std::atan2(da.cross(db).norm(), da.dot(db)) / pixel);
    }
    return worst;
}

TEST(RenderErrorEstimate, WithinAFactorOfTenOfAHighAccuracyIntegration) {
    struct Case {
        double a;
        Vec4 observer;
        StepperKind stepper;
        double tolerance;
    };
    for (const Case& c :
         {Case{0, Vec4(0, 20, 0, 0), StepperKind::Dopri5, 1e-5}, Case{0, Vec4(0, 20, 0, 0), StepperKind::Dopri5, 1e-8},
          Case{0.9, Vec4(0, 12, 0, 9), StepperKind::Dopri5, 1e-6},
          Case{0.9, Vec4(0, 12, 0, 9), StepperKind::CashKarp54, 1e-7}}) {
        const Scene s = besideHole(c.a, c.observer, c.stepper, c.tolerance);
        const RenderErrorEstimate e = estimateRenderError(s);
        ASSERT_GT(e.errorPixels.size(), 30u);
        const double truth = trueWorstPixels(s, e);
        std::printf("| a %.1f %s tol %.0e | estimated %.2e px | true %.2e px |\n", c.a, stepperName(c.stepper).c_str(),
                    c.tolerance, e.maxPixels(), truth);
        EXPECT_GT(e.maxPixels(), truth / 10) << c.tolerance;
        EXPECT_LT(e.maxPixels(), truth * 10) << c.tolerance;
    }
}

TEST(RenderErrorEstimate, NoneForClosedFormsAndFixedSteps) {
    Scene s = besideHole(0, Vec4(0, 20, 0, 0), StepperKind::RK4, 1e-6);
    EXPECT_TRUE(estimateRenderError(s).errorPixels.empty());
    EXPECT_TRUE(std::isnan(estimateRenderError(s).maxPixels()));
}

}  // namespace
