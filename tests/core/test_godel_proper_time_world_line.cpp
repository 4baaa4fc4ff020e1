// SPDX-License-Identifier: BSD-3-Clause
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

#include <chrono>
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

// A trip of 8000 a is searched only where the observer can see it (a few tens of a), and the
// search still finds every crossing of the light cone the brute-force scan of the whole trip finds,
// also for observers off the axis and above the trip's plane (issue #47).
TEST(ProperTimeWorldLine, ALongTripIsSearchedOnlyWhereItCanBeSeenAndLosesNoImage) {
    for (const Vec4& observer : {Vec4(-3, 0, 0, 0), Vec4(3990, 0.3, -0.2, 1.5), Vec4(-3, 0.2, 0.1, -2)})
        for (int w : {0, 1}) {
            const Scene s = travellerScene(timeMachine(4000, 4000), observer);
            const double trip = s.spheres[0].motion.properTimeLine->duration();
            ASSERT_GT(trip, 8000);
            double searched = 0;
            for (const auto& span : movingCentre(s, s.spheres[0], w).window.spans)
                searched += span.tauMax - span.tauMin;
            EXPECT_LT(searched, 300) << "of a trip of " << trip;
            EXPECT_EQ(static_cast<int>(imagesOfMovingCentre(s, s.spheres[0], w).size()), bruteForceCount(s, w))
                << "observer " << observer.transpose() << ", windings " << w;
        }
}

// Every leg at its range's maximum builds and is searched in bounded time (the guard is a hang
// detector, not a speed claim: bench/ measures speed), or is refused with the rule it breaks.
TEST(ProperTimeWorldLine, LegsAtTheirRangeMaximaEndQuicklyOrAreRefusedWithTheRule) {
    const auto start = std::chrono::steady_clock::now();
    auto trip = [](std::vector<WorldLineSegment> legs) {
        std::vector<WorldLineSegment> all(1);
        all[0].kind = K::Rest, all[0].properTime = 1;
        all.insert(all.end(), legs.begin(), legs.end());
        return travellerScene(all, Vec4(-3, 0, 0, 0));
    };
    WorldLineSegment rest, turns, fast, far, burn;
    rest.kind = K::Rest, rest.properTime = 1e6 - 2;
    turns.kind = K::Circle, turns.dtDphi = -0.8, turns.turns = 1e4;
    fast.kind = K::Radial, fast.speed = 0.99999999, fast.toRadius = 1.5;
    far.kind = K::Radial, far.speed = 0.9, far.toRadius = 1e4;
    burn.kind = K::Rocket, burn.acceleration = 1e-6, burn.properTime = 250, burn.thrust = WorldLineSegment::Thrust::Up;
    WorldLineSegment out = far;
    out.toRadius = 3;
    for (const Scene& s : {trip({rest}), trip({out, turns}), trip({fast}), trip({far}), trip({burn})})
        EXPECT_NO_THROW(imagesOfMovingCentre(s, s.spheres[0], 1));
    // A circle 1e-9 inside the timelike limit at r = 0.5 a: k^2 + 2 g_tphi k + g_phiphi = 0 at k*.
    const double gtphi = 0.25 / kSqrt2, gphiphi = -0.25 * (1 - 0.25 / 4);
    WorldLineSegment edge;
    edge.kind = K::Circle, edge.turns = 1;
    edge.dtDphi = (-2 * gtphi + std::sqrt(4 * gtphi * gtphi - 4 * gphiphi)) / 2 * (1 + 1e-9);
    EXPECT_NO_THROW(trip({edge}));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60);

    // Burns each within 250 but 1e9 samples in all (1000 legs of 250): refused past 1000 in all.
    const std::vector<WorldLineSegment> burns(5, burn);
    try {
        trip(burns);
        ADD_FAILURE() << "five burns of 250";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("the trip's rocket burns add up to 1250, beyond 1000"), std::string::npos)
            << e.what();
    }

    WorldLineSegment tooLong = rest, tooFast = burn, longBurn = burn;
    tooLong.properTime = 1e6;
    tooFast.acceleration = 1000, tooFast.properTime = 1;
    longBurn.properTime = 251;
    EXPECT_THROW(
        {
            try {
                trip({tooLong});
            } catch (const std::invalid_argument& e) {
                EXPECT_NE(std::string(e.what()).find("the trip's proper time reaches 1e+06, beyond 1e+06"),
                          std::string::npos)
                    << e.what();
                throw;
            }
        },
        std::invalid_argument);
    for (const auto& [leg, rule] : {std::pair{tooFast, std::string("passes the Lorentz factor 7071.07")},
                                    std::pair{longBurn, std::string("is longer than 250")}})
        try {
            trip({leg});
            ADD_FAILURE() << rule;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(rule), std::string::npos) << e.what();
        }
}

