// SPDX-License-Identifier: BSD-3-Clause
// The fate of a Kerr-Newman ray from Carter's radial potential (core/analysis/radial_potential_fate)
// against the independent oracle of integrating the ray (dopri87 at 1e-12) from observers a user
// picks (inclined, inside the photon region, charged, moving, far), and against Synge's closed-form
// edge to rounding; where it cannot decide it says so.
#include "core/analysis/radial_potential_fate.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/spacetime/frame.hpp"
#include "core/spacetime/integrator.hpp"
#include "core/spacetime/named_observer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace lc;

namespace {

// Frame components of a chart vector v (its part in the observer's rest space): g(v, e_i).
Vec3 frameComponents(const Spacetime& st, const LocalFrame& frame, const Vec4& v) {
    const Mat4 g = st.metric(frame.x);
    Vec3 w;
    for (int i = 0; i < 3; ++i) w(i) = v.dot(g * frame.e[i + 1]) / frame.e[i + 1].dot(g * frame.e[i + 1]);
    return w;
}

TraceOptions fateTrace() {
    TraceOptions opt;
    opt.stepper = StepperKind::Dopri87;
    opt.absTol = opt.relTol = 1e-12;
    return opt;
}

}  // namespace

TEST(RadialPotentialFate, AgreesWithTheTracedRayFromEveryKindOfObserver) {
    struct Case {
        double a, Q, r, thetaDegrees;
        NamedObserver observer;
    };
    const Case cases[] = {{0.9, 0, 10, 60, NamedObserver::Static},  {0.998, 0, 3, 90, NamedObserver::Static},
                          {0.998, 0, 1.5, 85, NamedObserver::Zamo}, {0.6, 0.7, 5, 30, NamedObserver::Carter},
                          {0, 0, 2.5, 45, NamedObserver::Static},   {-0.9, 0, 4, 70, NamedObserver::FreeFall},
                          {0.9, 0, 1000, 80, NamedObserver::Static}};
    std::mt19937 engine(11);
    std::normal_distribution<double> gauss;
    int captured = 0, escaped = 0;
    for (const Case& c : cases) {
        const KerrNewman hole(1, c.a, c.Q);
        const double th = c.thetaDegrees * kPi / 180;
        // The Kerr-Schild Cartesian event of Boyer-Lindquist (r, theta, phi = 0): x = sqrt(r^2 + a^2) sin(theta).
        const Vec4 x(0, std::sqrt(c.r * c.r + c.a * c.a) * std::sin(th), 0, c.r * std::cos(th));
        ASSERT_NEAR(hole.radius(x(1), x(2), x(3)), c.r, 1e-12 * c.r);
        const LocalFrame frame = LocalFrame::withVelocity(hole, x, namedObserverVelocity(hole, x, c.observer));
        // Half the rays aimed near the hole, where the fates mix.
        for (int k = 0; k < 120; ++k) {
            Vec3 n(gauss(engine), gauss(engine), gauss(engine));
            if (k % 2) n = n.normalized() - 3 * frameComponents(hole, frame, Vec4(0, -x(1), -x(2), -x(3))).normalized();
            n.normalize();
            const Vec4 p = frame.pastNullMomentum(hole, n);
            const std::optional<RayFate> fate = radialPotentialFate(*hole.kerrNewmanParameters(), hole, x, p);
            ASSERT_TRUE(fate) << "a " << c.a << " r " << c.r << " n " << n.transpose();
            const StopReason traced = traceGeodesic(hole, PhasePoint{x, p}, fateTrace()).reason;
            ASSERT_TRUE(traced == StopReason::Horizon || traced == StopReason::Escaped) << static_cast<int>(traced);
            EXPECT_EQ(*fate == RayFate::Captured, traced == StopReason::Horizon)
                << "a " << c.a << " Q " << c.Q << " r " << c.r << " n " << n.transpose();
            (*fate == RayFate::Captured ? captured : escaped)++;
        }
    }
    EXPECT_GT(captured, 150);
    EXPECT_GT(escaped, 150);
}

// A static observer at r = 6 M beside Schwarzschild: rays within Synge's angle of the centre,
// sin(alpha) = 3 sqrt(3) M sqrt(1 - 2M/r) / r, fall in, rays beyond it escape: decided to 1e-12
// of the angle on both sides, where a traced ray would need to wind ~10 times to tell.
TEST(RadialPotentialFate, SyngesEdgeIsDecidedToRounding) {
    const KerrNewman hole(1, 0, 0);
    const double r = 6, alpha = std::asin(3 * std::sqrt(3.0) * std::sqrt(1 - 2 / r) / r);
    const Vec4 x(0, r, 0, 0);
    const LocalFrame frame = LocalFrame::withVelocity(hole, x, namedObserverVelocity(hole, x, NamedObserver::Static));
    const Vec3 inward = frameComponents(hole, frame, Vec4(0, -1, 0, 0)).normalized(), side(0, 0.6, 0.8);
    for (const double psi : {alpha * (1 - 1e-12), alpha * (1 + 1e-12)}) {
        const Vec3 n = std::cos(psi) * inward + std::sin(psi) * side;
        const auto fate = radialPotentialFate(*hole.kerrNewmanParameters(), hole, x, frame.pastNullMomentum(hole, n));
        ASSERT_TRUE(fate);
        EXPECT_EQ(*fate, psi < alpha ? RayFate::Captured : RayFate::Escapes) << psi - alpha;
    }
    // Undecided: on the axis (theta undefined) and inside the horizon.
    const Vec4 axis(0, 0, 0, 6), inside(0, 1.5, 0, 0);
    const LocalFrame onAxis =
        LocalFrame::withVelocity(hole, axis, namedObserverVelocity(hole, axis, NamedObserver::Static));
    EXPECT_FALSE(radialPotentialFate(*hole.kerrNewmanParameters(), hole, axis,
                                     onAxis.pastNullMomentum(hole, Vec3(0.3, 0, -1).normalized())));
    EXPECT_FALSE(radialPotentialFate(*hole.kerrNewmanParameters(), hole, inside, Vec4(-1, 0.5, 0.2, 0)));
}
