// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/field_guide.hpp"

#include "core/formula/formula_metric.hpp"
#include "core/metrics/factory.hpp"
#include "core/render/render.hpp"
#include "core/scene/scene.hpp"
#include "core/spacetime/named_observer.hpp"

#include <algorithm>
#include <iterator>
#include <regex>
#include <sstream>

namespace lc::io {
namespace {

// The guide's pages (docs/guide/README.md) and the headings the tooltips point at. Renaming a
// heading there needs it renamed here; a test reads the pages and finds every one.
const char* const kIndex = "index.md";
const char* const kGodel = "godel.md";
const char* const kBlackHoles = "black_holes.md";
const char* const kSpecialRelativity = "special_relativity.md";
const char* const kTypedMetrics = "warp_drives_and_wormholes.md";

// What a field's unit is: a chart quantity (written out from the scene's chart) or plain text.
enum class Unit { Text, Event, FourVelocity, ChartDirection, ChartPoint, Length, ProperTime };
// Where the guide explains it: the page of the scene's kind, the index, the black-hole page.
enum class Page { Kind, Index, BlackHoles };

struct Entry {
    const char* pattern;  // the field path with every index written "[]"
    const char* meaning;
    Unit unit;
    const char* text;     // Unit::Text: the unit itself; otherwise added after the chart's words
    const char* choices;  // comma separated; "@metrics", "@observers", "@steppers", "@methods"
    const char* section;
    Page page;
};

const char* const kWhatYouSee = "What you see";
const char* const kMetricSection = "The metric and its parameters";
const char* const kUnits = "Units and coordinates";
const char* const kObserverCamera = "The observer and the camera";
const char* const kObjects = "Objects and lights";
const char* const kDisk = "The accretion disk";
const char* const kRenderSettings = "Render settings";

// clang-format off
const Entry kEntries[] = {
    {"description", "free text about the scene, shown in figure captions", Unit::Text, "", "", kWhatYouSee, Page::Kind},
    {"metric", "the spacetime: a built-in metric by name, a metric file, or a formula typed in the scene", Unit::Text, "", "", kMetricSection, Page::Kind},
    {"metric.name", "the built-in metric", Unit::Text, "", "@metrics", kMetricSection, Page::Kind},
    {"metric.file", "a metric written as text, its file relative to the scene", Unit::Text, "", "", kMetricSection, Page::Kind},
    {"observer", "who takes the picture: an event and a 4-velocity", Unit::Text, "", "", kObserverCamera, Page::Kind},
    {"camera", "the observer's camera: projection, image size, field of view and where it looks", Unit::Text, "", "", kObserverCamera, Page::Kind},
    {"observer.position", "the observer's event: where and when the picture is taken", Unit::Event, "", "", kUnits, Page::Kind},
    {"observer.velocity", "the observer's motion: a contravariant 4-velocity, or a named observer built at its event", Unit::FourVelocity, "", "@observers", kObserverCamera, Page::Kind},
    {"camera.projection", "how pixels map to directions: pinhole (a flat picture) or panorama (azimuth and elevation)", Unit::Text, "", "pinhole, panorama", kObserverCamera, Page::Kind},
    {"camera.width", "image width", Unit::Text, "pixels", "", kObserverCamera, Page::Kind},
    {"camera.height", "image height", Unit::Text, "pixels", "", kObserverCamera, Page::Kind},
    {"camera.fov", "field of view [horizontal, vertical]: a pinhole's full angles, a panorama's azimuth and elevation spans", Unit::Text, "degrees", "", kObserverCamera, Page::Kind},
    {"camera.forward", "where the camera looks", Unit::ChartDirection, "", "", kObserverCamera, Page::Kind},
    {"camera.up", "the camera's up (made orthogonal to forward)", Unit::ChartDirection, "", "", kObserverCamera, Page::Kind},
    {"camera.look_at", "a place the camera looks towards, instead of forward (light bends, so it is centred only where symmetry puts it there)", Unit::ChartPoint, "", "", kObserverCamera, Page::Kind},
    {"objects", "the bodies in the scene", Unit::Text, "", "", kObjects, Page::Kind},
    {"objects[]", "one body", Unit::Text, "", "", kObjects, Page::Kind},
    {"objects[].type", "what kind of body", Unit::Text, "", "sphere, box, mesh, disk", kObjects, Page::Kind},
    {"objects[].name", "the body's name in the tables, legends and picks", Unit::Text, "", "", kObjects, Page::Kind},
    {"objects[].centre", "the body's centre: the event where its motion starts", Unit::Event, "", "", kUnits, Page::Kind},
    {"objects[].radius", "the sphere's radius, in its own rest frame", Unit::Length, "", "", kObjects, Page::Kind},
    {"objects[].size", "the box's edges [sx, sy, sz], in its own rest frame", Unit::Length, "", "", kObjects, Page::Kind},
    {"objects[].subdivisions", "how finely each box face is cut into triangles (light bends inside a face)", Unit::Text, "", "", kObjects, Page::Kind},
    {"objects[].file", "the mesh file (OBJ, PLY, STL, VTP), relative to the scene", Unit::Text, "", "", kObjects, Page::Kind},
    {"objects[].scale", "factor on the mesh file's coordinates", Unit::Text, "", "", kObjects, Page::Kind},
    {"objects[].temperature", "a sphere's black-body temperature: it glows, its colour shifted by the Doppler and gravitational factor", Unit::Text, "kelvin", "", kObjects, Page::Kind},
    {"objects[].texture", "what the surface shows", Unit::Text, "", "checker, earth, earth-night, an image file, {\"type\": \"solid\"}, {\"type\": \"checker\"}", kObjects, Page::Kind},
    {"objects[].night_texture", "what a sphere shows where its surface is unlit", Unit::Text, "", "earth-night, an image file", kObjects, Page::Kind},
    {"objects[].motion", "how the body moves; rest when left out", Unit::Text, "", "rest, {\"type\": \"constant_velocity\"} (minkowski), {\"type\": \"free_fall\"} (godel), {\"type\": \"world_line\"}, {\"type\": \"segments\"} (godel)", kObjects, Page::Kind},
    {"objects[].motion.type", "how the body moves", Unit::Text, "", "rest, constant_velocity (minkowski), free_fall (godel), world_line, segments (godel)", kObjects, Page::Kind},
    {"objects[].motion.beta", "the body's velocity dx/dt, dy/dt, dz/dt in the chart, below the speed of light", Unit::Text, "units of c", "", kObjects, Page::Kind},
    {"objects[].motion.speed", "the fall's starting speed, measured by the static observer at the centre event", Unit::Text, "units of c", "", kObjects, Page::Kind},
    {"objects[].motion.k0", "the fall's energy constant (instead of speed; the Lorentz factor of the start)", Unit::Text, "dimensionless", "", kObjects, Page::Kind},
    {"objects[].motion.phi0", "the azimuth the fall starts towards", Unit::Text, "radians", "", kObjects, Page::Kind},
    {"objects[].motion.k3", "the fall's vertical momentum constant dz/dλ (k3² ≤ k0² − 1)", Unit::Text, "dimensionless", "", kObjects, Page::Kind},
    {"objects[].motion.points", "the world line's events, straight between them in coordinate time", Unit::Event, "", "", kUnits, Page::Kind},
    {"objects[].motion.points[]", "one event of the world line", Unit::Event, "", "", kUnits, Page::Kind},
    {"objects[].motion.segments", "the trip, leg after leg by the body's proper time", Unit::Text, "", "", kObjects, Page::Kind},
    {"objects[].motion.segments[].type", "one leg of the trip", Unit::Text, "", "rest, radial, circle, free_fall, rocket, samples", kObjects, Page::Kind},
    {"objects[].motion.segments[].proper_time", "how long the leg lasts on the body's own clock", Unit::ProperTime, "", "", kObjects, Page::Kind},
    {"objects[].motion.segments[].speed", "the radial leg's speed, measured by the static observers it passes", Unit::Text, "units of c", "", kObjects, Page::Kind},
    {"objects[].motion.segments[].to_radius", "where the radial leg ends: the cylindrical radius r", Unit::Length, "", "", kObjects, Page::Kind},
    {"objects[].motion.segments[].dt_dphi", "the circle's coordinate time per radian (below zero it runs into the chart's past, possible beyond r = 2a only)", Unit::Length, " per radian", "", kObjects, Page::Kind},
    {"objects[].motion.segments[].turns", "how many times the circle goes round the axis (signed)", Unit::Text, "turns", "", kObjects, Page::Kind},
    {"objects[].motion.segments[].acceleration", "the rocket's proper acceleration", Unit::Text, "units of 1/a (c = 1)", "", kObjects, Page::Kind},
    {"objects[].motion.segments[].direction", "the rocket's thrust, a chart direction at the body made orthogonal to its velocity", Unit::Text, "", "outward, inward, prograde, retrograde, up, down", kObjects, Page::Kind},
    {"objects[].motion.segments[].points", "events at given proper times [τ, t, x, y, z], straight in between", Unit::Event, " after the proper time τ", "", kObjects, Page::Kind},
    {"objects[].inner_radius", "the disk's inner edge: a Boyer-Lindquist radius (or a typed metric's radius label), never inside the innermost stable circular orbit", Unit::Length, "", "isco (default), a radius", kDisk, Page::BlackHoles},
    {"objects[].outer_radius", "the disk's outer edge (Boyer-Lindquist radius)", Unit::Length, "", "", kDisk, Page::BlackHoles},
    {"objects[].sense", "which way the disk's matter orbits: prograde turns with the hole (a = 0: counter-clockwise about +z)", Unit::Text, "", "prograde (default), retrograde", kDisk, Page::BlackHoles},
    {"objects[].emission", "what the disk shows: its local black body seen at g T, its Page-Thorne flux alone (grey), or a texture", Unit::Text, "", "blackbody (default), flux, texture", kDisk, Page::BlackHoles},
    {"lights", "point lights at rest, black bodies", Unit::Text, "", "", kObjects, Page::Kind},
    {"lights[].name", "the light's name", Unit::Text, "", "", kObjects, Page::Kind},
    {"lights[].position", "where the light is (it stays at rest in the chart)", Unit::Event, "", "", kUnits, Page::Kind},
    {"lights[].temperature", "the light's black-body temperature", Unit::Text, "kelvin", "", kObjects, Page::Kind},
    {"lights[].intensity", "the light's brightness, relative", Unit::Text, "dimensionless", "", kObjects, Page::Kind},
    {"sky", "what rays that escape show: a texture on the celestial sphere or a field of stars", Unit::Text, "", "checker (default), earth, an image file, {\"type\": \"stars\"}", kObjects, Page::Kind},
    {"other_sky", "the sky of a two-ended metric's far side (a wormhole's other mouth)", Unit::Text, "", "", kObjects, Page::Kind},
    {"sky.temperature", "the sky's black-body temperature: its colour shifted by each pixel's frequency ratio", Unit::Text, "kelvin", "", kObjects, Page::Kind},
    {"sky.stars", "how many stars", Unit::Text, "stars", "", kObjects, Page::Kind},
    {"sky.temperatures", "the stars' temperatures [coolest, hottest]", Unit::Text, "kelvin", "", kObjects, Page::Kind},
    {"sky.faintest_magnitude", "the faintest star's apparent magnitude", Unit::Text, "magnitudes", "", kObjects, Page::Kind},
    {"sky.size", "the stars' angular size", Unit::Text, "degrees", "", kObjects, Page::Kind},
    {"background", "the colour of rays that end nowhere", Unit::Text, "linear RGB, each in [0, 1]", "", kObjects, Page::Kind},
    {"render", "how the image is computed", Unit::Text, "", "", kRenderSettings, Page::Index},
    {"render.method", "the renderer", Unit::Text, "", "@methods", kRenderSettings, Page::Index},
    {"render.stepper", "the numeric tracer's integrator", Unit::Text, "", "@steppers", kRenderSettings, Page::Index},
    {"render.tolerance", "the numeric tracer's error per step, relative", Unit::Text, "dimensionless", "", kRenderSettings, Page::Index},
    {"render.windings", "how far Gödel rays are followed: (windings + 1) 2πa of affine length, two images more per winding", Unit::Text, "", "", kRenderSettings, Page::Index},
    {"render.max_affine", "the affine length after which a ray stops", Unit::Length, "", "", kRenderSettings, Page::Index},
    {"render.escape_radius", "beyond this distance (and the capture radius) a ray moving outwards may escape", Unit::Length, "", "", kRenderSettings, Page::Index},
    {"render.escape_angle", "a ray escapes once the bending still ahead of it is below this", Unit::Text, "radians", "", kRenderSettings, Page::Index},
    {"render.max_steps", "the steps after which a ray is given up", Unit::Text, "steps", "", kRenderSettings, Page::Index},
    {"render.initial_step", "the first step of each ray", Unit::Length, " of affine parameter", "", kRenderSettings, Page::Index},
    {"render.threads", "threads the render uses (0: every core)", Unit::Text, "", "", kRenderSettings, Page::Index},
    {"render.mesh_resolution", "a sphere's tessellation for the per-vertex renderer [latitudes, longitudes]", Unit::Text, "", "", kRenderSettings, Page::Index},
    {"animation", "the path lightcone animate follows: frames, the observer's proper time, pan, orbit, a swept field", Unit::Text, "", "", kRenderSettings, Page::Index},
    {"render.magnification", "carry a thin bundle with each ray: each pixel's magnification, shear and rotation", Unit::Text, "", "false (default), true", kRenderSettings, Page::Index},
};
// clang-format on

// The built-in metrics' charts and units, as docs/guide/ explains them.
struct BuiltInChart {
    const char *metric, *page, *chart, *lengthUnit, *unit;
};
const char* const kKerrUnit = "lengths and times in units of M (G = c = 1; one solar mass: M = 1.48 km = 4.93 μs)";
const BuiltInChart kBuiltInCharts[] = {
    {"godel", kGodel, "axis-regular chart of Gödel's universe (x = r cos φ, y = r sin φ)", "the length unit of a",
     "t and lengths in the unit of a (c = 1); an observer's horizon lies at r = 2a"},
    {"godel-cylindrical", kGodel, "cylindrical chart of Gödel's universe (Kajari et al.; φ in radians)",
     "the length unit of a", "t and lengths in the unit of a (c = 1); an observer's horizon lies at r = 2a"},
    {"minkowski", kSpecialRelativity, "inertial Cartesian chart", "any length unit",
     "any length unit, t in the same unit (c = 1)"},
    {"schwarzschild", kBlackHoles, "outgoing Kerr-Schild Cartesian chart", "units of M", kKerrUnit},
    {"kerr", kBlackHoles, "outgoing Kerr-Schild Cartesian chart, spin along +z", "units of M", kKerrUnit},
    {"kerr-newman", kBlackHoles, "outgoing Kerr-Schild Cartesian chart, spin along +z", "units of M", kKerrUnit},
    {"alcubierre", kTypedMetrics, "Cartesian chart in which the bubble moves along +x", "the length unit of R",
     "lengths in the unit of the bubble radius R, t in the same unit (c = 1)"},
};

const Entry* entryOf(const std::string& pattern) {
    for (const Entry& e : kEntries)
        if (pattern == e.pattern) return &e;
    return nullptr;
}

std::string withoutIndices(const std::string& field) {
    static const std::regex index(R"(\[[0-9]+\])");
    return std::regex_replace(field, index, "[]");
}

std::vector<std::string> split(const std::string& list) {
    std::vector<std::string> words;
    std::string word;
    int depth = 0;  // commas inside {...} belong to the word
    for (char c : list) {
        if (c == '{') ++depth;
        if (c == '}') --depth;
        if (c == ',' && depth == 0) {
            words.push_back(word);
            word.clear();
            continue;
        }
        if (!(word.empty() && c == ' ')) word += c;
    }
    if (!word.empty()) words.push_back(word);
    return words;
}

std::vector<std::string> choicesOf(const std::string& choices) {
    if (choices == "@metrics") {
        std::vector<std::string> names;
        for (const auto& m : knownMetrics()) names.push_back(m.name);
        return names;
    }
    if (choices == "@observers") {
        std::vector<std::string> names = split(namedObserverNames());
        names.push_back("four numbers [u^t, u^x, u^y, u^z]");
        return names;
    }
    if (choices == "@steppers") {
        std::vector<std::string> names = sceneStepperNames();
        names.front() += " (default: dopri5 for images, dopri87 where only a ray's fate counts)";
        return names;
    }
    if (choices == "@methods") {
        std::vector<std::string> names;
        for (auto m : {RenderSettings::Method::Auto, RenderSettings::Method::Numeric,
                       RenderSettings::Method::ClosedForm, RenderSettings::Method::PerVertex})
            names.push_back(renderMethodName(m));
        names.front() += " (default: the closed form in Gödel, the numeric tracer elsewhere)";
        return names;
    }
    return split(choices);
}

std::string spatial(const ChartGuide& chart) {
    return "(" + chart.coordinates[1] + ", " + chart.coordinates[2] + ", " + chart.coordinates[3] + ")";
}

std::string unitText(const Entry& e, const ChartGuide& chart) {
    switch (e.unit) {
        case Unit::Text: return e.text;
        case Unit::Event:
            return "an event " + chart.coordinateList() + e.text + " in the " + chart.chart + "; " + chart.unit;
        case Unit::FourVelocity:
            return "contravariant components (u^" + chart.coordinates[0] + ", u^" + chart.coordinates[1] + ", u^" +
                   chart.coordinates[2] + ", u^" + chart.coordinates[3] + ") in the " + chart.chart +
                   ", normalised on reading to g(u, u) = +1 (signature +,−,−,−); default: static";
        case Unit::ChartDirection:
            return "a chart direction " + spatial(chart) + " at the observer's event, in the " + chart.chart +
                   "; what the observer sees of it (its projection into the observer's rest space) is used, "
                   "only the direction counts";
        case Unit::ChartPoint: return "a chart position " + spatial(chart) + " in the " + chart.chart;
        case Unit::Length: return chart.lengthUnit + e.text;
        case Unit::ProperTime: return chart.lengthUnit + " of the body's proper time (c = 1)";
    }
    return {};
}

// "lengths and times in units of M (G = c = 1)" -> "units of M"; the metric's parameter
// meaning "mass; lengths are in units of M" says it for typed metrics.
std::string unitsFromMeanings(const std::vector<MetricParameter>& parameters) {
    for (const auto& p : parameters) {
        const auto at = p.why.find("units of ");
        if (at != std::string::npos) {
            std::string unit = p.why.substr(at);
            const auto end = unit.find_first_of(";,)");
            return end == std::string::npos ? unit : unit.substr(0, end);
        }
    }
    return {};
}

}  // namespace

std::string ChartGuide::coordinateList() const {
    return "(" + coordinates[0] + ", " + coordinates[1] + ", " + coordinates[2] + ", " + coordinates[3] + ")";
}

ChartGuide defaultChartGuide() {
    ChartGuide g;
    g.chart = "metric's chart";
    g.unit = "the metric's units (c = 1)";
    g.lengthUnit = "the metric's length unit";
    g.page = kIndex;
    return g;
}

ChartGuide chartGuideOf(const Json::Value& metricBlock, const Spacetime& spacetime) {
    ChartGuide g;
    g.metric = spacetime.name();
    g.coordinates = spacetime.coordinateNames();
    const std::string name = metricBlock.isObject() ? metricBlock.get("name", "").asString() : "";
    const auto builtIn = std::find_if(std::begin(kBuiltInCharts), std::end(kBuiltInCharts),
                                      [&](const BuiltInChart& c) { return name == c.metric; });
    if (builtIn != std::end(kBuiltInCharts)) {
        g.page = builtIn->page;
        g.chart = builtIn->chart;
        g.lengthUnit = builtIn->lengthUnit;
        g.unit = builtIn->unit;
    } else {
        const auto* typed = dynamic_cast<const formula::FormulaMetric*>(&spacetime);
        const std::string chartKind = typed ? typed->source().chart : "cartesian";
        g.chart = chartKind == "spherical"
                      ? "Cartesian chart (x = r sin θ cos φ, y = r sin θ sin φ, z = r cos θ) its spherical chart "
                        "is pulled back to"
                  : chartKind == "cylindrical"
                      ? "Cartesian chart (x = ρ cos φ, y = ρ sin φ) its cylindrical chart is pulled back to"
                      : "metric's Cartesian chart";
        g.chart = "typed metric " + g.metric + "'s " + g.chart;
        const std::string units = typed ? unitsFromMeanings(typed->source().parameters) : "";
        g.lengthUnit = units.empty() ? "the unit of the metric's lengths" : units;
        g.unit = units.empty() ? "lengths and times in the unit of the metric's parameters (c = 1)"
                               : "lengths and times in " + units + " (c = 1)";
        g.page = g.metric.find("godel") != std::string::npos ? kGodel
                 : spacetime.hasHorizon()                    ? kBlackHoles
                                                             : kTypedMetrics;
    }
    return g;
}

FieldGuide fieldGuide(const std::string& field, const ChartGuide& chart, const Json::Value& scene) {
    FieldGuide help;
    help.field = field;
    help.page = chart.page;
    help.section = kWhatYouSee;
    const std::string pattern = withoutIndices(field);
    // A metric's parameter: its own meaning, from the built-in table or the typed metric's file.
    if (pattern.rfind("metric.", 0) == 0 && pattern != "metric.name" && pattern != "metric.file" &&
        pattern != "metric.formula") {
        const std::string parameter = pattern.substr(7);
        const std::string metric = scene["metric"].get("name", "").asString();
        for (const auto& m : knownMetrics())
            if (m.name == metric)
                for (const auto& p : m.parameters)
                    if (p.name == parameter) help.meaning = "metric parameter " + parameter + ": " + p.why;
        if (help.meaning.empty()) help.meaning = "a parameter of the metric (its meaning: View > Metric editor)";
        help.unit = chart.unit;
        help.section = kMetricSection;
        return help;
    }
    if (pattern.rfind("metric.formula", 0) == 0) {
        help.meaning = "the metric typed as text (View > Metric editor edits it)";
        help.page = kTypedMetrics;
        help.section = kMetricSection;
        return help;
    }
    // A part the table does not name (a texture's cells, a star field's seed) is described by
    // the nearest field that it is part of.
    std::string named = pattern;
    const Entry* entry = entryOf(named);
    while (!entry && !named.empty()) {
        const auto cut = named.find_last_of(".[");
        named = cut == std::string::npos ? std::string() : named.substr(0, cut);
        entry = entryOf(named);
    }
    if (entry) {
        help.meaning = named == pattern ? entry->meaning : "part of " + named + ": " + entry->meaning;
        if (named == pattern) {
            help.unit = unitText(*entry, chart);
            help.choices = choicesOf(entry->choices);
        }
        help.section = entry->section;
        help.page = entry->page == Page::Index ? kIndex : entry->page == Page::BlackHoles ? kBlackHoles : chart.page;
    }
    // A disk's temperature is its profile's hottest ring, not the temperature everywhere.
    if (pattern == "objects[].temperature") {
        const Json::Value& object = scene["objects"][static_cast<Json::ArrayIndex>(std::stoul(field.substr(8)))];
        if (object.get("type", "").asString() == "disk") {
            help.meaning =
                "the disk's hottest ring: the maximum of its Page-Thorne temperature profile, in the "
                "matter's own frame (each ring is seen at g T)";
            help.page = kBlackHoles;
            help.section = kDisk;
        }
    }
    return help;
}

std::string FieldGuide::tooltip(const std::string& accepted) const {
    std::ostringstream s;
    s << field;
    if (!meaning.empty()) s << ": " << meaning;
    if (!unit.empty()) s << "\nunit: " << unit;
    if (!choices.empty()) {
        s << "\nchoices: ";
        for (std::size_t k = 0; k < choices.size(); ++k) s << (k ? ", " : "") << choices[k];
    }
    if (!accepted.empty()) s << "\naccepted: " << accepted;
    s << "\nF1: the guide, \"" << section << "\" (" << page << ")";
    return s.str();
}

const std::vector<std::string>& guidePages() {
    static const std::vector<std::string> pages{kIndex, kGodel, kBlackHoles, kSpecialRelativity, kTypedMetrics};
    return pages;
}

}  // namespace lc::io
