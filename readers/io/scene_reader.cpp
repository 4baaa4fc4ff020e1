#include "readers/io/scene_reader.hpp"

#include "core/metrics/factory.hpp"
#include "core/godel_placement.hpp"
#include "core/render.hpp"
#include "core/metrics/godel.hpp"
#include "readers/io/image_io.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace lc::io {
namespace fs = std::filesystem;
namespace {

Vec3 vec3(const JsonNode& n) {
    const auto v = n.numbers(3);
    return Vec3(v[0], v[1], v[2]);
}
Vec4 vec4(const JsonNode& n) {
    const auto v = n.numbers(4);
    return Vec4(v[0], v[1], v[2], v[3]);
}

SpacetimePtr readMetric(const JsonNode& m) {
    const std::string name = m.at("name").string();
    std::map<std::string, double> params;
    std::vector<std::string> known{"name"};
    for (const auto& d : knownMetrics())
        if (d.name == name)
            for (const auto& p : d.parameters) known.push_back(p.first);
    m.allowOnly(known);
    for (std::size_t i = 1; i < known.size(); ++i)
        if (m.has(known[i])) params[known[i]] = m.at(known[i]).number();
    try {
        return makeSpacetime(name, params);
    } catch (const std::invalid_argument& e) {
        m.fail(e.what(), "see docs/SCENES.md for the metrics and their parameters");
    }
}

TexturePtr readTexture(const JsonNode& t, const std::string& baseDir) {
    if (t.isString()) {  // shorthand: "checker", "earth" or a file name
        const std::string s = t.string();
        if (s == "checker") return std::make_shared<CheckerTexture>(16, 8, Vec3(0.9, 0.9, 0.9), Vec3(0.15, 0.25, 0.7));
        const std::string builtin = builtinTexturePath(s);
        const std::string path = !builtin.empty() ? builtin : (fs::path(s).is_absolute() ? s : (fs::path(baseDir) / s).string());
        try {
            const ImageChannels img = readImageRgb(path);
            return std::make_shared<ImageTexture>(img.width, img.height, img.data);
        } catch (const std::exception& e) {
            t.fail(std::string("cannot load texture: ") + e.what(),
                   builtin.empty() ? "paths are relative to the scene file" : "install Debian's xplanet-images");
        }
    }
    t.allowOnly({"type", "cells", "colors", "color"});
    const std::string type = t.at("type").string();
    if (type == "checker") {
        int nu = 16, nv = 8;
        if (t.has("cells")) {
            const JsonNode c = t.at("cells");
            nu = c[0].integer(1, 4096);
            nv = c.size() > 1 ? c[1].integer(1, 4096) : nu;
        }
        Vec3 a(0.9, 0.9, 0.9), b(0.15, 0.25, 0.7);
        if (t.has("colors")) {
            const JsonNode c = t.at("colors");
            if (c.size() != 2) c.fail("expected two colours", "\"colors\": [[r,g,b], [r,g,b]]");
            a = vec3(c[0]);
            b = vec3(c[1]);
        }
        return std::make_shared<CheckerTexture>(nu, nv, a, b);
    }
    if (type == "solid") return std::make_shared<SolidTexture>(vec3(t.at("color")));
    t.at("type").fail("unknown texture type '" + type + "'", "use checker, solid, earth, or an image file name");
}

// Goedel: an object's own frame is its centre's local chart (through the isometry that moves
// the centre to the origin); elsewhere a translation of the Cartesian chart.
PlacementPtr placementFor(const Spacetime& st, const Vec4& centre) {
    if (const auto* g = dynamic_cast<const GodelCartesian*>(&st)) return std::make_shared<GodelPlacement>(g->a(), centre);
    return std::make_shared<TranslationPlacement>(centre.tail<3>());
}

SphereObject readSphere(const JsonNode& o, const Spacetime& st, const std::string& baseDir) {
    o.allowOnly({"type", "name", "centre", "radius", "texture"});
    SphereObject s;
    s.name = o.string("name", "sphere");
    s.centre = vec4(o.at("centre"));
    s.radius = o.at("radius").positive();
    s.placement = placementFor(st, s.centre);
    s.texture = o.has("texture") ? readTexture(o.at("texture"), baseDir)
                                 : std::make_shared<CheckerTexture>(16, 8, Vec3(0.9, 0.9, 0.9), Vec3(0.7, 0.2, 0.1));
    return s;
}

Camera readCamera(const JsonNode& c) {
    c.allowOnly({"projection", "width", "height", "fov", "forward", "up"});
    Camera cam;
    const std::string proj = c.string("projection", "pinhole");
    if (proj == "pinhole") cam.projection = Camera::Projection::Pinhole;
    else if (proj == "panorama") cam.projection = Camera::Projection::Panorama;
    else c.at("projection").fail("unknown projection '" + proj + "'", "use pinhole or panorama");
    if (c.has("width")) cam.width = c.at("width").integer(1, 16384);
    if (c.has("height")) cam.height = c.at("height").integer(1, 16384);
    if (c.has("fov")) {
        const auto f = c.at("fov").numbers(2);
        cam.fovXDeg = f[0];
        cam.fovYDeg = f[1];
    }
    if (c.has("forward")) cam.forward = vec3(c.at("forward"));
    if (c.has("up")) cam.up = vec3(c.at("up"));
    try {
        cam.validate();
    } catch (const std::invalid_argument& e) {
        c.fail(e.what());
    }
    return cam;
}

void readRender(const JsonNode& r, RenderSettings& s) {
    r.allowOnly({"stepper", "tolerance", "windings", "max_affine", "max_steps", "initial_step", "method", "threads",
                 "mesh_resolution"});
    if (r.has("mesh_resolution")) {
        const JsonNode m = r.at("mesh_resolution");
        s.meshLatitudes = m[0].integer(3, 4096);
        s.meshLongitudes = m.size() > 1 ? m[1].integer(3, 8192) : 2 * s.meshLatitudes;
    }
    try {
        if (r.has("stepper")) s.trace.stepper = parseStepper(r.at("stepper").string());
    } catch (const std::invalid_argument& e) {
        r.at("stepper").fail(e.what());
    }
    if (r.has("tolerance")) s.trace.absTol = s.trace.relTol = r.at("tolerance").positive();
    if (r.has("windings")) s.windings = r.at("windings").integer(0, 1000);
    if (r.has("max_affine")) s.trace.maxAffine = r.at("max_affine").positive();
    if (r.has("max_steps")) s.trace.maxSteps = static_cast<std::size_t>(r.at("max_steps").integer(1, 100000000));
    if (r.has("initial_step")) s.trace.initialStep = r.at("initial_step").positive();
    if (r.has("threads")) s.threads = r.at("threads").integer(0, 256);
    const std::string method = r.string("method", "auto");
    try {
        s.method = parseRenderMethod(method);
    } catch (const std::invalid_argument& e) {
        r.at("method").fail(e.what());
    }
}

}  // namespace

