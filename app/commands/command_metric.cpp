// SPDX-License-Identifier: BSD-3-Clause
// `lightcone metric check FILE`: a metric written as formulas, parsed and checked, with what
// follows from it (symmetries, signature, cost) — what a physicist checks before rendering.
#include "app/commands/commands.hpp"
#include "core/accretion/thin_disk.hpp"
#include "core/codegen/expression.hpp"
#include "core/input/ranges.hpp"
#include "core/spacetime/metric_check.hpp"
#include "core/metrics/factory.hpp"
#include "readers/io/install_layout.hpp"
#include "readers/io/metric_file.hpp"

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>

namespace lc::cli {
namespace {

// Coordinates on which no component of g depends, decided on the expressions themselves: each
// gives a Killing vector d/dx^k (d/dt: stationary).
std::vector<std::string> cyclicCoordinates(const formula::FormulaMetric& m) {
    std::vector<std::string> names;
    for (int k = 0; k < 4; ++k) {
        codegen::Differentiator d(k);
        bool independent = true;
        for (int a = 0; a < 4 && independent; ++a)
            for (int b = a; b < 4 && independent; ++b) independent = d(m.expressions()(a, b)).isConstant(0.0);
        if (independent) names.push_back(m.coordinateNames()[static_cast<std::size_t>(k)]);
    }
    return names;
}

std::vector<Vec4> sampleEvents(const Vec4& around) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Vec4> events;
    for (int i = 0; i < 32; ++i) {
        const double scale = std::max(1.0, around.tail<3>().norm());
        events.push_back(around + Vec4(u(random), u(random), u(random), u(random)) * 0.5 * scale);
    }
    return events;
}

// The ISCO in both senses, found numerically from g (core/accretion/thin_disk), or why not.
std::string innermostStableOrbits(const std::shared_ptr<const formula::FormulaMetric>& metric) {
    std::ostringstream out;
    out << std::setprecision(7) << "innermost stable circular orbits (from g): ";
    try {
        const double prograde = ThinDiskModel(metric, 0, 1e4, true).isco();
        const double retrograde = ThinDiskModel(metric, 0, 1e4, false).isco();
        out << "prograde r = " << prograde << ", retrograde r = " << retrograde;
    } catch (const std::invalid_argument& e) {
        out << "none: " << e.what();
    }
    return out.str();
}

// "a = 0.9 [0, 1]" for each parameter, at its default.
std::string parameterList(const std::vector<MetricParameter>& parameters) {
    std::string list;
    for (const MetricParameter& p : parameters)
        list += (list.empty() ? "" : ", ") + p.name + " = " + input::formatBound(p.fallback) + " [" +
                input::formatBound(p.min) + ", " + input::formatBound(p.max) + "]";
    return list.empty() ? "no parameters" : list;
}

// `metric list`: the catalogue's files (io::catalogueFiles: LIGHTCONE_DATA_PATH, the installed or
// the checkout's data/metrics, each name once) under their folders, then the built-ins. A file
// that does not read as a metric is listed with its error.
int listMetrics() {
    int count = 0;
    std::filesystem::path shownFolder;
    for (const std::filesystem::path& file : io::catalogueFiles()) {
        if (file.parent_path() != shownFolder) {
            shownFolder = file.parent_path();
            std::cout << "metric files in " << shownFolder.string() << ":\n";
        }
        try {
            const auto metric = io::loadFormulaMetric(file.string(), {});
            const formula::FormulaMetricSource& m = metric->source();
            std::cout << "  " << file.stem().string() << ": " << m.name << ", " << m.chart << " chart; "
                      << parameterList(m.parameters) << "\n      " << m.summary << "\n";
            ++count;
        } catch (const std::exception& e) {
            std::cout << "  " << file.stem().string() << ": not a readable metric: " << e.what() << "\n";
        }
    }
    if (count == 0)
        std::cout << "no metric files found (looked in the LIGHTCONE_DATA_PATH folders and the "
                     "installed share/lightcone/data/metrics)\n";
    std::cout << "built in (scene \"metric\": {\"name\": ...}, --metric NAME):\n";
    for (const MetricDescription& d : knownMetrics())
        std::cout << "  " << d.name << ": " << parameterList(d.parameters) << "\n      " << d.summary << "\n";
    std::cout << count << " metric files, " << knownMetrics().size()
              << " built in; `lightcone metric check NAME` checks one file\n";
    return 0;
}

// What `check` and `show` both begin with: the name, the file, the summary, the chart and the
// parameters with their values, ranges and meanings.
void printHeading(const std::string& file, const formula::FormulaMetric& metric) {
    const formula::FormulaMetricSource& s = metric.source();
    const auto names = metric.coordinateNames();
    std::cout << "metric '" << s.name << "' (" << file << ")\n";
    if (!s.summary.empty()) std::cout << "  " << s.summary << "\n";
    const auto& written = s.coordinates;
    std::cout << "chart: " << s.chart << " (" << written[0] << " (time), " << written[1] << ", " << written[2] << ", "
              << written[3] << ")";
    if (s.chart != "cartesian")
        std::cout << ", traced in its Cartesian pull-back (" << names[0] << ", x, y, z); events below are Cartesian";
    std::cout << "\nsignature as written " << (s.mostlyPlus ? "(-,+,+,+), read as (+,-,-,-)" : "(+,-,-,-)") << "\n";
    std::cout << "parameters:";
    if (s.parameters.empty()) std::cout << " none";
    std::cout << "\n";
    for (const auto& p : s.parameters)
        std::cout << "  " << p.name << " = " << input::formatBound(metric.parameters().at(p.name)) << "  in ["
                  << input::formatBound(p.min) << ", " << input::formatBound(p.max) << "]"
                  << (p.why.empty() ? "" : ": " + p.why) << "\n";
}

// The file's "view" as a scene to start from: where its picture in docs/CATALOGUE.md is taken.
std::string viewSceneText(const std::string& file, const formula::FormulaMetric& metric) {
    const auto doc = io::JsonDocument::load(file);
    const Json::Value& root = doc->rootValue();
    std::ostringstream out;
    out << "{\"metric\": {\"file\": " << Json::valueToQuotedString(file.c_str());
    for (const auto& [name, value] : metric.parameters()) out << ", \"" << name << "\": " << input::formatBound(value);
    out << "}";
    if (root.isMember("view")) {
        Json::StreamWriterBuilder compact;
        compact["indentation"] = "";
        const Json::Value& view = root["view"];
        out << ",\n \"observer\": {\"position\": " << Json::writeString(compact, view["observer"]) << "},\n"
            << " \"camera\": {\"width\": 480, \"height\": 240, \"fov\": [90, 45], \"look_at\": "
            << (view.isMember("look_at") ? Json::writeString(compact, view["look_at"]) : "[0, 0, 0]")
            << ", \"up\": [0, 0, 1]}";
        if (view.isMember("max_affine"))
            out << ",\n \"render\": {\"max_affine\": " << Json::writeString(compact, view["max_affine"]) << "}";
        if (view.isMember("objects")) out << ",\n \"objects\": " << Json::writeString(compact, view["objects"]);
    }
    out << "}";
    return out.str();
}

// `metric show NAME`: what the file is and how to use it, without checking it at an event.
int showMetric(const std::string& file, const formula::FormulaMetric& metric) {
    const formula::FormulaMetricSource& s = metric.source();
    printHeading(file, metric);
    std::cout << "rays end: "
              << (metric.asymptoticallyFlat() ? "in the sky (asymptotically flat)"
                                              : "at render.max_affine (no sky at infinity)");
    if (s.horizon) std::cout << "; at a horizon where " << s.horizon->text << " < 1e-6";
    if (s.otherEnd) std::cout << "; in the far side's sky (other_sky) where " << s.otherEnd->text << " < 1e-6";
    std::cout << "\nchecked against a published number: docs/METRICS.md, \"The catalogue\"; pictured in "
                 "docs/CATALOGUE.md\na scene to start from (its view):\n"
              << viewSceneText(file, metric) << "\n";
    return 0;
}

}  // namespace

