// SPDX-License-Identifier: BSD-3-Clause
// `lightcone trace --event --direction [--observer] [--future]` as a user runs it: the launching
// observer and the meaning of --direction against closed forms. Alcubierre's metric
// ds^2 = dt^2 - (dx - v f dt)^2 - dy^2 - dz^2 has null rays along x with dx/dt = v f +- 1, so
// inside a superluminal bubble (f = 1, v = 2) light sent forward moves at dx/dt = 3 and light
// seen ahead at dx/dt = 1 (forward in the chart, overtaken by the bubble); the Eulerian observer
// u = d/dt + v f d/dx is the normal one (docs/PHYSICS.md section 9a).
#include "run_command.hpp"

#include <gtest/gtest.h>
#include <json/json.h>

#include <cmath>
#include <cstdio>
#include <sstream>

using namespace lc::test;

namespace {

Json::Value traceJson(const std::string& arguments) {
    const CommandResult r = runCommand(lightcone() + " trace " + arguments);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    Json::Value v;
    std::istringstream in(r.output);
    Json::CharReaderBuilder b;
    std::string errors;
    EXPECT_TRUE(Json::parseFromStream(b, in, &v, &errors)) << errors << "\n" << r.output;
    return v;
}

// dx/dt of the start momentum, raised with Alcubierre's inverse metric at the bubble's centre
// (f = 1): g^tt = 1, g^tx = v, g^xx = v^2 - 1.
double startSpeed(const Json::Value& out, double v) {
    const double pt = out["start"]["p"][0].asDouble(), px = out["start"]["p"][1].asDouble();
    const double ut = pt + v * px, ux = v * pt + (v * v - 1) * px;
    return ux / ut;
}

TEST(TraceCommand, LaunchesFromTheEulerianObserverInsideASuperluminalBubble) {
    const std::string head =
        "--metric alcubierre --param v=2 --event 0,0,0,0 --observer normal --direction 1,0,0 "
        "--max-affine 0.5 ";
    const Json::Value sent = traceJson(head + "--future");
    EXPECT_EQ(sent["observer"]["name"].asString(), "normal");
    EXPECT_NEAR(sent["observer"]["velocity"][0].asDouble(), 1, 1e-12);
    EXPECT_NEAR(sent["observer"]["velocity"][1].asDouble(), 2, 1e-12);  // u = d/dt + v d/dx
    EXPECT_NEAR(startSpeed(sent, 2), 3, 1e-12);                         // v + 1: sent forward along +x
    EXPECT_GT(sent["end"]["x"][1].asDouble(), 0);
    EXPECT_GT(sent["end"]["x"][0].asDouble(), 0);  // to the future
    const Json::Value seen = traceJson(head);
    // v - 1: the light the observer sees ahead moves forward in the chart too, slower than the
    // bubble, which overtakes it; traced back into the past it lies behind, at smaller x.
    EXPECT_NEAR(startSpeed(seen, 2), 1, 1e-12);
    EXPECT_LT(seen["end"]["x"][0].asDouble(), 0);  // to the past
    EXPECT_LT(seen["end"]["x"][1].asDouble(), 0);
    // The observer measures unit frequency: -p.u = 1 (p_t u^t + p_x u^x, signs of the past ray).
    const double pu = seen["start"]["p"][0].asDouble() * 1 + seen["start"]["p"][1].asDouble() * 2;
    EXPECT_NEAR(std::abs(pu), 1, 1e-12);
}

// Light the Eulerian observer at the centre of a superluminal bubble (v = 2, R = 1, sigma = 35)
// sends ahead runs into the front wall's horizon, where v f(xi) + 1 - v = 0 (f = 1/2; from ds^2 = 0
// on the axis, xi = x - v t), blueshifted without bound at finite affine length: the trace ends
// there and says so, not "raise --max-steps".
TEST(TraceCommand, LightSentAheadInASuperluminalBubbleEndsOnTheFrontHorizon) {
    const CommandResult r = runCommand(lightcone() +
                                       " trace --metric alcubierre --param v=2 --event 0,0,0,0 --observer normal "
                                       "--direction 1,0,0 --future --max-affine 10");
    EXPECT_EQ(r.exitCode, 4) << r.output;
    EXPECT_NE(r.output.find("reaches a horizon at finite affine length"), std::string::npos) << r.output;
    Json::Value v;
    std::istringstream in(r.output.substr(0, r.output.rfind('}') + 1));
    Json::CharReaderBuilder b;
    std::string errors;
    ASSERT_TRUE(Json::parseFromStream(b, in, &v, &errors)) << errors << "\n" << r.output;
    const double sigma = 35, R = 1;
    auto f = [&](double x) {
        return (std::tanh(sigma * (x + R)) - std::tanh(sigma * (x - R))) / (2 * std::tanh(sigma * R));
    };
    double lo = 0, hi = 2;  // f falls from 1 to 0 across the wall
    for (int i = 0; i < 100; ++i) (f(0.5 * (lo + hi)) > 0.5 ? lo : hi) = 0.5 * (lo + hi);
    const double xi = v["end"]["x"][1].asDouble() - 2 * v["end"]["x"][0].asDouble();
    EXPECT_NEAR(xi, 0.5 * (lo + hi), 1e-6);
    EXPECT_LT(v["affine"].asDouble(), 10);
}

// The static observer, the default, does not exist there: the error says so and names the others.
TEST(TraceCommand, RefusesAnObserverThatDoesNotExistAndNamesThoseThatDo) {
    const CommandResult warp =
        runCommand(lightcone() + " trace --metric alcubierre --param v=2 --event 0,0,0,0 --direction 1,0,0");
    EXPECT_NE(warp.exitCode, 0);
    EXPECT_NE(warp.output.find("option --observer: no static observer here"), std::string::npos) << warp.output;
    EXPECT_NE(warp.output.find("exist here: normal"), std::string::npos) << warp.output;
    const CommandResult bogus = runCommand(lightcone() +
                                           " trace --metric kerr --event 0,10,0,0 --direction 1,0,0 "
                                           "--observer hovering");
    EXPECT_EQ(bogus.exitCode, 2);
    EXPECT_NE(bogus.output.find("static, zamo, carter, free_fall, normal"), std::string::npos) << bogus.output;
    const CommandResult spacelike = runCommand(lightcone() +
                                               " trace --metric kerr --event 0,10,0,0 --direction 1,0,0 "
                                               "--observer 1,2,0,0");
    EXPECT_NE(spacelike.exitCode, 0);
    EXPECT_NE(spacelike.output.find("not future-directed timelike"), std::string::npos) << spacelike.output;
}

// --direction's meaning in Schwarzschild: a static observer at r = 10 M on the x axis, direction
// +x (outwards). Seen (default): the ray comes from outside, traced back it runs outwards into the
// past and escapes. Sent (--future): the photon runs outwards into the future and escapes. Towards
// the hole (-x) both end at the horizon.
TEST(TraceCommand, TheRayRunsAlongTheDirectionToThePastOrWithFutureToTheFuture) {
    for (const bool future : {false, true}) {
        const std::string f = future ? " --future" : "";
        const Json::Value out = traceJson("--metric schwarzschild --event 0,10,0,0 --direction 1,0,0" + f);
        EXPECT_EQ(out["reason"].asString(), "escaped") << f;
        EXPECT_GT(out["end"]["x"][1].asDouble(), 100) << f;
        EXPECT_EQ(out["end"]["x"][0].asDouble() > 0, future) << f;
        const Json::Value in = traceJson("--metric schwarzschild --event 0,10,0,0 --direction -1,0,0" + f);
        EXPECT_NE(in["reason"].asString(), "escaped") << f;
        EXPECT_LT(in["end"]["x"][1].asDouble(), 2.01) << f;  // at the horizon, r = 2M
    }
}

// Honest outputs (issue #52): a ray stopped by --max-steps before it escaped prints no deflection
// as if it were a result (none, and the reason) and exits with status 4; a captured ray has none
// either (status 0: the physics ended it); rk4 refuses a tolerance it would ignore.
TEST(TraceCommand, NoDeflectionWithoutEscapeAndNoToleranceForAFixedStepper) {
    const CommandResult stopped = runCommand(lightcone() + " trace --impact 5.25 --max-steps 100");
    EXPECT_EQ(stopped.exitCode, 4) << stopped.output;
    EXPECT_EQ(stopped.output.find("\"deflection\""), std::string::npos) << stopped.output;
    EXPECT_NE(stopped.output.find("it stopped at max_steps"), std::string::npos) << stopped.output;
    const Json::Value captured = traceJson("--impact 5");  // below 3 sqrt 3: captured
    EXPECT_EQ(captured["reason"].asString(), "horizon");
    EXPECT_FALSE(captured.isMember("deflection"));
    EXPECT_EQ(captured["no_deflection_because"].asString(), "the ray did not escape: it stopped at horizon");
    const Json::Value escaped = traceJson("--impact 100");
    EXPECT_NEAR(escaped["deflection"].asDouble(), 4.0 / 100, 2e-3);  // weak field: 4M/b
    // Goedel: rays never escape; one given up on at --max-steps before --max-affine says so too
    // (the help's example once ended at 10^6 steps with status 0 and no word).
    const CommandResult goedel = runCommand(lightcone() +
                                            " trace --metric godel --event 0,0.5,0,0 --direction "
                                            "0,1,0 --max-steps 100");
    EXPECT_EQ(goedel.exitCode, 4) << goedel.output;
    EXPECT_NE(goedel.output.find("stopped at max_steps after 100 steps, before --max-affine"), std::string::npos)
        << goedel.output;
    const CommandResult rk4 = runCommand(lightcone() + " trace --impact 10 --stepper rk4 --tolerance 1e-8");
    EXPECT_EQ(rk4.exitCode, 2);
    EXPECT_NE(rk4.output.find("rk4 takes fixed steps"), std::string::npos) << rk4.output;
}

// A metric refused for its parameters names the options given and the accepted range (issue
// #47: `--metric kerr --param a=2` said only "Kerr-Newman: ...").
TEST(TraceCommand, RefusedParametersNameTheOptionsAndTheRange) {
    const CommandResult r = runCommand(lightcone() + " trace --metric kerr --param a=2 --impact 5");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("option --metric kerr --param a=2: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("accepted |a| <= 1"), std::string::npos) << r.output;
}

// Every trace reports its error (issue #52): the deflection's estimated error, by a second
// integration 100 times tighter, against the exact Schwarzschild deflection of b = 6 M
// (1.719388310230169, an exact integral, docs/PHYSICS.md section 7) within a factor of 10, where
// the integration's error dominates (dopri5, 1e-6 to 1e-9; below, D = 1e6 M's finite distance
// does); Goedel's end position at a fixed affine length.
TEST(TraceCommand, ErrorEstimateIsWithinAFactorOfTenOfTheTrueError) {
    for (const char* tolerance : {"1e-6", "1e-7", "1e-8", "1e-9"}) {
        const Json::Value out = traceJson(std::string("--impact 6 --stepper dopri5 --tolerance ") + tolerance);
        const double actual = std::abs(out["deflection"].asDouble() - 1.719388310230169);
        const double estimate = out["error_estimate"]["deflection"].asDouble();
        std::printf("| dopri5 %s | true error %.2e | estimate %.2e |\n", tolerance, actual, estimate);
        EXPECT_GT(estimate, actual / 10) << tolerance;
        EXPECT_LT(estimate, actual * 10) << tolerance;
    }
    const Json::Value godel =
        traceJson("--metric godel --event 0,0.5,0,0 --direction 0,1,0 --max-affine 20 --tolerance 1e-8");
    EXPECT_TRUE(godel["error_estimate"].isMember("end_position")) << godel.toStyledString();
    EXPECT_LT(godel["error_estimate"]["end_position"].asDouble(), 1e-5);
}

}  // namespace
