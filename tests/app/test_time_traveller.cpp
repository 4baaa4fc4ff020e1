// SPDX-License-Identifier: BSD-3-Clause
// data/godel_time_traveller.json as a user runs it (docs/PHYSICS.md section 11): `render` lists
// each image of the traveller with its age, two ages at once, differing by what the closed forms
// of the trip's legs give; the image carries the labels; `animate` along the observer's proper
// time shows the older traveller before the younger one leaves; the t-r diagram draws the trip.
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>

using namespace lc::test;

namespace {

// (age, emission time) of each image render lists.
std::vector<std::pair<double, double>> imagesIn(const std::string& output) {
    std::vector<std::pair<double, double>> images;
    const std::regex line(R"(image of 'traveller': proper time ([0-9.]+) at emission, emitted at t = (-?[0-9.]+))");
    for (auto it = std::sregex_iterator(output.begin(), output.end(), line); it != std::sregex_iterator(); ++it)
        images.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
    return images;
}

TEST(TimeTraveller, RenderListsTwoAgesAtOnceDifferingByTheTripsClosedForms) {
    const ScratchFolder dir("time-traveller");
    const CommandResult run =
        runCommand(lightcone() + " render " + sourcePath("data/godel_time_traveller.json") + " -o " + dir / "t.png");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto images = imagesIn(run.output);
    ASSERT_EQ(images.size(), 4u) << run.output;  // two ages, each seen outbound and inbound
    // Emitted at the same coordinate time (both wait at r = 0.5 a from the axis), the older one
    // has lived the trip's proper time plus the coordinate time the trip gained:
    // (2 dtau_radial + dtau_circle) - (2 gamma dtau_radial + dt/dphi 2 pi turns).
    const double gamma = 1 / std::sqrt(0.19), radial = 2 * (std::asinh(1.5) - std::asinh(0.25)) / (gamma * 0.9);
    const double gphiphi = 9 * (2.25 - 1), gtphi = 9 / std::sqrt(2.0), k = -0.8;
    const double circle = 2.25 * 2 * M_PI * std::sqrt(k * k + 2 * gtphi * k + gphiphi);  // 2 pi turns / omega
    const double expected = (2 * radial + circle) - (2 * gamma * radial + k * 2 * M_PI * 2.25);
    int pairs = 0;
    for (const auto& [ageA, tA] : images)
        for (const auto& [ageB, tB] : images)
            if (ageB > ageA && std::abs(tA - tB) < 1e-4) {
                EXPECT_NEAR(ageB - ageA, expected, 2e-4) << run.output;
                ++pairs;
            }
    EXPECT_EQ(pairs, 2) << run.output;  // the outbound pair and the inbound pair
    // The labels are drawn only into the image: the same render without travellers has none.
    EXPECT_GT(fileBytes(dir / "t.png").size(), 1000u);
}

// The figures docs/PHYSICS.md section 11 and the scene's own description quote are what the
// program gives (issue #47: "each age is seen twice", tau = 12 and -7.100 had drifted from the
// scene): the ages and emission times render prints, rounded as quoted; the legs' coordinate times
// from their closed forms; the first rest leg's proper time from the scene file.
TEST(TimeTraveller, NumbersQuotedInThePhysicsDocAndTheSceneAreWhatTheProgramGives) {
    const ScratchFolder dir("time-traveller-docs");
    const CommandResult run = runCommand(lightcone() + " render " + sourcePath("data/godel_time_traveller.json") +
                                         " --width 160 --height 40 --quiet -o " + dir / "t.png");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto images = imagesIn(run.output);
    ASSERT_EQ(images.size(), 4u) << run.output;
    auto fixed = [](double v, int decimals) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
        return std::string(buf);
    };
    const std::string scene = fileBytes(sourcePath("data/godel_time_traveller.json"));
    std::set<double> emitted;
    for (const auto& [age, t] : images) {
        EXPECT_NE(scene.find(fixed(age, 2)), std::string::npos) << "the scene's description lacks the age " << age;
        emitted.insert(std::round(t * 100) / 100);
    }
    ASSERT_EQ(emitted.size(), 2u);
    const std::string times = "emitted at t = " + fixed(*emitted.rbegin(), 2) + " and " + fixed(*emitted.begin(), 2);
    EXPECT_NE(scene.find(times), std::string::npos) << "the scene's description does not say " << times;
    EXPECT_NE(scene.find("four images"), std::string::npos);
    // docs/PHYSICS.md: each leg's coordinate time and the net gain, to the digits it quotes.
    const std::string physics = fileBytes(sourcePath("docs/PHYSICS.md"));
    const double gamma = 1 / std::sqrt(0.19), radialTau = 2 * (std::asinh(1.5) - std::asinh(0.25)) / (gamma * 0.9);
    const double radialT = gamma * radialTau, circleT = -0.8 * 2 * M_PI * 2.25;
    for (const std::string& quoted : {"\u0394t = +" + fixed(radialT, 5) + " a", "= \u2212" + fixed(-circleT, 5) + " a",
                                      "Net \u0394t = 2 \u00b7 " + fixed(radialT, 5) + " \u2212 " + fixed(-circleT, 5) +
                                          " = \u2212" + fixed(-(2 * radialT + circleT), 5) + " a",
                                      "\u0394\u03c4 = " + fixed(radialTau, 3)})
        EXPECT_NE(physics.find(quoted), std::string::npos) << "docs/PHYSICS.md does not quote " << quoted;
    // "wait ... (for tau = 30 in the scene)": the scene's first rest leg.
    const std::smatch rest = [&] {
        std::smatch m;
        std::regex_search(scene, m, std::regex(R"("type": "rest", "proper_time": ([0-9.]+))"));
        return m;
    }();
    ASSERT_FALSE(rest.empty());
    EXPECT_NE(physics.find("(for \u03c4 = " + rest[1].str() + " in the scene)"), std::string::npos);
}

