// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/structural_edits.hpp"

#include "core/input/ranges.hpp"
#include "core/metrics/factory.hpp"
#include "readers/io/json_document.hpp"
#include "readers/io/scene_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <stdexcept>

namespace lc::io {
namespace {

std::set<std::string> namesIn(const Json::Value& list) {
    std::set<std::string> names;
    for (const auto& e : list)
        if (e.isObject() && e["name"].isString()) names.insert(e["name"].asString());
    return names;
}

// `stem`, or `stem-2`, `stem-3`... : the first one no element of `list` carries.
std::string unusedName(const Json::Value& list, const std::string& stem, bool numberFirst) {
    const std::set<std::string> taken = namesIn(list);
    if (!numberFirst && !taken.count(stem)) return stem;
    for (int n = numberFirst ? 1 : 2;; ++n) {
        const std::string name = stem + "-" + std::to_string(n);
        if (!taken.count(name)) return name;
    }
}

// The list as the document has it (an empty array when absent), checked to be one.
Json::Value listOf(const Json::Value& document, SceneList list) {
    const Json::Value& v = document[fieldName(list)];
    if (v.isNull()) return Json::Value(Json::arrayValue);
    if (!v.isArray()) throw std::invalid_argument(std::string("field '") + fieldName(list) + "' is not a list");
    return v;
}

void checkIndex(const Json::Value& elements, SceneList list, int index) {
    if (index < 0 || static_cast<Json::ArrayIndex>(index) >= elements.size())
        throw std::invalid_argument(std::string("field '") + fieldName(list) + "': the scene has no element [" +
                                    std::to_string(index) + "] (it has " + std::to_string(elements.size()) + ")");
}

// The chart direction the camera looks along at the observer, unit length in chart components.
Vec3 forwardOf(const Scene& scene) {
    Vec3 f = scene.camera.forward;
    if (scene.camera.lookAt) f = *scene.camera.lookAt - scene.observer.tail<3>();
    return f.norm() > 0 ? Vec3(f.normalized()) : Vec3::UnitX();
}

}  // namespace

const char* fieldName(SceneList list) { return list == SceneList::Objects ? "objects" : "lights"; }

SceneEdit metricChange(const std::string& name) {
    for (const auto& metric : knownMetrics())
        if (metric.name == name) {
            Json::Value m(Json::objectValue);
            m["name"] = name;
            for (const auto& p : metric.parameters) m[p.name] = p.fallback;
            return {"metric", m};
        }
    std::string names;
    for (const auto& metric : knownMetrics()) names += (names.empty() ? "" : ", ") + metric.name;
    throw std::invalid_argument("unknown metric '" + name + "' (expected one of: " + names + ")");
}

SceneEdit metricFileChange(const std::string& file, const std::string& sceneFolder) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path absolute = fs::weakly_canonical(fs::absolute(file), ec);
    const fs::path folder = fs::weakly_canonical(fs::absolute(sceneFolder.empty() ? "." : sceneFolder), ec);
    const fs::path relative = absolute.lexically_relative(folder);
    const bool inside = !relative.empty() && *relative.begin() != "..";
    Json::Value m(Json::objectValue);
    m["file"] = (inside ? relative : absolute).generic_string();
    return {"metric", m};
}

namespace {

bool aboutObserverOrCamera(const std::string& field) {
    for (const std::string part : {"observer", "camera"})
        if (field.compare(0, part.size(), part) == 0 &&
            (field.size() == part.size() || field[part.size()] == '.' || field[part.size()] == '['))
            return true;
    return false;
}

}  // namespace

MetricChangePlan plannedMetricChange(const EditableScene& scene, const SceneEdit& metric) {
    const auto reads = [&](const std::vector<SceneEdit>& edits) {
        EditableScene trial = scene;
        trial.apply(edits);
    };
    try {
        reads({metric});
        return {{metric}, ""};
    } catch (const InputError& refused) {
        if (!aboutObserverOrCamera(refused.field())) throw;
        const SpacetimePtr st = metricFromBlock(metric.value, scene.source(), scene.baseDir());
        const Scene& old = scene.scene();
        // Where the observer may go: where it is, then a place the new metric surely serves.
        struct Place {
            Vec4 event;
            std::string why;  // "" for the old event
        };
        std::vector<Place> places{{old.observer, ""}};
        if (st->asymptoticallyFlat()) {
            const FarField far = st->farField(old.observer);
            const double d = std::isfinite(far.captureRadius) && far.captureRadius > 0 ? 6 * far.captureRadius : 30.0;
            Vec4 x = old.observer;
            x.tail<3>() = far.centre - d * forwardOf(old);
            places.push_back({x, input::formatBound(d) + " from the hole, which the camera looks at"});
        } else {
            Scene moved = old;
            moved.spacetime = st;
            Vec4 x = old.observer;
            x(1) += 0.1 * placeDistance(moved);
            places.push_back({x, "off the chart's axis"});
        }
        for (const Place& place : places)
            for (const char* velocity : {"", "normal", "zamo", "free_fall", "carter"}) {
                std::vector<SceneEdit> edits{metric};
                if (!place.why.empty()) edits.push_back({"observer.position", jsonArray(place.event)});
                if (*velocity) edits.push_back({"observer.velocity", Json::Value(velocity)});
                if (edits.size() == 1) continue;  // the metric alone was refused
                try {
                    reads(edits);
                } catch (const InputError& e) {
                    // Something else that a moved observer meets (an object the metric cannot
                    // hold) stays whatever the observer does: said at once.
                    if (!aboutObserverOrCamera(e.field())) throw;
                    continue;
                }
                std::string what = "the observer";
                if (!place.why.empty()) what += " moved to " + formatEvent(place.event) + ", " + place.why;
                if (*velocity)
                    what += std::string(place.why.empty() ? "" : ",") + " with the " + velocity + " velocity";
                return {edits, what + ". Where it was, " + refused.reason()};
            }
        throw;
    }
}

