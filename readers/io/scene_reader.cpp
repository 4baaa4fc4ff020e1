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

Motion readMotion(const JsonNode& m, const Spacetime& st) {
    Motion motion;
    if (m.isString()) {
        if (m.string() != "rest") m.fail("unknown motion '" + m.string() + "'", "use \"rest\" or an object with a type");
        return motion;
    }
    const std::string type = m.at("type").string();
    const bool godel = dynamic_cast<const GodelCartesian*>(&st) != nullptr;
    if (type == "rest") {
        m.allowOnly({"type"});
    } else if (type == "constant_velocity") {
        m.allowOnly({"type", "beta"});
        if (st.name() != "minkowski") m.at("type").fail("constant velocity needs the minkowski metric", "in curved spacetimes use free_fall or world_line");
        motion.kind = Motion::Kind::ConstantVelocity;
        motion.beta = vec3(m.at("beta"));
        if (!(motion.beta.norm() < 1))
            m.at("beta").fail("speed |beta| = " + std::to_string(motion.beta.norm()) + " is not below the speed of light", "|beta| must be < 1");
    } else if (type == "free_fall") {
        m.allowOnly({"type", "k0", "k3", "phi0", "speed"});
        if (!godel) m.at("type").fail("free fall is available in the godel metric", "use world_line elsewhere");
        motion.kind = Motion::Kind::FreeFall;
        motion.k3 = m.number("k3", 0.0);
        motion.phi0 = m.number("phi0", 0.0);
        if (m.has("speed")) {
            // Speed v relative to the static observer at the centre event: there the chart is
            // Minkowskian, so k0 = p_t = gamma, and k3 = gamma v_z must not exceed gamma v.
            const double v = m.at("speed").number();
            if (!(v >= 0 && v < 1)) m.at("speed").fail("speed must be in [0, 1)", "a fraction of the speed of light");
            motion.k0 = 1 / std::sqrt(1 - v * v);
        } else {
            motion.k0 = m.number("k0", 1.0);
        }
        if (!(std::abs(motion.k0) >= std::sqrt(1 + motion.k3 * motion.k3)))
            m.fail("free fall needs |k0| >= sqrt(1 + k3^2) (timelike geodesic)", "raise k0 or lower k3");
    } else if (type == "world_line") {
        m.allowOnly({"type", "points"});
        motion.kind = Motion::Kind::WorldLine;
        const JsonNode pts = m.at("points");
        if (pts.size() < 2) pts.fail("a world line needs at least two events");
        for (std::size_t i = 0; i < pts.size(); ++i) {
            motion.points.push_back(vec4(pts[i]));
            if (i > 0 && !(motion.points[i](0) > motion.points[i - 1](0))) pts[i].fail("events must have increasing time");
        }
    } else {
        m.at("type").fail("unknown motion type '" + type + "'", "use rest, constant_velocity, free_fall or world_line");
    }
    return motion;
}

TexturePtr defaultObjectTexture() {
    return std::make_shared<CheckerTexture>(16, 8, Vec3(0.9, 0.9, 0.9), Vec3(0.7, 0.2, 0.1));
}

double readTemperature(const JsonNode& o) {
    if (!o.has("temperature")) return 0;
    const double T = o.at("temperature").positive();
    if (T < 300 || T > 1e6) o.at("temperature").fail("temperature outside [300, 1e6] K");
    return T;
}

SphereObject readSphere(const JsonNode& o, const Spacetime& st, const std::string& baseDir) {
    o.allowOnly({"type", "name", "centre", "radius", "texture", "night_texture", "motion", "temperature"});
    SphereObject s;
    s.name = o.string("name", "sphere");
    s.centre = vec4(o.at("centre"));
    s.radius = o.at("radius").positive();
    s.placement = placementFor(st, s.centre);
    s.texture = o.has("texture") ? readTexture(o.at("texture"), baseDir) : defaultObjectTexture();
    if (o.has("night_texture")) s.nightTexture = readTexture(o.at("night_texture"), baseDir);
    if (o.has("motion")) s.motion = readMotion(o.at("motion"), st);
    s.temperature = readTemperature(o);
    return s;
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
    m.centre = vec4(o.at("centre"));
    if (type == "box") {
        o.allowOnly({"type", "name", "centre", "size", "subdivisions", "texture", "motion", "temperature"});
        m.name = o.string("name", "box");
        m.source = "box";
        const Vec3 size = vec3(o.at("size"));
        for (int k = 0; k < 3; ++k)
            if (!(size(k) > 0)) o.at("size")[static_cast<std::size_t>(k)].fail("box edge lengths must be > 0");
        makeBox(size, o.has("subdivisions") ? o.at("subdivisions").integer(1, 512) : 10, m);
    } else {
        o.allowOnly({"type", "name", "centre", "file", "scale", "texture", "motion", "temperature"});
        m.name = o.string("name", "mesh");
        const std::string file = o.at("file").string();
        m.source = fs::path(file).is_absolute() ? file : (fs::path(baseDir) / file).string();
        if (!opt.meshLoader)
            o.at("file").fail("this program was built without a mesh reader", "build with VTK (the default) to read OBJ, PLY, STL and VTP");
        try {
            opt.meshLoader(m.source, m);
        } catch (const std::exception& e) {
            o.at("file").fail(std::string("cannot use mesh '") + m.source + "': " + e.what(),
                              "OBJ, PLY, STL and VTP files with at least one triangle; paths are relative to the scene file");
        }
        if (m.triangles.empty()) o.at("file").fail("mesh '" + m.source + "' has no triangles", "an empty mesh cannot be drawn");
        const double scale = o.has("scale") ? o.at("scale").positive() : 1.0;
        for (auto& p : m.positions) p *= scale;
    }
    m.texture = o.has("texture") ? readTexture(o.at("texture"), baseDir) : defaultObjectTexture();
    if (o.has("motion")) m.motion = readMotion(o.at("motion"), st);
    m.temperature = readTemperature(o);
    return m;
}

PointLight readLight(const JsonNode& l) {
    l.allowOnly({"name", "position", "temperature", "intensity"});
    PointLight p;
    p.name = l.string("name", "light");
    p.position = vec4(l.at("position"));
    if (l.has("temperature")) p.temperature = l.at("temperature").positive();
    if (l.has("intensity")) p.intensity = l.at("intensity").positive();
    return p;
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

Scene parseScene(const std::string& text, const std::string& name, const std::string& baseDir,
                 const SceneReadOptions& options) {
    const auto doc = JsonDocument::parse(text, name);
    const JsonNode root = doc->root();
    root.allowOnly({"description", "metric", "observer", "camera", "objects", "lights", "sky", "background", "render"});
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
            else if (type == "box" || type == "mesh") scene.meshes.push_back(readMesh(o, *scene.spacetime, baseDir, options));
            else o.at("type").fail("unknown object type '" + type + "'", "use sphere, box or mesh");
        }
    }
    if (root.has("lights")) {
        const JsonNode lights = root.at("lights");
        for (std::size_t i = 0; i < lights.size(); ++i) scene.lights.push_back(readLight(lights[i]));
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

Scene readScene(const std::string& file, const SceneReadOptions& options) {
    std::ifstream probe(file);
    if (!probe) throw InputError(file, 0, "", "cannot open the scene file", "check the path");
    std::stringstream ss;
    ss << probe.rdbuf();
    return parseScene(ss.str(), file, fs::path(file).parent_path().string(), options);
}

}  // namespace lc::io
