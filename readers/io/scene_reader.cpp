// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/scene_reader.hpp"

#include "core/accretion/thin_disk.hpp"
#include "core/godel/proper_time_world_line.hpp"
#include "core/metrics/factory.hpp"
#include "core/scene/godel_placement.hpp"
#include "core/render/render.hpp"
#include "core/render/special_relativity.hpp"
#include "core/scene/frame_camera.hpp"
#include "core/scene/star_sky.hpp"
#include "core/spacetime/named_observer.hpp"
#include "core/metrics/godel.hpp"
#include "core/spacetime/metric_check.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/input_file.hpp"
#include "readers/io/metric_file.hpp"

#include <algorithm>
#include <map>
#include <cstdio>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace lc::io {
namespace fs = std::filesystem;
namespace {

Vec3 vec3(const JsonNode& n, const input::Range& eachInRange) {
    const auto v = n.numbers(3, eachInRange);
    return Vec3(v[0], v[1], v[2]);
}

// An event in the metric's chart. Goedel events must also lie where the isometries that move
// them to the axis stay accurate (input::kGodelAxisDistance).
Vec4 event(const JsonNode& n, const Spacetime& st) {
    const auto v = n.numbers(4, input::kCoordinate);
    const Vec4 x(v[0], v[1], v[2], v[3]);
    if (const auto a = st.godelRadius()) {
        const double r = std::hypot(x(1), x(2)) / *a;
        if (!input::kGodelAxisDistance.contains(r))
            n.fail("Goedel events must lie within r = " + input::formatBound(input::kGodelAxisDistance.max) +
                       " a of the axis; this one is at r = " + input::formatBound(r) + " a",
                   "the observer's horizon is at r = 2a: nothing farther is seen from the axis");
    }
    return x;
}

// Names label exported files and the GUI: printable, no path separators, not hidden.
std::string objectName(const JsonNode& o, const std::string& fallback) {
    if (!o.has("name")) return fallback;
    const JsonNode n = o.at("name");
    const std::string s = n.string();
    const bool printable = std::all_of(s.begin(), s.end(), [](char c) {
        return static_cast<unsigned char>(c) >= 0x20 && c != 0x7f && c != '/' && c != '\\';
    });
    if (s.empty() || s.size() > 64 || !printable || s.front() == '.')
        n.fail("a name is 1 to 64 printable characters without '/', '\\' or a leading '.'",
               "it also names exported files");
    return s;
}

SpacetimePtr readMetric(const JsonNode& m, const std::string& baseDir) {
    if (isFormulaMetricBlock(m)) return readFormulaMetric(m, baseDir);
    const std::string name = m.at("name").string();
    std::map<std::string, double> params;
    std::vector<std::string> known{"name"};
    const MetricDescription* desc = nullptr;
    for (const auto& d : knownMetrics())
        if (d.name == name) desc = &d;
    if (desc)
        for (const auto& p : desc->parameters) known.push_back(p.name);
    m.allowOnly(known);
    if (desc)
        for (const auto& p : desc->parameters)
            if (m.has(p.name)) params[p.name] = m.at(p.name).number(p.range());
    try {
        return makeSpacetime(name, params);
    } catch (const std::invalid_argument& e) {
        m.fail(e.what(), "see docs/SCENES.md for the metrics and their parameters");
    }
}

// "sky": {"type": "stars", ...}: a random field of black-body stars (lc::StarSky, docs/SCENES.md).
TexturePtr readStarSky(const JsonNode& t) {
    t.allowOnly({"type", "stars", "seed", "temperatures", "faintest_magnitude", "size"});
    StarFieldRecipe recipe;
    if (t.has("stars")) recipe.stars = t.at("stars").integer(input::kStars);
    if (t.has("seed")) recipe.seed = static_cast<std::uint32_t>(t.at("seed").integer(input::kStarSeed));
    if (t.has("temperatures")) {
        const JsonNode range = t.at("temperatures");
        if (range.size() != 2) range.fail("expected two temperatures", "\"temperatures\": [coolest, hottest] in K");
        recipe.minTemperature = range[0].number(input::kTemperature);
        recipe.maxTemperature = range[1].number(input::kTemperature);
        if (recipe.maxTemperature < recipe.minTemperature)
            range.fail("the hottest below the coolest", "\"temperatures\": [coolest, hottest] in K");
    }
    if (t.has("faintest_magnitude"))
        recipe.faintestMagnitude = t.at("faintest_magnitude").number(input::kStarMagnitude);
    const double size = t.has("size") ? t.at("size").number(input::kStarSize) : 0.25;
    return std::make_shared<StarSky>(randomStars(recipe), size);
}

TexturePtr readTexture(const JsonNode& t, const std::string& baseDir, const SceneReadOptions& options,
                       bool sky = false) {
    if (t.isString()) {  // shorthand: "checker", "earth" or a file name
        try {
            return textureFromName(t.string(), baseDir, options);
        } catch (const std::exception& e) {
            t.fail(e.what(), builtinTexturePath(t.string()).empty() ? "paths are relative to the scene file"
                                                                    : "install Debian's xplanet-images");
        }
    }
    const std::string type = t.at("type").string();
    if (sky && type == "stars") return readStarSky(t);
    if (sky)
        t.allowOnly({"type", "cells", "colors", "color", "temperature"});
    else
        t.allowOnly({"type", "cells", "colors", "color"});
    if (type == "checker") {
        int nu = 16, nv = 8;
        if (t.has("cells")) {
            const JsonNode c = t.at("cells");
            c.size(1, 2);
            nu = c[0].integer(input::kCheckerCells);
            nv = c.size() > 1 ? c[1].integer(input::kCheckerCells) : nu;
        }
        Vec3 a(0.9, 0.9, 0.9), b(0.15, 0.25, 0.7);
        if (t.has("colors")) {
            const JsonNode c = t.at("colors");
            if (c.size() != 2) c.fail("expected two colours", "\"colors\": [[r,g,b], [r,g,b]]");
            a = vec3(c[0], input::kColourComponent);
            b = vec3(c[1], input::kColourComponent);
        }
        return std::make_shared<CheckerTexture>(nu, nv, a, b);
    }
    if (type == "solid") return std::make_shared<SolidTexture>(vec3(t.at("color"), input::kColourComponent));
    t.at("type").fail("unknown texture type '" + type + "'", "use checker, solid, earth, or an image file name");
}

// Goedel: an object's own frame is its centre's local chart (through the isometry that moves
// the centre to the origin); elsewhere a translation of the Cartesian chart.
PlacementPtr placementFor(const Spacetime& st, const Vec4& centre) {
    if (const auto a = st.godelRadius()) return std::make_shared<GodelPlacement>(*a, centre);
    return std::make_shared<TranslationPlacement>(centre.tail<3>());
}

// motion.type constant_velocity (minkowski only): a velocity beta below c.
void readConstantVelocity(const JsonNode& m, const Spacetime& st, Motion& motion) {
    m.allowOnly({"type", "beta"});
    if (st.name() != "minkowski")
        m.at("type").fail("constant velocity needs the minkowski metric",
                          "in curved spacetimes use free_fall or world_line");
    motion.kind = Motion::Kind::ConstantVelocity;
    static const input::Range betaComponent{"beta component", -1, 1, false, "c", ""};
    motion.beta = vec3(m.at("beta"), betaComponent);
    if (!input::kSpeed.contains(motion.beta.norm()))
        m.at("beta").fail("speed |beta| = " + input::formatBound(motion.beta.norm()) + ": " +
                              input::kSpeed.problem(motion.beta.norm()),
                          "|beta| must be below the speed of light");
}

// motion.type free_fall (godel only): the geodesic's constants k0 (or a speed), k3, phi0.
void readFreeFall(const JsonNode& m, bool godel, Motion& motion) {
    m.allowOnly({"type", "k0", "k3", "phi0", "speed"});
    if (!godel) m.at("type").fail("free fall is available in the godel metric", "use world_line elsewhere");
    motion.kind = Motion::Kind::FreeFall;
    if (m.has("k3")) motion.k3 = m.at("k3").number(input::kFreeFallK3);
    if (m.has("phi0")) motion.phi0 = m.at("phi0").number(input::kAngle);
    if (m.has("speed") && m.has("k0")) m.at("k0").fail("give either speed or k0, not both");
    if (m.has("speed")) {
        // Speed v relative to the static observer at the centre event: there the chart is
        // Minkowskian, so k0 = p_t = gamma, and k3 = gamma v_z must not exceed gamma v.
        const double v = m.at("speed").number(input::kSpeed);
        motion.k0 = 1 / std::sqrt((1 - v) * (1 + v));
    } else if (m.has("k0")) {
        motion.k0 = m.at("k0").number(input::kFreeFallEnergy);
    }
    if (!(std::abs(motion.k0) >= std::sqrt(1 + motion.k3 * motion.k3)))
        m.fail("free fall needs |k0| >= sqrt(1 + k3^2) (timelike geodesic)", "raise k0 or lower k3");
}

// motion.type world_line: events of increasing time, moved along by the reader's chart.
void readWorldLineEvents(const JsonNode& m, const Spacetime& st, Motion& motion) {
    m.allowOnly({"type", "points"});
    motion.kind = Motion::Kind::WorldLine;
    const JsonNode pts = m.at("points");
    const std::size_t n = pts.size(static_cast<std::size_t>(input::kWorldLineEvents.min),
                                   static_cast<std::size_t>(input::kWorldLineEvents.max));
    motion.points.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        motion.points.push_back(event(pts[i], st));
        if (i > 0 && !(motion.points[i](0) > motion.points[i - 1](0))) pts[i].fail("events must have increasing time");
    }
}