double placeDistance(const Scene& scene) {
    const auto parameters = scene.spacetime->parameters();
    const std::string name = scene.spacetime->name();
    if (name.rfind("godel", 0) == 0) return parameters.at("a");
    if (parameters.count("M")) {
        const double mass = parameters.at("M");
        return std::max(3 * mass, 0.3 * scene.observer.tail<3>().norm());
    }
    return 3.0;
}

SceneEdit sphereAdded(const Json::Value& document, const Scene& scene) {
    Json::Value objects = listOf(document, SceneList::Objects);
    const double d = placeDistance(scene);
    Vec4 centre = scene.observer;
    centre.tail<3>() += d * forwardOf(scene);
    Json::Value sphere(Json::objectValue);
    sphere["type"] = "sphere";
    sphere["name"] = unusedName(objects, "sphere", true);
    sphere["centre"] = jsonArray(centre);
    sphere["radius"] = 0.1 * d;
    objects.append(sphere);
    return {"objects", objects};
}

SceneEdit lightAdded(const Json::Value& document, const Scene& scene) {
    Json::Value lights = listOf(document, SceneList::Lights);
    Vec4 position = scene.observer;
    const Vec3 up = scene.camera.up.norm() > 0 ? Vec3(scene.camera.up.normalized()) : Vec3::UnitZ();
    position.tail<3>() += placeDistance(scene) * up;
    Json::Value light(Json::objectValue);
    light["name"] = unusedName(lights, "light", true);
    light["position"] = jsonArray(position);
    light["temperature"] = 6500;
    lights.append(light);
    return {"lights", lights};
}

namespace {

// The size of element `index` of the objects list as the scene holds it: a sphere's radius, a
// mesh's or box's largest distance of a vertex from its centre; 0 for a disk or what the scene
// does not hold.
double objectSize(const Json::Value& objects, const Scene& scene, int index) {
    std::size_t spheres = 0, meshes = 0;
    for (int k = 0; k < index; ++k) {
        const std::string type = objects[k]["type"].asString();
        spheres += type == "sphere";
        meshes += type == "box" || type == "mesh";
    }
    const std::string type = objects[index]["type"].asString();
    if (type == "sphere" && spheres < scene.spheres.size()) return scene.spheres[spheres].radius;
    double size = 0;
    if ((type == "box" || type == "mesh") && meshes < scene.meshes.size())
        for (const Vec3& p : scene.meshes[meshes].positions) size = std::max(size, p.norm());
    return size;
}

// The camera's right (forward x up, chart components), unit; any direction across the view where
// up is along forward.
Vec3 rightOf(const Scene& scene) {
    const Vec3 forward = forwardOf(scene);
    const Vec3 right = forward.cross(scene.camera.up);
    return right.norm() > 1e-9 * scene.camera.up.norm() ? Vec3(right.normalized()) : Vec3(forward.unitOrthogonal());
}

}  // namespace

SceneEdit elementDuplicated(const Json::Value& document, const Scene& scene, SceneList list, int index) {
    const Json::Value elements = listOf(document, list);
    checkIndex(elements, list, index);
    Json::Value copy = elements[index];
    // Beside the original, to the camera's right: 2.5 sizes between their centres (a gap of half
    // a size), or a third of placeDistance for a light.
    const char* where = list == SceneList::Lights ? "position" : "centre";
    const double shift =
        list == SceneList::Lights ? 0.3 * placeDistance(scene) : 2.5 * objectSize(elements, scene, index);
    if (shift > 0 && copy[where].isArray() && copy[where].size() == 4) {
        const Vec3 right = rightOf(scene);
        for (Json::ArrayIndex k = 1; k < 4; ++k)
            if (copy[where][k].isNumeric()) copy[where][k] = copy[where][k].asDouble() + shift * right(k - 1);
    }
    const std::string stem = copy["name"].isString()   ? copy["name"].asString()
                             : copy["type"].isString() ? copy["type"].asString()
                                                       : std::string(list == SceneList::Lights ? "light" : "object");
    copy["name"] = unusedName(elements, stem.substr(0, 48) + "-copy", false);  // within the 64 characters
    Json::Value out(Json::arrayValue);
    for (Json::ArrayIndex k = 0; k < elements.size(); ++k) {
        out.append(elements[k]);
        if (static_cast<int>(k) == index) out.append(copy);
    }
    return {fieldName(list), out};
}

SceneEdit elementRemoved(const Json::Value& document, SceneList list, int index) {
    const Json::Value elements = listOf(document, list);
    checkIndex(elements, list, index);
    Json::Value out(Json::arrayValue);
    for (Json::ArrayIndex k = 0; k < elements.size(); ++k)
        if (static_cast<int>(k) != index) out.append(elements[k]);
    return {fieldName(list), out.empty() ? Json::Value() : out};
}

}  // namespace lc::io