TEST(TimeTraveller, AnimationShowsTheOlderTravellerBeforeTheYoungerLeaves) {
    const ScratchFolder dir("time-traveller-movie");
    // Observer times -10 (before the return at -7.10: one age) and -5 (both), as frames 0 and 1.
    const CommandResult run = runCommand(lightcone() + " animate " + sourcePath("data/godel_time_traveller.json") +
                                         " -o " + dir / "f%d.png --proper-time -7:-2:2 --width 320 --height 80");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (int f = 0; f < 2; ++f) {
        // Each frame is the render of its scene (observer at t = -10, -5), ages listed by render.
        const std::string scene = fileBytes(sourcePath("data/godel_time_traveller.json"));
        const std::string at =
            std::regex_replace(scene, std::regex(R"("position": \[-3, 0, 0, 0\])"),
                               f == 0 ? "\"position\": [-10, 0, 0, 0]" : "\"position\": [-5, 0, 0, 0]");
        std::ofstream(dir / "s.json") << at;
        const CommandResult single =
            runCommand(lightcone() + " render " + dir / "s.json" + " -o " + dir / "s.png --width 320 --height 80");
        ASSERT_EQ(single.exitCode, 0) << single.output;
        EXPECT_EQ(fileBytes(dir / ("f" + std::to_string(f) + ".png")), fileBytes(dir / "s.png")) << "frame " << f;
        std::set<int> distinct;
        for (const auto& image : imagesIn(single.output)) distinct.insert(image.first > 40 ? 1 : 0);
        EXPECT_EQ(distinct.size(), f == 0 ? 1u : 2u) << single.output;
    }
}

TEST(TimeTraveller, TrDiagramDrawsTheTripIntoTheClosedTimelikeBand) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "VTK's charts need an X display (ctest runs under xvfb-run)";
    const ScratchFolder dir("time-traveller-diagram");
    const CommandResult run = runCommand(lightcone() + " diagram " + sourcePath("data/godel_time_traveller.json") +
                                         " -o " + dir / "tr.svg --kind t-r --size 600");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string svg = fileBytes(dir / "tr.svg");
    EXPECT_NE(svg.find("world line of &apos;traveller&apos;"), std::string::npos);
    EXPECT_NE(svg.find("closed timelike circles"), std::string::npos);
    EXPECT_NE(svg.find("emission events of &apos;traveller&apos;"), std::string::npos);
}

}  // namespace