// One entry of motion.segments (rest, free_fall, radial, circle, rocket, samples).
godel::WorldLineSegment readSegment(const JsonNode& s) {
    const std::string kind = s.at("type").string();
    godel::WorldLineSegment seg;
    if (kind == "rest" || kind == "free_fall") {
        s.allowOnly({"type", "proper_time"});
        seg.kind = kind == "rest" ? godel::WorldLineSegment::Kind::Rest : godel::WorldLineSegment::Kind::FreeFall;
        seg.properTime = s.at("proper_time").number(input::kProperTimeSpan);
    } else if (kind == "radial") {
        s.allowOnly({"type", "speed", "to_radius"});
        seg.kind = godel::WorldLineSegment::Kind::Radial;
        seg.speed = s.at("speed").number(input::kSpeed);
        seg.toRadius = s.at("to_radius").number(input::kLength);
    } else if (kind == "circle") {
        s.allowOnly({"type", "dt_dphi", "turns"});
        seg.kind = godel::WorldLineSegment::Kind::Circle;
        seg.dtDphi = s.at("dt_dphi").number(input::kCircleDtDphi);
        seg.turns = s.at("turns").number(input::kCircleTurns);
    } else if (kind == "rocket") {
        s.allowOnly({"type", "acceleration", "proper_time", "direction"});
        seg.kind = godel::WorldLineSegment::Kind::Rocket;
        seg.acceleration = s.at("acceleration").number(input::kRocketAcceleration);
        seg.properTime = s.at("proper_time").number(input::kRocketBurnTime);
        using T = godel::WorldLineSegment::Thrust;
        const std::string d = s.string("direction", "outward");
        const std::map<std::string, T> thrusts{
            {"outward", T::Outward},       {"inward", T::Inward}, {"prograde", T::Prograde},
            {"retrograde", T::Retrograde}, {"up", T::Up},         {"down", T::Down}};
        if (!thrusts.count(d))
            s.at("direction")
                .fail("unknown direction '" + d + "'", "use outward, inward, prograde, retrograde, up or down");
        seg.thrust = thrusts.at(d);
    } else if (kind == "samples") {
        s.allowOnly({"type", "points"});
        seg.kind = godel::WorldLineSegment::Kind::Samples;
        const JsonNode pts = s.at("points");
        const std::size_t np = pts.size(static_cast<std::size_t>(input::kWorldLineEvents.min),
                                        static_cast<std::size_t>(input::kWorldLineEvents.max));
        for (std::size_t i = 0; i < np; ++i) {
            const auto v = pts[i].numbers(5, input::kCoordinate);
            seg.samples.emplace_back(v[0], Vec4(v[1], v[2], v[3], v[4]));
        }
    } else {
        s.at("type").fail("unknown segment type '" + kind + "'",
                          "use rest, radial, circle, free_fall, rocket or samples");
    }
    return seg;
}

