// SPDX-License-Identifier: BSD-3-Clause
// The exported t-r diagram read back from its SVG: each emission event where `lightcone images`
// puts it (the same core solver, called here on its own), the legend beside the plot area, the
// horizon and the closed-timelike-circle band drawn even without objects, and the scenes it
// refuses. Runs under Xvfb.
#include "core/godel/images.hpp"
#include "core/metrics/godel.hpp"
#include "core/render/photo_scene.hpp"
#include "diagram_checks.hpp"
#include "readers/io/scene_reader.hpp"
#include "vtkLightconeTRDiagram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

lc::Scene sceneFile(const std::string& name) {
    return lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/" + name);
}

struct Event {
    double r, t;
};

void latestFirst(std::vector<Event>& events) {
    std::sort(events.begin(), events.end(), [](const Event& x, const Event& y) { return x.t > y.t; });
}

// A built diagram and its SVG, parsed.
struct Drawn {
    vtkSmartPointer<vtkLightconeTRDiagram> diagram = vtkSmartPointer<vtkLightconeTRDiagram>::New();
    lc::test::SvgDocument svg;
};
Drawn draw(const lc::Scene& scene, int windings, int rays) {
    Drawn d;
    d.diagram->SetScene(scene);
    d.diagram->SetWindings(windings);
    d.diagram->SetFanRays(rays);
    d.diagram->Build();
    d.svg = lc::test::parseSvg(d.diagram->Encode(".svg"));
    return d;
}

// The diamonds inside the plot area, in data units through the axes' tick labels, against the
// expected (r, t). Tolerance: 1.5 px on either axis (tick labels and the plot group's offset are
// written to whole pixels): here about 0.07 in t and 0.005 in r.
void expectEmissionEvents(const lc::test::SvgDocument& svg, std::vector<Event> expected) {
    const lc::test::SvgAxisMap r = lc::test::axisMap(svg, true), t = lc::test::axisMap(svg, false);
    std::vector<Event> drawn;
    for (const auto& u : svg.uses)
        if (u.symbol == "Diamond" && svg.clip.contains(u.x, u.y)) drawn.push_back({r(u.x), t(u.y)});
    latestFirst(drawn);
    latestFirst(expected);
    ASSERT_EQ(drawn.size(), expected.size());
    const double rTol = 1.5 / r.pixelsPerUnit(), tTol = 1.5 / t.pixelsPerUnit();
    EXPECT_LT(tTol, 0.1);
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        EXPECT_NEAR(drawn[i].r, expected[i].r, rTol) << "image " << i;
        EXPECT_NEAR(drawn[i].t, expected[i].t, tTol) << "image " << i;
    }
}

bool hasText(const lc::test::SvgDocument& svg, const std::string& text) {
    return std::any_of(svg.texts.begin(), svg.texts.end(), [&](const lc::test::SvgText& t) { return t.text == text; });
}

TEST(TRDiagram, EmissionEventsInTheSvgAreWhereLightconeImagesPutsThem) {
    const lc::Scene scene = sceneFile("godel_many_images.json");  // a static ball, observer at the origin
    const int windings = scene.settings.windings;
    const Drawn d = draw(scene, windings, 6);

    // What `lightcone images` reports for the ball's centre (app/commands/command_images.cpp); the images
    // are at least 0.47 apart in t.
    const double a = static_cast<const lc::GodelCartesian&>(*scene.spacetime).a();
    const lc::godel::ImageSet set =
        lc::godel::ObserverView(a, scene.observer).images(scene.spheres.at(0).centre.tail<3>(), windings);
    ASSERT_EQ(set.images.size(), 12u);  // two per winding, windings 0..5
    std::vector<Event> expected;
    for (const auto& im : set.images) expected.push_back({std::hypot(im.event(1), im.event(2)), im.emissionTime});
    expectEmissionEvents(d.svg, expected);
    EXPECT_EQ(d.diagram->GetNumberOfEmissionEvents(), 12);
    EXPECT_EQ(d.diagram->GetNumberOfImagePaths(), 12);
}