std::string builtinTexturePath(const std::string& name) {
    if (name == "earth") return "/usr/share/xplanet/images/earth.jpg";
    if (name == "earth-night") return "/usr/share/xplanet/images/night.jpg";
    return "";
}

Scene parseScene(const std::string& text, const std::string& name, const std::string& baseDir) {
    const auto doc = JsonDocument::parse(text, name);
    const JsonNode root = doc->root();
    root.allowOnly({"description", "metric", "observer", "camera", "objects", "sky", "background", "render"});
    Scene scene;
    scene.source = name;
    scene.spacetime = readMetric(root.at("metric"));
    if (root.has("observer")) {
        const JsonNode o = root.at("observer");
        o.allowOnly({"position", "velocity"});
        if (o.has("position")) scene.observer = vec4(o.at("position"));
        if (o.has("velocity")) scene.observerVelocity = vec4(o.at("velocity"));
        const Mat4 g = scene.spacetime->metric(scene.observer);
        const double uu = scene.observerVelocity.dot(g * scene.observerVelocity);
        if (!(uu > 0) || scene.observerVelocity(0) <= 0)
            (o.has("velocity") ? o.at("velocity") : o)
                .fail("the observer's 4-velocity is not future timelike here (g(u,u) = " + std::to_string(uu) + ")",
                      "inside an ergoregion or beyond the Goedel radius a static observer is impossible: give a velocity");
    }
    if (root.has("camera")) scene.camera = readCamera(root.at("camera"));
    if (root.has("objects")) {
        const JsonNode objs = root.at("objects");
        for (std::size_t i = 0; i < objs.size(); ++i) {
            const JsonNode o = objs[i];
            const std::string type = o.at("type").string();
            if (type == "sphere") scene.spheres.push_back(readSphere(o, *scene.spacetime, baseDir));
            else o.at("type").fail("unknown object type '" + type + "'", "this version renders spheres");
        }
    }
    if (root.has("sky")) scene.sky = readTexture(root.at("sky"), baseDir);
    else if (scene.spacetime->asymptoticallyFlat())
        scene.sky = std::make_shared<CheckerTexture>(36, 18, Vec3(0.85, 0.85, 0.85), Vec3(0.1, 0.1, 0.1));
    if (root.has("background")) scene.background = vec3(root.at("background"));
    if (root.has("render")) readRender(root.at("render"), scene.settings);
    // Goedel rays never escape: follow them for the requested number of windings (a ray
    // returns to the axis after at most 2 pi a of affine length).
    if (const auto* g = dynamic_cast<const GodelCartesian*>(scene.spacetime.get()))
        scene.settings.trace.maxAffine = std::min(scene.settings.trace.maxAffine, (scene.settings.windings + 1) * 2 * kPi * g->a());
    return scene;
}

Scene readScene(const std::string& file) {
    std::ifstream probe(file);
    if (!probe) throw InputError(file, 0, "", "cannot open the scene file", "check the path");
    std::stringstream ss;
    ss << probe.rdbuf();
    return parseScene(ss.str(), file, fs::path(file).parent_path().string());
}

}  // namespace lc::io