// motion.type segments (godel only): a world line by proper time from the centre event
// (docs/SCENES.md, docs/PHYSICS.md section 11); a segment the world line refuses is named by its field.
void readSegments(const JsonNode& m, const Spacetime& st, const Vec4& centre, Motion& motion) {
    m.allowOnly({"type", "segments"});
    const auto godelA = st.godelRadius();
    if (!godelA) m.at("type").fail("segments are available in the godel metric", "use world_line elsewhere");
    const JsonNode list = m.at("segments");
    const std::size_t n = list.size(static_cast<std::size_t>(input::kWorldLineSegments.min),
                                    static_cast<std::size_t>(input::kWorldLineSegments.max));
    std::vector<godel::WorldLineSegment> segments;
    for (std::size_t k = 0; k < n; ++k) segments.push_back(readSegment(list[k]));
    motion.kind = Motion::Kind::ProperTime;
    try {
        motion.properTimeLine = std::make_shared<const godel::ProperTimeWorldLine>(*godelA, centre, segments);
    } catch (const std::invalid_argument& e) {
        // "world line segment k (kind): why" -> the field of that segment.
        const std::string what = e.what();
        std::size_t k = 0;
        if (std::sscanf(what.c_str(), "world line segment %zu", &k) == 1 && k < n) list[k].fail(what);
        m.fail(what);
    }
}

Motion readMotion(const JsonNode& m, const Spacetime& st, const Vec4& centre) {
    Motion motion;
    if (m.isString()) {
        if (m.string() != "rest")
            m.fail("unknown motion '" + m.string() + "'", "use \"rest\" or an object with a type");
        return motion;
    }
    const std::string type = m.at("type").string();
    if (type == "rest")
        m.allowOnly({"type"});
    else if (type == "constant_velocity")
        readConstantVelocity(m, st, motion);
    else if (type == "free_fall")
        readFreeFall(m, st.godelRadius().has_value(), motion);
    else if (type == "world_line")
        readWorldLineEvents(m, st, motion);
    else if (type == "segments")
        readSegments(m, st, centre, motion);
    else
        m.at("type").fail("unknown motion type '" + type + "'",
                          "use rest, constant_velocity, free_fall, world_line or segments");
    return motion;
}