TEST(TRDiagram, FreeFallEmissionEventsAreThoseOfItsWorldLine) {
    // The moving earth: emission events where lc::imagesOfMovingCentre solves them, in the
    // observer's chart (here the scene's: the observer sits at the origin).
    const lc::Scene scene = sceneFile("godel_free_fall_earth.json");
    const Drawn d = draw(scene, 1, 4);
    std::vector<Event> expected;
    for (const auto& mi : lc::imagesOfMovingCentre(scene, scene.spheres.at(0), 1))
        expected.push_back({std::hypot(mi.image.event(1), mi.image.event(2)), mi.image.emissionTime});
    ASSERT_FALSE(expected.empty());
    expectEmissionEvents(d.svg, expected);
    EXPECT_TRUE(hasText(d.svg, "world line of 'earth'"));
}

TEST(TRDiagram, LegendStaysOutsideThePlotArea) {
    const Drawn d = draw(sceneFile("godel_many_images.json"), 5, 6);
    // In the chart and in the file: the legend's box and every entry's text right of the plot
    // area, which is the SVG's clip rectangle; the legend's column widens the page.
    const lc::test::SvgRect plot = lc::test::plotArea(d.diagram, d.svg.height);
    EXPECT_NEAR(plot.x, d.svg.clip.x, 1.0);
    EXPECT_NEAR(plot.width, d.svg.clip.width, 1.0);
    EXPECT_NEAR(plot.width, plot.height, 1.0);
    EXPECT_GT(lc::test::legendLeft(d.diagram), plot.x + plot.width);
    const auto entries =
        lc::test::legendTexts(d.svg, {"image of", "Goedel horizon", "closed timelike", "emission events"});
    EXPECT_EQ(entries.size(), 12u + 3u);
    for (const auto& t : entries) EXPECT_GT(t.x, d.svg.clip.x + d.svg.clip.width) << t.text;
    EXPECT_GT(d.svg.width, d.svg.height);
}

TEST(TRDiagram, SceneWithoutObjectsStillDrawsAxesHorizonAndClosedTimelikeBand) {
    lc::Scene scene = sceneFile("godel_many_images.json");
    scene.spheres.clear();
    const Drawn d = draw(scene, 1, 3);
    EXPECT_EQ(d.diagram->GetNumberOfImagePaths(), 0);
    EXPECT_EQ(d.diagram->GetNumberOfEmissionEvents(), 0);
    EXPECT_NO_THROW(lc::test::axisMap(d.svg, true));
    EXPECT_NO_THROW(lc::test::axisMap(d.svg, false));
    EXPECT_TRUE(hasText(d.svg, "Goedel horizon r = 2a"));
    EXPECT_TRUE(hasText(d.svg, "closed timelike circles (r > 2a)"));
    const std::string bytes = d.diagram->Encode(".svg");
    // The horizon: a dashed red line in the plot's group (data units: thin stroke) besides its
    // legend swatch; the band: a filled shape in the plot besides its swatch.
    EXPECT_NE(bytes.find("<polyline stroke=\"#cc1919\" stroke-width=\"0."), std::string::npos);
    std::size_t fills = 0;
    for (std::size_t at = bytes.find("fill=\"#f2bfcc\""); at != std::string::npos;
         at = bytes.find("fill=\"#f2bfcc\"", at + 1))
        ++fills;
    EXPECT_GE(fills, 2u);
}

TEST(TRDiagram, RefusesNonGodelScenesAndUnknownFormats) {
    vtkNew<vtkLightconeTRDiagram> diagram;
    try {
        diagram->SetScene(sceneFile("kerr.json"));
        ADD_FAILURE() << "a Kerr scene was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("the t-r diagram needs a scene with the 'godel' metric"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(diagram->Build(), std::logic_error);  // no scene yet
    diagram->SetScene(sceneFile("godel_many_images.json"));
    EXPECT_THROW(diagram->Encode(".bmpx"), std::invalid_argument);
}

}  // namespace
