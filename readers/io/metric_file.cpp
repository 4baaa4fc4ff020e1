// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/metric_file.hpp"

#include "readers/io/install_layout.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

namespace lc::io {
namespace fs = std::filesystem;
namespace {

using formula::FormulaMetricSource;
using formula::FormulaText;

// A formula is one string, or an array of strings read as lines (long line elements).
FormulaText formulaText(const JsonNode& n, const std::string& field) {
    if (n.isString()) return {field, n.string()};
    if (!n.isArray()) n.fail("expected a formula: a string, or an array of strings (its lines)");
    std::string text;
    for (std::size_t i = 0; i < n.size(); ++i) text += (i ? "\n" : "") + n[i].string();
    return {field, text};
}

// Where each field's node is, so that a formula's error names its line in the file.
using FieldNodes = std::map<std::string, JsonNode>;

void readParameters(const JsonNode& ps, FormulaMetricSource& s, FieldNodes& nodes) {
    for (const std::string& name : ps.keys()) {
        const JsonNode p = ps.at(name);
        p.allowOnly({"default", "range", "meaning"});
        MetricParameter q{name, 0, -1e300, 1e300, ""};  // no range given: any finite number
        q.fallback = p.at("default").number();
        if (p.has("range")) {
            const auto r = p.at("range").numbers(2);
            if (!(r[0] <= r[1])) p.at("range").fail("a range is [min, max] with min <= max");
            q.min = r[0];
            q.max = r[1];
        }
        if (!(q.fallback >= q.min && q.fallback <= q.max))
            p.at("default").fail("the default " + input::formatBound(q.fallback) + " lies outside the range [" +
                                 input::formatBound(q.min) + ", " + input::formatBound(q.max) + "]");
        if (p.has("meaning")) q.why = p.at("meaning").string();
        nodes.emplace("parameters." + name, p);
        s.parameters.push_back(q);
    }
}

// "tt", "t,phi", "t phi", "rtheta": a component's key as a pair of coordinates.
std::pair<int, int> componentIndices(const JsonNode& node, const std::string& key,
                                     const std::array<std::string, 4>& coordinates) {
    auto index = [&](const std::string& name) {
        for (int k = 0; k < 4; ++k)
            if (coordinates[static_cast<std::size_t>(k)] == name) return k;
        return -1;
    };
    const std::size_t sep = key.find_first_of(", ");
    std::vector<std::pair<int, int>> found;
    if (sep != std::string::npos) {
        const int m = index(key.substr(0, sep)), n = index(key.substr(sep + 1));
        if (m >= 0 && n >= 0) found.push_back({m, n});
    } else {
        for (std::size_t cut = 1; cut < key.size(); ++cut) {
            const int m = index(key.substr(0, cut)), n = index(key.substr(cut));
            if (m >= 0 && n >= 0) found.push_back({m, n});
        }
    }
    if (found.size() != 1) {
        std::string names;
        for (const auto& c : coordinates) names += (names.empty() ? "" : ", ") + c;
        node.fail("'" + key + "' " + (found.empty() ? "names no pair" : "is ambiguous as a pair") +
                      " of coordinates (" + names + ")",
                  "write the two coordinates with a comma: \"t,phi\"");
    }
    return found[0];
}

void readFarField(const JsonNode& f, FormulaMetricSource& s, FieldNodes& nodes) {
    f.allowOnly({"mass", "spin", "size", "capture", "velocity"});
    s.asymptoticallyFlat = true;
    auto optional = [&](const char* key, std::optional<FormulaText>& into) {
        if (!f.has(key)) return;
        const JsonNode n = f.at(key);
        const std::string field = std::string("far_field.") + key;
        into = n.isString() || n.isArray() ? formulaText(n, field) : FormulaText{field, input::formatBound(n.number())};
        nodes.emplace(field, n);
    };
    optional("mass", s.farMass);
    optional("spin", s.farSpin);
    optional("size", s.farSize);
    optional("capture", s.farCapture);
    if (f.has("velocity")) {
        const JsonNode v = f.at("velocity");
        if (v.size() != 3) v.fail("expected three components [vx, vy, vz]");
        for (std::size_t i = 0; i < 3; ++i) {
            const std::string field = "far_field.velocity[" + std::to_string(i) + "]";
            s.farVelocity[i] =
                v[i].isString() ? formulaText(v[i], field) : FormulaText{field, input::formatBound(v[i].number())};
            nodes.emplace(field, v[i]);
        }
    }
}

// "view": where a picture of the metric is taken from at its defaults (an observer at rest at
// `observer` (t, x, y, z) looking at `look_at`, rays followed to `max_affine` where the metric
// has no sky, and `objects` to see where it has none: a scene's objects, checked by the scene
// reader where they are used). The catalogue's render test and gallery read it; the metric
// itself does not.
void checkView(const JsonNode& v) {
    v.allowOnly({"observer", "look_at", "max_affine", "objects"});
    v.at("observer").numbers(4);
    if (v.has("look_at")) v.at("look_at").numbers(3);
    if (v.has("max_affine")) v.at("max_affine").positive();
    if (v.has("objects"))
        for (std::size_t i = 0; i < v.at("objects").size(); ++i)
            if (!v.at("objects")[i].isObject())
                v.at("objects")[i].fail("expected an object, as in a scene's \"objects\"");
}

FormulaMetricSource readSource(const JsonNode& f, FieldNodes& nodes) {
    f.allowOnly({"name", "summary", "coordinates", "chart", "signature", "parameters", "define", "ds2", "g", "horizon",
                 "radius", "far_field", "view", "other_end"});
    if (f.has("view")) checkView(f.at("view"));
    FormulaMetricSource s;
    s.name = f.string("name", "formula");
    s.summary = f.string("summary", "");
    s.chart = f.string("chart", "cartesian");
    if (s.chart != "cartesian" && s.chart != "spherical" && s.chart != "cylindrical")
        f.at("chart").fail("unknown chart '" + s.chart + "'",
                           "cartesian, spherical (t, r, theta, phi) or cylindrical (t, rho, phi, z)");
    if (s.chart == "spherical") s.coordinates = {"t", "r", "theta", "phi"};
    if (s.chart == "cylindrical") s.coordinates = {"t", "rho", "phi", "z"};
    if (f.has("coordinates")) {
        const JsonNode c = f.at("coordinates");
        if (c.size() != 4) c.fail("expected four coordinate names, time first", "[\"t\", \"x\", \"y\", \"z\"]");
        for (std::size_t i = 0; i < 4; ++i) s.coordinates[i] = c[i].string();
        nodes.emplace("coordinates", c);
    }
    const std::string signature = f.string("signature", "-+++");
    if (signature != "-+++" && signature != "+---")
        f.at("signature").fail("expected \"-+++\" or \"+---\"", "the signs of the line element's dt^2 and dx^2");
    s.mostlyPlus = signature == "-+++";
    if (f.has("parameters")) readParameters(f.at("parameters"), s, nodes);
    if (f.has("define")) {
        const JsonNode d = f.at("define");
        for (std::size_t i = 0; i < d.size(); ++i) {
            const std::string field = "define[" + std::to_string(i) + "]";
            s.definitions.push_back({field, d[i].string()});
            nodes.emplace(field, d[i]);
        }
    }
    if (f.has("ds2")) {
        s.lineElement = formulaText(f.at("ds2"), "ds2");
        nodes.emplace("ds2", f.at("ds2"));
    }
    if (f.has("g")) {
        const JsonNode g = f.at("g");
        nodes.emplace("g", g);
        for (const std::string& key : g.keys()) {
            const std::string field = "g." + key;
            s.components.push_back({formulaText(g.at(key), field), componentIndices(g.at(key), key, s.coordinates)});
            nodes.emplace(field, g.at(key));
        }
    }
    if (f.has("horizon")) {
        s.horizon = formulaText(f.at("horizon"), "horizon");
        nodes.emplace("horizon", f.at("horizon"));
    }
    if (f.has("other_end")) {
        s.otherEnd = formulaText(f.at("other_end"), "other_end");
        nodes.emplace("other_end", f.at("other_end"));
    }
    if (f.has("radius")) {
        s.radius = formulaText(f.at("radius"), "radius");
        nodes.emplace("radius", f.at("radius"));
    }
    if (f.has("far_field")) readFarField(f.at("far_field"), s, nodes);
    return s;
}

// Builds the metric; a problem is reported at the node of its field (a parameter value given
// in `valueNodes`, or a field of the formula in `nodes`).
std::shared_ptr<const formula::FormulaMetric> build(const JsonNode& formulaNode, const FieldNodes& nodes,
                                                    FormulaMetricSource source,
                                                    const std::map<std::string, double>& values,
                                                    const JsonNode* valueBlock) {
    try {
        return std::make_shared<formula::FormulaMetric>(std::move(source), values);
    } catch (const formula::FormulaMetricError& e) {
        const std::string& field = e.field();
        if (field.rfind(formula::kValueField, 0) == 0) {
            const std::string parameter = field.substr(formula::kValueField.size());
            if (valueBlock && valueBlock->has(parameter)) valueBlock->at(parameter).fail(e.detail());
            formulaNode.fail(e.detail(), "parameters are given as --param NAME=VALUE or in the scene's metric block");
        }
        if (const auto it = nodes.find(e.field()); it != nodes.end()) it->second.fail(e.detail());
        formulaNode.fail(e.what());
    }
}

std::shared_ptr<const formula::FormulaMetric> fromDocument(const JsonDocument& doc,
                                                           const std::map<std::string, double>& values) {
    const JsonNode root = doc.root();
    FieldNodes nodes;
    FormulaMetricSource source = readSource(root, nodes);
    return build(root, nodes, std::move(source), values, nullptr);
}

}  // namespace

bool isFormulaMetricBlock(const JsonNode& metric) { return metric.has("formula") || metric.has("file"); }

std::shared_ptr<const formula::FormulaMetric> readFormulaMetric(const JsonNode& m, const std::string& baseDir) {
    if (m.has("name")) m.at("name").fail("a formula metric takes its name from its formula", "remove \"name\"");
    if (m.has("formula") && m.has("file")) m.fail("give \"formula\" or \"file\", not both");
    // Every other member is a parameter's value.
    std::map<std::string, double> values;
    for (const std::string& key : m.keys())
        if (key != "formula" && key != "file") values[key] = m.at(key).number();

    std::shared_ptr<JsonDocument> fileDoc;  // keeps the file's nodes alive while building
    JsonNode formulaNode = m;
    if (m.has("file")) {
        const std::string file = m.at("file").string();
        const std::string path = fs::path(file).is_absolute() ? file : (fs::path(baseDir) / file).string();
        fileDoc = JsonDocument::load(path);
        formulaNode = fileDoc->root();
    } else {
        formulaNode = m.at("formula");
    }
    FieldNodes nodes;
    FormulaMetricSource source = readSource(formulaNode, nodes);
    return build(formulaNode, nodes, std::move(source), values, &m);
}

std::vector<fs::path> catalogueFiles() {
    std::vector<fs::path> catalogue;
    std::set<std::string> seen;
    for (const fs::path& folder : dataSearchPath(true)) {
        std::error_code ignored;
        std::vector<fs::path> files;
        for (const auto& entry : fs::directory_iterator(folder, ignored))
            if (entry.path().extension() == ".json" && entry.is_regular_file(ignored)) files.push_back(entry.path());
        std::sort(files.begin(), files.end());
        for (const fs::path& file : files) {
            if (!seen.insert(file.filename().string()).second) continue;
            try {
                if (JsonDocument::load(file.string())->root().has("metric")) continue;  // a scene
            } catch (const std::exception&) {
                // kept: its reader says why it is not a metric
            }
            catalogue.push_back(file);
        }
    }
    return catalogue;
}

std::shared_ptr<const formula::FormulaMetric> loadFormulaMetric(const std::string& file,
                                                                const std::map<std::string, double>& values) {
    return fromDocument(*JsonDocument::loadDataFile(file, true), values);
}

std::shared_ptr<const formula::FormulaMetric> parseFormulaMetric(const std::string& json, const std::string& name,
                                                                 const std::map<std::string, double>& values) {
    return fromDocument(*JsonDocument::parse(json, name), values);
}

}  // namespace lc::io