TexturePtr defaultObjectTexture() {
    return std::make_shared<CheckerTexture>(16, 8, Vec3(0.9, 0.9, 0.9), Vec3(0.7, 0.2, 0.1));
}

double readTemperature(const JsonNode& o) {
    if (!o.has("temperature")) return 0;
    return o.at("temperature").number(input::kTemperature);
}

SphereObject readSphere(const JsonNode& o, const Spacetime& st, const std::string& baseDir,
                        const SceneReadOptions& options) {
    o.allowOnly({"type", "name", "centre", "radius", "texture", "night_texture", "motion", "temperature"});
    SphereObject s;
    s.name = objectName(o, "sphere");
    s.centre = event(o.at("centre"), st);
    s.radius = o.at("radius").number(input::kLength);
    s.placement = placementFor(st, s.centre);
    s.texture = o.has("texture") ? readTexture(o.at("texture"), baseDir, options) : defaultObjectTexture();
    if (o.has("night_texture")) s.nightTexture = readTexture(o.at("night_texture"), baseDir, options);
    if (o.has("motion")) s.motion = readMotion(o.at("motion"), st, s.centre);
    s.temperature = readTemperature(o);
    return s;
}

// A thin accretion disk in the equatorial plane (kerr-newman family only); its orbits and flux are
// computed here, once per scene.
DiskObject readDisk(const JsonNode& o, const SpacetimePtr& st, const std::string& baseDir,
                    const SceneReadOptions& options) {
    o.allowOnly({"type", "name", "inner_radius", "outer_radius", "sense", "emission", "temperature", "texture"});
    DiskObject d;
    d.name = objectName(o, "disk");
    // "isco" (the default) or a radius at or beyond it.
    double inner = 0;
    if (o.has("inner_radius")) {
        const JsonNode in = o.at("inner_radius");
        if (in.isString() && in.string() != "isco")
            in.fail("expected \"isco\" or a number in [" + input::formatBound(input::kDiskRadius.min) + ", " +
                    input::formatBound(input::kDiskRadius.max) + "], got '" + in.string() + "'");
        if (!in.isString()) inner = in.number(input::kDiskRadius);
    }
    const double outer = o.has("outer_radius") ? o.at("outer_radius").number(input::kDiskRadius) : 20.0;
    const std::string sense = o.string("sense", "prograde");
    if (sense != "prograde" && sense != "retrograde")
        o.at("sense").fail("unknown sense '" + sense + "'", "use prograde (turning with the hole) or retrograde");
    const std::string emission = o.string("emission", "blackbody");
    if (emission == "blackbody")
        d.emission = DiskObject::Emission::Blackbody;
    else if (emission == "flux")
        d.emission = DiskObject::Emission::Flux;
    else if (emission == "texture")
        d.emission = DiskObject::Emission::Texture;
    else
        o.at("emission").fail("unknown emission '" + emission + "'", "use blackbody, flux or texture");
    if (o.has("temperature")) d.temperature = o.at("temperature").number(input::kTemperature);
    d.texture = o.has("texture") ? readTexture(o.at("texture"), baseDir, options)
                                 : std::make_shared<CheckerTexture>(24, 8, Vec3(0.95, 0.8, 0.4), Vec3(0.5, 0.15, 0.05));
    try {
        d.model = std::make_shared<ThinDiskModel>(st, inner, outer, sense == "prograde");
    } catch (const std::invalid_argument& e) {
        const std::string why = e.what();
        const char* field = why.find("metric") != std::string::npos ? "type"
                            : why.find("outer") == 0                ? "outer_radius"
                                                                    : "inner_radius";
        (o.has(field) ? o.at(field) : o).fail(why);
    }
    return d;
}

// Box of edge lengths `size`, each face split into n x n squares (two triangles each), faces
// not sharing vertices so that normals are flat.
void makeBox(const Vec3& size, int n, MeshObject& m) {
    const Vec3 h = 0.5 * size;
    for (int axis = 0; axis < 3; ++axis)
        for (int sign : {-1, 1}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            Vec3 normal = Vec3::Zero();
            normal(axis) = sign;
            const int base = static_cast<int>(m.positions.size());
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) {
                    Vec3 p;
                    p(axis) = sign * h(axis);
                    p(u) = -h(u) + size(u) * i / n;
                    p(v) = -h(v) + size(v) * j / n;
                    m.positions.push_back(p);
                    m.normals.push_back(normal);
                }
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const int a = base + i * (n + 1) + j, b = a + (n + 1), c = b + 1, d = a + 1;
                    // Counter-clockwise seen from outside.
                    if (sign > 0) {
                        m.triangles.push_back({a, b, c});
                        m.triangles.push_back({a, c, d});
                    } else {
                        m.triangles.push_back({a, c, b});
                        m.triangles.push_back({a, d, c});
                    }
                }
        }
}

