// World lines by proper time and the time machine (core/godel/proper_time_world_line.hpp,
// docs/PHYSICS.md section 11). Oracles: the metric itself (g(u, u) = 1 at every sample), the
// closed-form coordinate times of each leg, the closed-form null geodesic of each image (the
// emission event on the observer's past light cone) and a dense brute-force scan of the light-cone
// function for the image count.
#include "core/godel/images.hpp"
#include "core/godel/proper_time_world_line.hpp"
#include "core/metrics/godel.hpp"
#include "core/render/photo_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace lc {
namespace {

using godel::ProperTimeWorldLine;
using godel::WorldLineSegment;
using K = WorldLineSegment::Kind;

std::vector<WorldLineSegment> timeMachine(double wait = 12, double after = 15) {
    std::vector<WorldLineSegment> s(5);
    s[0].kind = K::Rest, s[0].properTime = wait;
    s[1].kind = K::Radial, s[1].speed = 0.9, s[1].toRadius = 3;
    s[2].kind = K::Circle, s[2].dtDphi = -0.8, s[2].turns = 2.25;
    s[3].kind = K::Radial, s[3].speed = 0.9, s[3].toRadius = 0.5;
    s[4].kind = K::Rest, s[4].properTime = after;
    return s;
}

TEST(ProperTimeWorldLine, TimeMachineIsTimelikeAndReturnsEarlierInCoordinateTime) {
    const ProperTimeWorldLine trip(1.0, Vec4(-12, 0.5, 0, 0), timeMachine());
    const GodelCartesian g(1.0);
    const int n = 20000;
    double worst = 0;
    for (int i = 0; i <= n; ++i) {
        const double tau = trip.duration() * i / n;
        const Vec4 x = trip.position(tau), u = trip.velocity(tau);
        worst = std::max(worst, std::abs(u.dot(g.metric(x) * u) - 1));
        EXPECT_GT((g.metric(x) * u)(0), 0) << "future-directed at tau " << tau;
        if (i > 0 && i < n) {  // the velocity is the derivative of the position (inside pieces)
            const double h = 1e-6;
            const Vec4 d = (trip.position(tau + h) - trip.position(tau - h)) / (2 * h);
            if ((trip.velocity(tau + h) - trip.velocity(tau - h)).norm() < 1e-3) {
                EXPECT_LT((d - u).norm(), 1e-6);
            }
        }
    }
    EXPECT_LT(worst, 1e-12);
    // Closed forms per leg: radial at beta from r0 to r1: dtau = 2a |asinh(r1/2a) - asinh(r0/2a)| / (gamma beta),
    // dt = gamma dtau; the circle: dt = dt_dphi * 2 pi turns.
    const double gamma = 1 / std::sqrt(1 - 0.81), radialTau = 2 * (std::asinh(1.5) - std::asinh(0.25)) / (gamma * 0.9);
    const auto j = trip.junctions();
    ASSERT_EQ(j.size(), 5u);
    const double depart = trip.position(j[1].tau)(0), back = trip.position(j[4].tau)(0);
    EXPECT_NEAR(depart, 0, 1e-12);
    EXPECT_NEAR(back - depart, 2 * gamma * radialTau - 0.8 * 2 * kPi * 2.25, 1e-10);
    EXPECT_LT(back, depart - 7);  // 7.10 a before it left
    // It comes back to r = 0.5 a a quarter turn on.
    const Vec4 home = trip.position(j[4].tau);
    EXPECT_NEAR(home(1), 0, 1e-10);
    EXPECT_NEAR(home(2), 0.5, 1e-10);
    EXPECT_GT(j[2].jumpGamma, 1);  // the burns between legs are impulsive
}

TEST(ProperTimeWorldLine, RefusesSegmentsThatAreNotFutureTimelikeNamingThem) {
    auto message = [](std::vector<WorldLineSegment> s, Vec4 start = Vec4(0, 0.5, 0, 0)) {
        try {
            ProperTimeWorldLine(1.0, start, std::move(s));
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    // Inside the horizon a circle cannot run back in time: with dt/dphi < 0 it is past-directed.
    std::vector<WorldLineSegment> inside(1);
    inside[0].kind = K::Circle, inside[0].dtDphi = -0.8, inside[0].turns = 1;
    EXPECT_NE(message(inside).find("world line segment 0 (circle): past-directed"), std::string::npos)
        << message(inside);
    // A pure rotation (dt = 0) inside 2a is spacelike.
    inside[0].dtDphi = 0;
    EXPECT_NE(message(inside).find("not timelike"), std::string::npos) << message(inside);
    // ... and beyond 2a it is a closed timelike curve.
    EXPECT_EQ(message(inside, Vec4(0, 3, 0, 0)), "");
    std::vector<WorldLineSegment> radial(2);
    radial[0].kind = K::Rest, radial[0].properTime = 1;
    radial[1].kind = K::Radial, radial[1].speed = 1, radial[1].toRadius = 2;
    EXPECT_NE(message(radial).find("world line segment 1 (radial): speed"), std::string::npos);
    radial[1].speed = 0.5;
    EXPECT_NE(message(radial, Vec4::Zero()).find("starts on the axis"), std::string::npos);
}

// The observer on the axis at t = -3 and the traveller of data/godel_time_traveller.json.
Scene travellerScene(const std::vector<WorldLineSegment>& segments, const Vec4& observer) {
    Scene s;
    s.spacetime = std::make_shared<GodelCartesian>(1.0);
    s.observer = observer;
    SphereObject t;
    t.name = "traveller";
    t.centre = Vec4(-12, 0.5, 0, 0);
    t.radius = 0.12;
    t.motion.kind = Motion::Kind::ProperTime;
    t.motion.properTimeLine = std::make_shared<const ProperTimeWorldLine>(1.0, t.centre, segments);
    s.spheres.push_back(t);
    return s;
}

// Sign changes of each slot's light-cone function t_image(x(tau)) - x^0(tau), tau sampled densely.
int bruteForceCount(const Scene& s, int maxWinding) {
    const auto& line = *s.spheres[0].motion.properTimeLine;
    const godel::ImageSolver solver(1.0);
    const godel::Isometry toObserver = godel::Isometry::movingToOrigin(1.0, s.observer);
    godel::ImageOptions opt;
    opt.maxWinding = maxWinding;
    int count = 0;
    for (int n = 0; n <= maxWinding; ++n)
        for (int b = 0; b < 2; ++b) {
            std::optional<double> previous;
            const int samples = 200000;
            for (int i = 0; i <= samples; ++i) {
                const Vec4 x = toObserver.apply(line.position(line.duration() * i / samples));
                std::optional<godel::Image> out[2];
                solver.solveWinding(solver.prepare(x.segment<3>(1)), n, opt, out);
                std::optional<double> f;
                if (out[b]) f = out[b]->emissionTime - x(0);
                if (f && previous && ((*f > 0) != (*previous > 0))) ++count;
                previous = f;
            }
        }
    return count;
}

TEST(ProperTimeWorldLine, EveryImageOfTheTravellerIsOnTheLightConeAndTheCountMatchesABruteForceScan) {
    const Scene early = travellerScene(timeMachine(), Vec4(-3, 0, 0, 0));
    const auto images = imagesOfMovingCentre(early, early.spheres[0], 0);
    // Two ages at once: the younger traveller waiting (tau < 12) and the older one back
    // (tau > 32), each seen twice (the outbound and inbound images of one winding).
    ASSERT_EQ(images.size(), 4u);
    int young = 0, old = 0;
    for (const auto& mi : images) young += mi.tau<12, old += mi.tau> 32;
    EXPECT_EQ(young, 2);
    EXPECT_EQ(old, 2);
    const godel::Isometry toObserver = godel::Isometry::movingToOrigin(1.0, early.observer);
    for (const auto& mi : images) {
        // On the world line, and reached by the closed-form null geodesic of the image.
        EXPECT_LT((toObserver.apply(early.spheres[0].motion.properTimeLine->position(mi.tau)) -
                   toObserver.apply(toObserver.inverse().apply(mi.image.event)))
                      .norm(),
                  1e-10);
        const Vec4 reached = mi.image.ray(1.0).cartesian(mi.image.lambda);
        EXPECT_LT((reached - mi.image.event).norm(), 1e-10) << "tau " << mi.tau;
    }
    for (double t : {-11.0, -8.0, -5.0, -3.0, -0.5, 0.2, 3.0})
        for (int w : {0, 1}) {
            const Scene s = travellerScene(timeMachine(), Vec4(t, 0, 0, 0));
            EXPECT_EQ(static_cast<int>(imagesOfMovingCentre(s, s.spheres[0], w).size()), bruteForceCount(s, w))
                << "observer at t = " << t << ", windings " << w;
        }
}

TEST(ProperTimeWorldLine, ATripInsideTheHorizonNeverShowsTwoAgesAtOnce) {
    std::vector<WorldLineSegment> s(5);
    s[0].kind = K::Rest, s[0].properTime = 12;
    s[1].kind = K::Radial, s[1].speed = 0.9, s[1].toRadius = 1.5;
    s[2].kind = K::Circle, s[2].dtDphi = 2, s[2].turns = 1;  // future-directed inside 2a: t grows
    s[3].kind = K::Radial, s[3].speed = 0.9, s[3].toRadius = 0.5;
    s[4].kind = K::Rest, s[4].properTime = 15;
    for (double t = -11; t <= 20; t += 1.5) {
        const Scene scene = travellerScene(s, Vec4(t, 0, 0, 0));
        const auto images = imagesOfMovingCentre(scene, scene.spheres[0], 0);
        int outbound = 0, inbound = 0;
        for (const auto& mi : images) (mi.image.branch == godel::Branch::Inbound ? inbound : outbound)++;
        EXPECT_LE(outbound, 1) << "t = " << t;
        EXPECT_LE(inbound, 1) << "t = " << t;
    }
}

}  // namespace
}  // namespace lc