int runMetric(const std::vector<std::string>& argv) {
    const MetricCheckOptions o = parseMetricCheckOptions(argv);
    if (o.list) return listMetrics();
    const std::string file = io::findDataFile(o.file, true);  // the file read, for the heading
    const auto start = std::chrono::steady_clock::now();
    const auto metric = io::loadFormulaMetric(file, o.parameters);
    const double prepareMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (o.show) return showMetric(file, *metric);
    const formula::FormulaMetricSource& s = metric->source();
    const auto names = metric->coordinateNames();
    printHeading(file, *metric);

    std::cout << "at (" << input::formatBound(o.at(0)) << ", " << input::formatBound(o.at(1)) << ", "
              << input::formatBound(o.at(2)) << ", " << input::formatBound(o.at(3)) << "), signature (+,-,-,-):\n";
    const Mat4 g = metric->metric(o.at);
    std::cout << std::setprecision(10);
    for (int m = 0; m < 4; ++m)
        for (int n = m; n < 4; ++n)
            if (g(m, n) != 0) std::cout << "  " << componentName(names, m, n) << " = " << g(m, n) << "\n";
    std::cout << "  det g = " << g.determinant() << ", eigenvalue signs " << signatureAt(*metric, o.at) << "\n";
    const std::string problem = metricProblemAt(*metric, o.at);
    std::cout << "  " << (problem.empty() ? "finite and Lorentzian there" : "cannot serve there: " + problem) << "\n";

    std::cout << "derived:\n";
    const auto cyclic = cyclicCoordinates(*metric);
    std::string list;
    for (const auto& c : cyclic) list += (list.empty() ? "" : ", ") + c;
    std::cout << "  g depends on no " << (cyclic.empty() ? "coordinate alone" : list)
              << (cyclic.empty() ? "" : " (Killing vectors d/d" + cyclic[0] + (cyclic.size() > 1 ? ", ..." : "") + ")")
              << "\n";
    const bool stationary = !cyclic.empty() && cyclic[0] == names[0];
    std::cout << "  " << (stationary ? "stationary (static observers exist where g_tt > 0)" : "not stationary") << "\n";
    std::cout << "  rotations about the z axis: "
              << (rotationSymmetricAboutZ(*metric, sampleEvents(o.at)) ? "a symmetry (checked at 32 events)"
                                                                       : "not a symmetry")
              << "\n";
    std::cout << "  asymptotically flat: "
              << (metric->asymptoticallyFlat() ? "declared (far_field), rays escape to the sky"
                                               : "not declared: rays end at max_affine")
              << "\n";
    std::cout << "  horizon: " << (s.horizon ? "given; rays stop where it is <= 1e-6" : "none given") << "\n";
    std::cout << "  circular orbits and thin disks: "
              << (metric->equatorialRadius()
                      ? "yes, labelled by " +
                            (s.radius ? "'" + s.radius->text + "'" : std::string("the distance from the z axis"))
                      : "no: " + metric->whyNoCircularOrbits())
              << "\n";
    if (metric->equatorialRadius()) std::cout << "  " << innermostStableOrbits(metric) << "\n";
    std::cout << "  Kerr-Schild form (flat + F (l.dx)^2, l null): "
              << (metric->kerrSchild() ? "yes, traced with the closed-form inverse" : "no, traced by the general path")
              << "\n";
    std::cout << "prepared in " << std::setprecision(3) << prepareMs
              << " ms (read, parse, differentiate); the CPU tape has " << metric->tapeInstructions()
              << " instructions for g and its 40 first derivatives\n";
    return problem.empty() ? 0 : 1;
}

}  // namespace lc::cli