MeshObject readMesh(const JsonNode& o, const Spacetime& st, const std::string& baseDir, const SceneReadOptions& opt) {
    const std::string type = o.at("type").string();
    MeshObject m;
    m.centre = event(o.at("centre"), st);
    if (type == "box") {
        o.allowOnly({"type", "name", "centre", "size", "subdivisions", "texture", "motion", "temperature"});
        m.name = objectName(o, "box");
        m.source = "box";
        const Vec3 size = vec3(o.at("size"), input::kLength);
        makeBox(size, o.has("subdivisions") ? o.at("subdivisions").integer(input::kBoxSubdivisions) : 10, m);
    } else {
        o.allowOnly({"type", "name", "centre", "file", "scale", "texture", "motion", "temperature"});
        m.name = objectName(o, "mesh");
        const std::string file = o.at("file").string();
        m.source = fs::path(file).is_absolute() ? file : (fs::path(baseDir) / file).string();
        if (!opt.meshLoader)
            o.at("file").fail("this program was built without a mesh reader",
                              "build with VTK (the default) to read OBJ, PLY, STL and VTP");
        try {
            opt.meshLoader(m.source, m);
        } catch (const std::exception& e) {
            o.at("file").fail(
                std::string("cannot use mesh '") + m.source + "': " + e.what(),
                "OBJ, PLY, STL and VTP files with at least one triangle; paths are relative to the scene file");
        }
        if (m.triangles.empty())
            o.at("file").fail("mesh '" + m.source + "' has no triangles", "an empty mesh cannot be drawn");
        const double scale = o.has("scale") ? o.at("scale").number(input::kScale) : 1.0;
        for (auto& p : m.positions) p *= scale;
    }
    m.texture = o.has("texture") ? readTexture(o.at("texture"), baseDir, opt) : defaultObjectTexture();
    if (o.has("motion")) m.motion = readMotion(o.at("motion"), st, m.centre);
    m.temperature = readTemperature(o);
    return m;
}

PointLight readLight(const JsonNode& l, const Spacetime& st) {
    l.allowOnly({"name", "position", "temperature", "intensity"});
    PointLight p;
    p.name = objectName(l, "light");
    p.position = event(l.at("position"), st);
    if (l.has("temperature")) p.temperature = l.at("temperature").number(input::kTemperature);
    if (l.has("intensity")) p.intensity = l.at("intensity").number(input::kLightIntensity);
    return p;
}

Camera readCamera(const JsonNode& c) {
    c.allowOnly({"projection", "width", "height", "fov", "forward", "up", "look_at"});
    Camera cam;
    const std::string proj = c.string("projection", "pinhole");
    if (proj == "pinhole")
        cam.projection = Camera::Projection::Pinhole;
    else if (proj == "panorama")
        cam.projection = Camera::Projection::Panorama;
    else
        c.at("projection").fail("unknown projection '" + proj + "'", "use pinhole or panorama");
    if (c.has("width")) cam.width = c.at("width").integer(input::kImageSide);
    if (c.has("height")) cam.height = c.at("height").integer(input::kImageSide);
    if (c.has("fov")) {
        const auto f = c.at("fov").numbers(2, input::kFieldOfView);
        cam.fovXDeg = f[0];
        cam.fovYDeg = f[1];
    }
    if (c.has("forward")) cam.forward = vec3(c.at("forward"), input::kDirectionComponent);
    if (c.has("up")) cam.up = vec3(c.at("up"), input::kDirectionComponent);
    if (c.has("look_at")) {
        if (c.has("forward"))
            c.at("look_at").fail("both forward and look_at are given", "give one: look_at sets forward");
        cam.lookAt = vec3(c.at("look_at"), input::kCoordinate);
    }
    try {
        cam.validate();
    } catch (const std::invalid_argument& e) {
        c.fail(e.what());
    }
    return cam;
}

void readRender(const JsonNode& r, RenderSettings& s) {
    r.allowOnly({"stepper", "tolerance", "windings", "max_affine", "escape_radius", "escape_angle", "max_steps",
                 "initial_step", "method", "threads", "mesh_resolution", "magnification"});
    if (r.has("mesh_resolution")) {
        const JsonNode m = r.at("mesh_resolution");
        m.size(1, 2);
        s.meshLatitudes = m[0].integer(input::kMeshLatitudes);
        s.meshLongitudes = m.size() > 1 ? m[1].integer(input::kMeshLongitudes) : 2 * s.meshLatitudes;
        const double vertices = double(s.meshLatitudes) * s.meshLongitudes;
        if (!input::kMeshResolutionVertices.contains(vertices))
            m.fail(input::kMeshResolutionVertices.problem(vertices));
    }
    try {
        if (r.has("stepper")) setSceneStepper(s, r.at("stepper").string());
    } catch (const std::invalid_argument& e) {
        r.at("stepper").fail(e.what());
    }
    if (r.has("tolerance")) s.trace.absTol = s.trace.relTol = r.at("tolerance").number(input::kTolerance);
    if (r.has("windings")) s.windings = r.at("windings").integer(input::kWindings);
    if (r.has("max_affine")) s.trace.maxAffine = r.at("max_affine").number(input::kMaxAffine);
    if (r.has("escape_radius")) s.trace.escapeRadius = r.at("escape_radius").number(input::kEscapeRadius);
    if (r.has("escape_angle")) s.trace.escapeAngle = r.at("escape_angle").number(input::kEscapeAngle);
    if (r.has("max_steps")) s.trace.maxSteps = static_cast<std::size_t>(r.at("max_steps").integer(input::kMaxSteps));
    if (r.has("initial_step")) s.trace.initialStep = r.at("initial_step").number(input::kInitialStep);
    if (r.has("threads")) s.threads = r.at("threads").integer(input::kThreads);
    if (r.has("magnification")) s.magnification = r.at("magnification").boolean();
    const std::string method = r.string("method", "auto");
    try {
        s.method = parseRenderMethod(method);
    } catch (const std::invalid_argument& e) {
        r.at("method").fail(e.what());
    }
}