// 1000 windings of the traveller on a 100 x 200 sphere once asked for 14 GB of photo-object layers
// (8008 layers of 19802 vertices); it is refused before any is built, saying how much and why.
TEST(ProperTimeWorldLine, PhotoObjectsTooLargeForMemoryAreRefusedBeforeTheyAreBuilt) {
    Scene s = travellerScene(timeMachine(), Vec4(-3, 0, 0, 0));
    PhotoSceneOptions opt = photoSceneOptions(s);
    opt.maxWinding = 1000;
    opt.latitudes = 100, opt.longitudes = 200;
    const auto start = std::chrono::steady_clock::now();
    try {
        buildPhotoScene(s, opt);
        ADD_FAILURE() << "built 14 GB of layers";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(
            std::string(e.what()).find("8008 layers (windings 1000, 4 crossings each) of 19802 vertices, about 1"),
            std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("fewer windings or a coarser render.mesh_resolution"), std::string::npos);
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10);
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

namespace lc {
namespace {

// A rocket burn: its 4-acceleration a = du/dtau + Gamma u u, from finite differences of the world
// line and Christoffel symbols of the metric's derivatives (not the Hamiltonian form the burn is
// integrated in), has the burn's magnitude, is orthogonal to u and points along the thrust.
TEST(ProperTimeWorldLine, RocketBurnHasItsProperAccelerationAlongTheThrust) {
    std::vector<WorldLineSegment> s(2);
    s[0].kind = K::Rocket, s[0].acceleration = 1.5, s[0].properTime = 1.2,
    s[0].thrust = WorldLineSegment::Thrust::Outward;
    s[1].kind = K::Rocket, s[1].acceleration = 0.7, s[1].properTime = 2,
    s[1].thrust = WorldLineSegment::Thrust::Prograde;
    const ProperTimeWorldLine line(1.0, Vec4(0, 0.4, 0.1, 0.2), s);
    const GodelCartesian g(1.0);
    for (double tau : {0.3, 0.7, 1.0, 1.6, 2.5, 3.0}) {
        // Fourth-order differences of the positions (the interpolated velocity's own derivative is
        // only piecewise linear): truncation h^4, rounding 1e-16 / h^2.
        const double h = 1e-3;
        const Vec4 x = line.position(tau), p1 = line.position(tau + h), m1 = line.position(tau - h),
                   p2 = line.position(tau + 2 * h), m2 = line.position(tau - 2 * h);
        const Vec4 u = (-p2 + 8 * p1 - 8 * m1 + m2) / (12 * h);
        const Vec4 du = (-p2 + 16 * p1 - 30 * x + 16 * m1 - m2) / (12 * h * h);
        Mat4 m;
        std::array<Mat4, 4> dg;
        g.metricAndDerivatives(x, m, dg);
        const Mat4 mi = m.inverse();
        Vec4 acc = du;
        for (int mu = 0; mu < 4; ++mu)
            for (int al = 0; al < 4; ++al)
                for (int be = 0; be < 4; ++be) {
                    double gamma = 0;
                    for (int nu = 0; nu < 4; ++nu)
                        gamma += 0.5 * mi(mu, nu) * (dg[al](nu, be) + dg[be](nu, al) - dg[nu](al, be));
                    acc(mu) += gamma * u(al) * u(be);
                }
        const double expected = tau < 1.2 ? 1.5 : 0.7;
        EXPECT_NEAR(std::sqrt(-acc.dot(m * acc)), expected, 2e-5) << "tau " << tau;
        EXPECT_NEAR(acc.dot(m * u), 0, 2e-5) << "tau " << tau;
        const Vec4 v = line.velocity(tau);
        EXPECT_NEAR(v.dot(m * v), 1, 1e-12) << "tau " << tau;
        EXPECT_LT((v - u).norm(), 1e-5) << "tau " << tau;
        // Along the thrust: outward (the chart's radial direction), then prograde (about the axis).
        const double r = std::hypot(x(1), x(2));
        const Vec4 thrust = tau < 1.2 ? Vec4(0, x(1) / r, x(2) / r, 0) : Vec4(0, -x(2) / r, x(1) / r, 0);
        EXPECT_LT(acc.dot(m * thrust), 0) << "tau " << tau;  // g(a, d) < 0: a points along d (spacelike)
    }
}

// A burn of vanishing acceleration is the free fall of the closed form (section 2 moved by an
// isometry): the integration against the geodesic, to the burn's own effect a tau^2 / 2.
TEST(ProperTimeWorldLine, FeebleRocketFollowsTheClosedFormFreeFall) {
    std::vector<WorldLineSegment> kick(2), rocket, fall;
    kick[0].kind = K::Rest, kick[0].properTime = 0.5;
    kick[1].kind = K::Radial, kick[1].speed = 0.6, kick[1].toRadius = 1.0;
    rocket = fall = kick;
    WorldLineSegment r;
    r.kind = K::Rocket, r.acceleration = 1e-7, r.properTime = 3;
    WorldLineSegment f;
    f.kind = K::FreeFall, f.properTime = 3;
    rocket.push_back(r);
    fall.push_back(f);
    const ProperTimeWorldLine a(1.0, Vec4(0, 0.3, 0, 0), rocket), b(1.0, Vec4(0, 0.3, 0, 0), fall);
    for (double tau = a.junctions()[2].tau; tau <= a.duration(); tau += 0.25)
        EXPECT_LT((a.position(tau) - b.position(tau)).norm(), 1e-6) << "tau " << tau;
}

}  // namespace
}  // namespace lc

namespace lc {
namespace {

// Samples of x(tau): a circle beyond the horizon sampled from its closed form is the same world
// line (to the chords' sagitta); a chord whose proper times disagree with its proper length, or
// that is spacelike, is refused naming the chord.
TEST(ProperTimeWorldLine, SamplesFollowTheEventsAndRefuseInconsistentProperTimes) {
    std::vector<WorldLineSegment> circle(1);
    circle[0].kind = K::Circle, circle[0].dtDphi = -0.8, circle[0].turns = 0.25;
    const ProperTimeWorldLine exact(1.0, Vec4(0, 3, 0, 0), circle);
    WorldLineSegment sampled;
    sampled.kind = K::Samples;
    const int n = 2000;
    for (int i = 0; i <= n; ++i) {
        const double tau = exact.duration() * i / n;
        sampled.samples.emplace_back(tau, exact.position(tau));
    }
    const ProperTimeWorldLine line(1.0, Vec4(0, 3, 0, 0), {sampled});
    EXPECT_NEAR(line.duration(), exact.duration(), 1e-12);
    for (double f : {0.1, 0.37, 0.5, 0.93}) {
        const double tau = f * exact.duration();
        EXPECT_LT((line.position(tau) - exact.position(tau)).norm(), 1e-5);
        EXPECT_LT((line.velocity(tau) - exact.velocity(tau)).norm(), 1e-3);
    }
    EXPECT_LT(line.position(line.duration())(0), 0);  // into the chart's past, as the circle
    WorldLineSegment bad = sampled;
    bad.samples[7].first += 0.5 * (bad.samples[8].first - bad.samples[7].first);
    try {
        ProperTimeWorldLine(1.0, Vec4(0, 3, 0, 0), {bad});
        ADD_FAILURE() << "inconsistent proper times accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("world line segment 0 (samples): chord 6 to 7 has proper length"),
                  std::string::npos)
            << e.what();
    }
    bad = sampled;
    bad.samples[1].second(1) += 1.0;  // far in space, a moment later: spacelike
    EXPECT_THROW(ProperTimeWorldLine(1.0, Vec4(0, 3, 0, 0), {bad}), std::invalid_argument);
}

}  // namespace
}  // namespace lc
