// SPDX-License-Identifier: BSD-3-Clause
// Shadow rays from a light anywhere. Oracles: flat (t, z) plane on the axis, backward numeric
// integration of the geodesic equation from the surface point to the light.
#include "core/godel/shadow.hpp"
#include "core/spacetime/integrator.hpp"
#include "core/metrics/godel.hpp"

#include <gtest/gtest.h>

using namespace lc;
using namespace lc::godel;

TEST(GodelShadow, LightBelowOnTheAxis) {
    const double a = 1.0;
    const ShadowTester T(a, Vec4(0, 0, 0, -1.0));
    ShadowOptions o;
    o.maxWinding = 0;
    const LightResult r = T.test(Vec3(0, 0, 0.5), {}, o);
    ASSERT_EQ(r.status, LightStatus::Lit);
    ASSERT_FALSE(r.rays.empty());
    const ShadowRay& s = r.rays[r.firstUnoccluded];
    EXPECT_FALSE(s.image.ring);
    EXPECT_LT((s.towardLight - Vec3(0, 0, -1)).norm(), 1e-12);
    EXPECT_NEAR(s.arrivalEvent(0), 1.5, 1e-12);  // flat along the axis: 1.5 later
    EXPECT_NEAR(s.image.lambda, 1.5, 1e-12);
}

TEST(GodelShadow, RaysReachTheLightByNumericIntegration) {
    const double a = 1.0;
    const GodelCartesian st(a);
    const Vec4 L(2.0, 0.7, -0.5, 0.4);
    const ShadowTester T(a, L);
    const Vec3 S(-0.3, 0.6, 0.9);
    const LightResult r = T.test(S);
    ASSERT_EQ(r.status, LightStatus::Lit);
    ASSERT_GE(r.rays.size(), 2u);
    for (const ShadowRay& s : r.rays) {
        EXPECT_LT((s.arrivalEvent.segment<3>(1) - S).norm(), 1e-10);
        EXPECT_GT(s.arrivalEvent(0), L(0));
        // Integrate back from the surface point (reverse the momentum) for lambda: it must end
        // at the light event.
        PhasePoint s0;
        s0.x = s.arrivalEvent;
        s0.p = -(st.metric(s.arrivalEvent) * s.tangentWorld);
        TraceOptions to;
        to.absTol = to.relTol = 1e-13;
        to.maxAffine = s.image.lambda;
        const TraceResult tr = traceGeodesic(st, s0, to);
        ASSERT_EQ(tr.reason, StopReason::MaxAffine);
        EXPECT_LT((tr.end.x - L).cwiseAbs().maxCoeff(), 1e-9);
        EXPECT_NEAR(s.towardLight.norm(), 1.0, 1e-12);
        // The reported direction is the spatial part of the reversed tangent seen in the
        // surface point's frame.
        const Isometry I = Isometry::movingToOrigin(a, s.arrivalEvent);
        const Vec4 back = I.pushForward(s.arrivalEvent, st.metric(s.arrivalEvent).inverse() * s0.p);
        EXPECT_LT((back.segment<3>(1).normalized() - s.towardLight).norm(), 1e-9);
    }
}

TEST(GodelShadow, SphereOnTheDirectRayCastsAShadow) {
    const double a = 1.0;
    const Vec4 L(0.0, 0.2, 0.1, 0.0);
    const ShadowTester T(a, L);
    const Vec3 S(0.5, 0.6, 0.3);
    ShadowOptions o;
    o.maxWinding = 0;
    const LightResult free = T.test(S, {}, o);
    ASSERT_EQ(free.rays.size(), 2u);
    // Put a small ball on the middle of the shorter ray, found by numeric integration from the
    // light (independent of the closed form).
    const GodelCartesian st(a);
    const ShadowRay& direct = free.rays[0];
    PhasePoint s0;
    s0.x = L;
    s0.p = -(st.metric(direct.arrivalEvent) * direct.tangentWorld);
    TraceOptions to;
    to.absTol = to.relTol = 1e-12;
    to.maxAffine = direct.image.lambda;
    const TraceResult back = traceGeodesic(st, {direct.arrivalEvent, s0.p}, [&] {
        TraceOptions t2 = to;
        t2.maxAffine = 0.5 * direct.image.lambda;
        return t2;
    }());
    const Vec3 mid = back.end.x.segment<3>(1);
    const LightResult blocked = T.test(S, sphereOccluder(mid, 0.02), o);
    ASSERT_EQ(blocked.rays.size(), 2u);
    EXPECT_TRUE(blocked.rays[0].occluded);
    EXPECT_FALSE(blocked.rays[1].occluded);  // the other branch goes round: still lit
    EXPECT_EQ(blocked.status, LightStatus::Lit);
    EXPECT_EQ(blocked.firstUnoccluded, 1);
    // Block both: shadowed.
    const Occluder both = [&](const Vec4& x0, const Vec4& x1) {
        return sphereOccluder(mid, 0.02)(x0, x1) || sphereOccluder(S, 0.05)(x0, x1);
    };
    ShadowOptions o2 = o;
    o2.endMargin = 0.0;
    EXPECT_EQ(T.test(S, both, o2).status, LightStatus::Shadowed);
    // A ball far away blocks nothing.
    EXPECT_EQ(T.test(S, sphereOccluder(Vec3(0, 0, 5), 0.5), o).firstUnoccluded, 0);
}

TEST(GodelShadow, LightBeyondTheHorizonIsReported) {
    const double a = 1.0;
    const ShadowTester T(a, Vec4(0, 1.5, 0, 0));
    LightResult r;
    EXPECT_NO_THROW(r = T.test(Vec3(-1.5, 0, 0.2)));
    EXPECT_EQ(r.status, LightStatus::BeyondHorizon);
    EXPECT_TRUE(r.rays.empty());
    EXPECT_FALSE(r.message.empty());
    EXPECT_FALSE(r.lit());
    EXPECT_EQ(T.test(Vec3(NAN, 0, 0)).status, LightStatus::InvalidInput);
}