// [FROM, TO] of one path; the frame count is the block's.
FrameInterval interval(const JsonNode& node, const input::Range& range, int frames) {
    const auto v = node.numbers(2, range);
    return FrameInterval{v[0], v[1], frames};
}

AnimationPath readAnimation(const JsonNode& a) {
    a.allowOnly({"frames", "proper_time", "motion", "pan", "orbit", "sweep"});
    const int frames = a.at("frames").integer(input::kAnimationFrames);
    AnimationPath path;
    if (a.has("proper_time")) path.properTime = interval(a.at("proper_time"), input::kCoordinate, frames);
    if (a.has("motion")) {
        if (!a.has("proper_time")) a.at("motion").fail("motion goes with proper_time");
        try {
            path.motion = parseObserverMotion(a.at("motion").string());
        } catch (const std::invalid_argument& e) {
            a.at("motion").fail(e.what());
        }
    }
    if (a.has("pan")) path.panDegrees = interval(a.at("pan"), input::kTurnDegrees, frames);
    if (a.has("orbit")) path.orbitDegrees = interval(a.at("orbit"), input::kTurnDegrees, frames);
    if (a.has("sweep")) {
        const JsonNode w = a.at("sweep");
        w.allowOnly({"field", "from", "to"});
        static const input::Range anyField{"scene field", -1e12, 1e12, false, "", ""};
        path.sweep = FieldSweep{w.at("field").string(),
                                FrameInterval{w.at("from").number(anyField), w.at("to").number(anyField), frames}};
        if (path.sweep->field.rfind("animation", 0) == 0)
            w.at("field").fail("a sweep cannot change the animation itself");
    }
    if (path.empty()) a.fail("an animation needs a path: proper_time, pan, orbit or sweep");
    return path;
}

}  // namespace

TexturePtr textureFromName(const std::string& name, const std::string& baseDir, const SceneReadOptions& options) {
    if (name == "checker") return std::make_shared<CheckerTexture>(16, 8, Vec3(0.9, 0.9, 0.9), Vec3(0.15, 0.25, 0.7));
    const std::string builtin = builtinTexturePath(name);
    const std::string path =
        !builtin.empty() ? builtin : (fs::path(name).is_absolute() ? name : (fs::path(baseDir) / name).string());
    auto load = [&path]() -> TexturePtr {
        const ImageChannels img = readImageRgb(path);
        return std::make_shared<ImageTexture>(img.width, img.height, img.data);
    };
    try {
        return options.textures ? options.textures->get(path, load) : load();
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("cannot load texture: ") + e.what());
    }
}

TexturePtr TextureCache::get(const std::string& path, const std::function<TexturePtr()>& load) {
    std::error_code e1, e2;
    const auto modified = fs::last_write_time(path, e1);
    const auto size = fs::file_size(path, e2);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        const auto it = entries_.find(path);
        if (!e1 && !e2 && it != entries_.end() && it->second.modified == modified && it->second.size == size)
            if (TexturePtr held = it->second.texture.lock()) return held;
    }
    TexturePtr texture = load();  // read outside the lock; throws as an uncached read would
    if (!e1 && !e2) {
        std::lock_guard<std::mutex> lock(mutex_);
        entries_[path] = Entry{modified, size, texture};
    }
    return texture;
}

std::string builtinTexturePath(const std::string& name) {
    if (name == "earth") return "/usr/share/xplanet/images/earth.jpg";
    if (name == "earth-night") return "/usr/share/xplanet/images/night.jpg";
    return "";
}

SpacetimePtr metricFromBlock(const Json::Value& metric, const std::string& nameForMessages,
                             const std::string& baseDir) {
    Json::Value root(Json::objectValue);
    root["metric"] = metric;
    Json::StreamWriterBuilder writer;
    const auto doc = JsonDocument::parse(Json::writeString(writer, root), nameForMessages);
    return readMetric(doc->root().at("metric"), baseDir);
}

std::string formatEvent(const Vec4& x) {
    std::string s = "(";
    for (int k = 0; k < 4; ++k) s += (k ? ", " : "") + input::formatBound(x(k));
    return s + ")";
}

Scene sceneFromDocument(const JsonDocument& doc, const std::string& baseDir, const SceneReadOptions& options) {
    const std::string& name = doc.file();
    const JsonNode root = doc.root();
    root.allowOnly({"description", "metric", "observer", "camera", "objects", "lights", "sky", "other_sky",
                    "background", "render", "animation"});
    Scene scene;
    scene.source = name;
    scene.spacetime = readMetric(root.at("metric"), baseDir);
    if (root.has("observer")) {
        const JsonNode o = root.at("observer");
        o.allowOnly({"position", "velocity"});
        if (o.has("position")) scene.observer = event(o.at("position"), *scene.spacetime);
        // Where the metric itself fails (a black hole's centre, a polar chart's axis) no observer can
        // be: said first, before a velocity computed there reads as the cause.
        if (const std::string problem = metricProblemAt(*scene.spacetime, scene.observer); !problem.empty())
            (o.has("position") ? o.at("position") : o)
                .fail("the metric cannot serve at the observer's event " + formatEvent(scene.observer) + ": " +
                          problem +
                          (problem.find("det g") != std::string::npos
                               ? " (a coordinate singularity, such as a polar chart's axis)"
                           : problem.find("Lorentzian") != std::string::npos
                               ? ""
                               : " (a singularity of the spacetime or of its chart, such as a black hole's centre)"),
                      scene.spacetime->asymptoticallyFlat()
                          ? "move the observer away from it, e.g. [0, -30, 0, 0] is 30 M from a hole at the origin"
                          : "move the observer, or check the metric with 'lightcone metric check' --at t,x,y,z");
        if (o.has("velocity") && o.at("velocity").isString()) {
            // A named observer (core/spacetime/named_observer.hpp), built where the observer is.
            const JsonNode v = o.at("velocity");
            const std::optional<NamedObserver> named = namedObserverFrom(v.string());
            if (!named)
                v.fail("unknown observer '" + v.string() + "'",
                       "use one of " + namedObserverNames() + ", or four numbers (a 4-velocity)");
            try {
                scene.observerVelocity = namedObserverVelocity(*scene.spacetime, scene.observer, *named);
            } catch (const std::invalid_argument& e) {
                v.fail(e.what());
            }
        } else if (o.has("velocity")) {
            const auto v = o.at("velocity").numbers(4, input::kObserverVelocityComponent);
            scene.observerVelocity = Vec4(v[0], v[1], v[2], v[3]);
        }
        const Mat4 g = scene.spacetime->metric(scene.observer);
        const double uu = scene.observerVelocity.dot(g * scene.observerVelocity);
        if (!(uu > 0) || scene.observerVelocity(0) <= 0) {
            if (!o.has("velocity")) {
                // The static observer, implied: why it does not exist here (an ergoregion, a
                // horizon, a warp bubble faster than light) and which observers do.
                try {
                    (void)namedObserverVelocity(*scene.spacetime, scene.observer, NamedObserver::Static);
                } catch (const std::invalid_argument& e) {
                    o.fail(
                        std::string("the observer is static unless observer.velocity says otherwise, and ") + e.what(),
                        "give observer.velocity: a name or four numbers (docs/SCENES.md)");
                }
            }
            const Boundary edge = scene.spacetime->boundary(scene.observer);
            (o.has("velocity") ? o.at("velocity") : o)
                .fail("the observer's 4-velocity is not future timelike here (g(u,u) = " + std::to_string(uu) +
                          " in the (+,-,-,-) signature Lightcone computes in, where timelike is g(u,u) > 0 and "
                          "future u^t > 0)" +
                          (edge == Boundary::Horizon       ? "; the event is at or inside the metric's horizon"
                           : edge == Boundary::Singularity ? "; the event is at the metric's singularity"
                                                           : ""),
                      "the named observers other than the static one that exist here: " +
                          namedObserversAt(*scene.spacetime, scene.observer) + " (docs/SCENES.md)");
        }
        // Minkowski scenes go to the special-relativity renderer, which draws from an observer at rest
        // in the chart: refused here, so that an edit (a metric changed in the workbench) cannot
        // leave a scene no renderer draws.
        if (isSrScene(scene) && scene.observerVelocity.tail<3>().norm() > 0)
            o.at("velocity")
                .fail("special relativity draws from an observer at rest in the minkowski chart",
                      "remove observer.velocity and give the objects the opposite velocity "
                      "(motion constant_velocity)");
        // Lorentz factor against the static observer e0 = d/dt / sqrt(g_tt), where there is one.
        if (g(0, 0) > 0) {
            const double gamma = (g * scene.observerVelocity)(0) / std::sqrt(uu * g(0, 0));
            if (!input::kObserverGamma.contains(gamma))
                o.at("velocity")
                    .fail("the observer moves with Lorentz factor " + input::formatBound(gamma) +
                          " relative to the static observer: " + input::kObserverGamma.problem(gamma));
        }
    }
    if (root.has("camera")) {
        const JsonNode c = root.at("camera");
        scene.camera = readCamera(c);
        try {  // the chart directions seen at the observer's event: not parallel there, look_at not the observer
            (void)frameCamera(scene);
        } catch (const std::exception& e) {
            (c.has("look_at") ? c.at("look_at") : c).fail(e.what());
        }
    }
    if (root.has("objects")) {
        const JsonNode objs = root.at("objects");
        const std::size_t n = objs.size(0, static_cast<std::size_t>(input::kObjects.max));
        for (std::size_t i = 0; i < n; ++i) {
            const JsonNode o = objs[i];
            const std::string type = o.at("type").string();
            if (type == "sphere")
                scene.spheres.push_back(readSphere(o, *scene.spacetime, baseDir, options));
            else if (type == "box" || type == "mesh")
                scene.meshes.push_back(readMesh(o, *scene.spacetime, baseDir, options));
            else if (type == "disk") {
                if (!scene.disks.empty())
                    o.at("type").fail("a second disk", "a scene has one equatorial plane: give one disk");
                scene.disks.push_back(readDisk(o, scene.spacetime, baseDir, options));
            } else
                o.at("type").fail("unknown object type '" + type + "'", "use sphere, box, mesh or disk");
        }
    }
    if (root.has("lights")) {
        const JsonNode lights = root.at("lights");
        const std::size_t n = lights.size(0, static_cast<std::size_t>(input::kLights.max));
        for (std::size_t i = 0; i < n; ++i) scene.lights.push_back(readLight(lights[i], *scene.spacetime));
    }
    if (root.has("sky")) {
        const JsonNode sky = root.at("sky");
        scene.sky = readTexture(sky, baseDir, options, true);
        if (scene.sky->lightMap() && !scene.spacetime->asymptoticallyFlat())
            sky.at("type").fail("a star sky shines from infinity: " + scene.spacetime->name() + " has none",
                                "asymptotically flat metrics (schwarzschild, kerr, kerr-newman, alcubierre, formulas "
                                "with \"far_field\") take it");
        if (sky.isObject() && sky.has("temperature")) {
            if (!scene.spacetime->asymptoticallyFlat())
                sky.at("temperature")
                    .fail("a black-body sky shines from infinity: " + scene.spacetime->name() + " has none",
                          "asymptotically flat metrics (schwarzschild, kerr, kerr-newman, alcubierre, formulas with "
                          "\"far_field\") take it");
            scene.skyTemperature = sky.at("temperature").number(input::kSkyTemperature);
        }
    } else if (scene.spacetime->asymptoticallyFlat())
        scene.sky = std::make_shared<CheckerTexture>(36, 18, Vec3(0.85, 0.85, 0.85), Vec3(0.1, 0.1, 0.1));
    // A two-ended metric's far side has a sky of its own: by default an orange checkerboard, so
    // the two ends tell apart at a glance.
    if (root.has("other_sky")) {
        const JsonNode other = root.at("other_sky");
        if (!scene.spacetime->hasOtherEnd())
            other.fail("a far end's sky: " + scene.spacetime->name() + " has one end",
                       "two-ended metrics (a metric file with \"other_end\", as metrics/ellis_wormhole.json) take it");
        if (other.isObject() && other.has("temperature"))
            other.at("temperature").fail("a black-body sky is drawn on this side only", "give the far side a texture");
        scene.otherSky = readTexture(other, baseDir, options, true);
    } else if (scene.spacetime->hasOtherEnd())
        scene.otherSky = std::make_shared<CheckerTexture>(36, 18, Vec3(0.95, 0.6, 0.25), Vec3(0.2, 0.08, 0.03));
    if (root.has("background")) scene.background = vec3(root.at("background"), input::kColourComponent);
    if (root.has("render")) readRender(root.at("render"), scene.settings);
    if (root.has("animation")) scene.animation = readAnimation(root.at("animation"));
    // Goedel rays never escape: follow them for the requested number of windings.
    scene.settings.trace.maxAffine =
        std::min(scene.settings.trace.maxAffine, affineLengthForWindings(*scene.spacetime, scene.settings.windings));
    if (isFormulaMetricBlock(root.at("metric")) && !scene.spacetime->asymptoticallyFlat() &&
        !std::isfinite(scene.settings.trace.maxAffine))
        root.at("metric").fail("rays of a metric that is not asymptotically flat never escape: they need an end",
                               "give the metric a \"far_field\" (docs/METRICS.md) or the scene \"render\": "
                               "{\"max_affine\": L}");
    return scene;
}

Scene parseScene(const std::string& text, const std::string& name, const std::string& baseDir,
                 const SceneReadOptions& options) {
    return sceneFromDocument(*JsonDocument::parse(text, name), baseDir, options);
}

Scene readScene(const std::string& file, const SceneReadOptions& options) {
    const auto doc = JsonDocument::loadDataFile(file, false);  // "default.json": the installed scenes
    return sceneFromDocument(*doc, fs::path(doc->file()).parent_path().string(), options);
}

}  // namespace lc::io
