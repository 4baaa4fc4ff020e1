// SPDX-License-Identifier: BSD-3-Clause
// `lightcone sweep`: per value of a scene field, the figures a paper plots, as CSV and SVG. Black
// holes: the shadow's edges, width, offset and height (core/analysis/shadow.hpp), with Bardeen's
// edge-on width for Kerr beside it, and an accretion disk's flux and mean redshift
// (core/analysis/disk_observables.hpp). Goedel: per object, the number of images of its centre and
// their emission times (the inverse problem, docs/PHYSICS.md section 3). Values are tasks over
// MPI ranks like animate's frames.
#include "app/cli/command_options.hpp"
#include "app/commands/commands.hpp"
#include "app/distributed/distributed_tasks.hpp"
#include "app/cli/progress_bar.hpp"
#include "app/commands/render_report.hpp"
#include "app/commands/svg_plot.hpp"
#ifdef LIGHTCONE_WITH_VTK
#include "app/commands/outline_polydata.hpp"
#endif
#include "core/analysis/disk_observables.hpp"
#include "core/analysis/point_source_images.hpp"
#include "core/analysis/shadow.hpp"
#include "core/godel/images.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/render/photo_scene.hpp"
#include "readers/io/atomic_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <limits>
#include <sstream>

namespace lc::cli {
namespace {

using Row = std::vector<std::pair<std::string, double>>;

// One swept value's figures: the table's row and, with --outline, the shadow's outline as camera
// components (right, up, forward) of its unit directions.
struct Figures {
    Row row;
    std::vector<Vec3> outline;
};

Row shadowRow(const Scene& scene) {
    const ShadowSize s = measureShadow(scene);
    // Angles as the camera sees them, measured from the shadow's own symmetry line; alpha in units
    // of M from each edge ray's constants of motion (Bardeen's celestial coordinate, > 0 to the
    // camera's right); right_edge_sense says which way the right edge's rays go round the hole.
    Row row{{"shadow_centre_up_deg", s.centreUpDegrees},
            {"shadow_left_deg", s.leftDegrees},
            {"shadow_right_deg", s.rightDegrees},
            {"shadow_width_deg", s.widthDegrees()},
            {"shadow_offset_deg", s.offsetDegrees()},
            {"shadow_height_deg", s.heightDegrees},
            {"shadow_width_M", s.widthImpact(scene.observer.tail<3>().norm())},
            // Every angle's estimated error: the bisection's bracket, confirmed 10 times tighter.
            {"shadow_edge_error_deg", s.edgeErrorDegrees}};
    // Kerr-Newman's closed forms: Bardeen's alpha of each edge and, without charge, the edge-on width.
    if (const auto kn = scene.spacetime->kerrNewmanParameters()) {
        row.emplace_back("shadow_left_alpha_M", s.leftAlpha);
        row.emplace_back("shadow_right_alpha_M", s.rightAlpha);
        row.emplace_back("right_edge_sense", s.rightEdgeSense);
        if (kn->charge == 0) row.emplace_back("bardeen_edge_on_width_M", bardeenEdgeOnWidth(kn->mass, kn->spin));
    }
    return row;
}

// Emission times, latest first (the image seen "now" leads).
void appendImages(Row& row, const std::string& name, std::vector<double> times) {
    std::sort(times.rbegin(), times.rend());
    row.emplace_back(name + "_images", static_cast<double>(times.size()));
    for (std::size_t k = 0; k < times.size(); ++k) row.emplace_back(name + "_t" + std::to_string(k + 1), times[k]);
}

Row godelRow(const Scene& scene, double godelRadius) {
    if (scene.observerVelocity.tail<3>().norm() > 0)
        throw std::invalid_argument("the Goedel images are found for a static observer");
    Row row;
    const godel::ObserverView view(godelRadius, scene.observer);
    std::vector<std::string> names;
    for (const SphereObject& s : scene.spheres) {
        // Columns by object name; unnamed or repeated names get the object's index.
        std::string name = s.name.empty() ? "object" + std::to_string(names.size()) : s.name;
        if (std::find(names.begin(), names.end(), name) != names.end()) name += "_" + std::to_string(names.size());
        names.push_back(name);
        std::vector<double> times;
        if (s.motion.moving()) {
            for (const auto& m : imagesOfMovingCentre(scene, s, scene.settings.windings))
                times.push_back(m.image.emissionTime);
        } else {
            const godel::ImageSet set = view.images(s.centre.tail<3>(), scene.settings.windings, -1);
            if (set.status == godel::ImageStatus::InvalidInput) throw std::invalid_argument(set.message);
            for (const auto& im : set.images) times.push_back(im.emissionTime);
        }
        appendImages(row, names.back(), std::move(times));
    }
    if (scene.spheres.empty())
        throw std::invalid_argument("a Goedel sweep counts the images of spheres; the scene has none");
    return row;
}

// A disk's observed bolometric flux (Mdot / M^2), its flux-weighted mean g and the share of the
// secondary and higher images, from a numeric render of the scene's image.
void appendDisk(Row& row, const Scene& scene) {
    Scene quiet = scene;
    quiet.settings.progress = false;
    const DiskObservables d = observeDisk(quiet, render(quiet));
    row.emplace_back("disk_flux", d.flux);
    row.emplace_back("disk_mean_redshift", d.meanRedshift);
    row.emplace_back("disk_higher_order_flux_fraction", d.higherOrderFraction());
}

// The outline's solid angle and centroid in the row; its points in the figures. Where only a
// small cap of sky is left the edges along the symmetry line are undefined (NaN), the outline not.
void appendOutline(Figures& f, const Scene& scene, int points) {
    const ShadowOutline o = traceShadowOutline(scene, points);
    f.row.emplace_back("shadow_solid_angle_sr", o.solidAngle);
    f.row.emplace_back("shadow_sky_fraction", o.solidAngle / (4 * kPi));
    const Vec3 c(o.centroid.dot(o.right), o.centroid.dot(o.up), o.centroid.dot(o.forward));
    f.row.emplace_back("shadow_centroid_polar_deg", std::acos(std::clamp(c(2), -1.0, 1.0)) * 180 / kPi);
    f.row.emplace_back("shadow_centroid_azimuth_deg", std::atan2(c(1), c(0)) * 180 / kPi);
    for (const Vec3& n : o.points) f.outline.emplace_back(n.dot(o.right), n.dot(o.up), n.dot(o.forward));
}

// The point source's images: how many, and their magnifications added (|mu|: what a detector that
// does not resolve them receives; signed: 1 for a point lens).
void appendPointSource(Row& row, const Scene& scene, const Vec3& source) {
    const PointSourceImages images = findPointSourceImages(scene, source);
    row.emplace_back("point_source_images", static_cast<double>(images.images.size()));
    row.emplace_back("point_source_magnification", images.totalMagnification());
    row.emplace_back("point_source_signed_magnification", images.signedMagnification());
}

Figures figuresOf(const Scene& scene, const SweepOptions& opt) {
    // A lens without a horizon (a wormhole, a warp bubble) has images but no shadow.
    if (opt.pointSource && scene.spacetime->asymptoticallyFlat() && !scene.spacetime->hasHorizon() &&
        opt.outline.empty()) {
        Figures f;
        appendPointSource(f.row, scene, *opt.pointSource);
        return f;
    }
    // Whatever has a horizon in an asymptotically flat spacetime casts a shadow: built-in or typed.
    if (scene.spacetime->asymptoticallyFlat() && scene.spacetime->hasHorizon()) {
        Figures f;
        auto noEdges = [&] {
            for (const char* name : {"shadow_centre_up_deg", "shadow_left_deg", "shadow_right_deg", "shadow_width_deg",
                                     "shadow_offset_deg", "shadow_height_deg"})
                f.row.emplace_back(name, std::nan(""));
        };
        try {
            f.row = shadowRow(scene);
        } catch (const NoSkyAlongGreatCircle&) {
            if (opt.outline.empty()) throw;
            noEdges();
        } catch (const std::invalid_argument&) {
            if (!opt.pointSource) throw;  // a camera that looks past the shadow at the images: they alone
            noEdges();
        }
        if (!opt.outline.empty()) appendOutline(f, scene, opt.outlinePoints);
        if (!scene.disks.empty()) appendDisk(f.row, scene);
        if (opt.pointSource) appendPointSource(f.row, scene, *opt.pointSource);
        return f;
    }
    if (opt.pointSource)
        throw std::invalid_argument("--point-source is a source at infinity: " + scene.spacetime->name() +
                                    " is not asymptotically flat");
    if (!opt.outline.empty())
        throw std::invalid_argument("--outline traces a black hole's shadow; " + scene.spacetime->name() +
                                    " casts none (asymptotically flat metrics with a horizon do)");
    if (const auto a = scene.spacetime->godelRadius()) return Figures{godelRow(scene, *a), {}};
    throw std::invalid_argument(
        "sweep measures shadows (asymptotically flat metrics with a horizon: schwarzschild, kerr, "
        "kerr-newman, formulas with \"horizon\" and \"far_field\") and Goedel images; " +
        scene.spacetime->name() + " has neither");
}

// Figures as text between MPI ranks: "name<TAB>value" lines, then one "@outline<TAB>x y z" line
// per outline point.
std::string encodeFigures(const Figures& f) {
    std::ostringstream out;
    out.precision(17);
    for (const auto& [name, value] : f.row) out << name << '\t' << value << '\n';
    for (const Vec3& n : f.outline) out << "@outline\t" << n(0) << ' ' << n(1) << ' ' << n(2) << '\n';
    return out.str();
}

Figures decodeFigures(const std::string& text) {
    Figures f;
    std::istringstream in(text);
    std::string name, value;
    // strtod, not >>: it reads back the "nan" of an undefined figure.
    while (std::getline(in, name, '\t') && std::getline(in, value)) {
        if (name == "@outline") {
            char* end = nullptr;
            const double x = std::strtod(value.c_str(), &end), y = std::strtod(end, &end),
                         z = std::strtod(end, nullptr);
            f.outline.emplace_back(x, y, z);
        } else
            f.row.emplace_back(name, std::strtod(value.c_str(), nullptr));
    }
    return f;
}

std::string csvNumber(double v) {
    if (!std::isfinite(v)) return "";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.12g", v);
    return buf;
}

// The figure a physicist quotes with the table: the worst estimated error of its angles, and where.
void printErrorEstimate(const std::string& field, const std::vector<double>& x,
                        const std::vector<PlotColumn>& columns) {
    for (const PlotColumn& c : columns) {
        if (c.name != "shadow_edge_error_deg") continue;
        std::size_t worst = c.values.size();
        for (std::size_t k = 0; k < c.values.size(); ++k)
            if (std::isfinite(c.values[k]) && (worst == c.values.size() || c.values[k] > c.values[worst])) worst = k;
        if (worst < c.values.size())
            std::printf(
                "error estimate: the shadow's angles to %.1e deg at worst (%s = %s; column shadow_edge_error_deg)\n",
                c.values[worst], field.c_str(), csvNumber(x[worst]).c_str());
        return;
    }
    std::printf("error estimate: none (Goedel images come from closed forms, exact to rounding)\n");
}

}  // namespace

int runSweep(const std::vector<std::string>& argv) {
    const SweepOptions opt = parseSweepOptions(argv);
    io::checkOutputPath(opt.table, {".csv"}, "--table");
    if (!opt.plot.empty()) io::checkOutputPath(opt.plot, {".svg"}, "--plot");
    if (!opt.outline.empty()) io::checkOutputPath(opt.outline, {".csv"}, "--outline");
    if (!opt.outlineVtk.empty()) io::checkOutputPath(opt.outlineVtk, {".vtp"}, "--outline-vtk");
#ifndef LIGHTCONE_WITH_VTK
    if (!opt.outlineVtk.empty()) throw std::invalid_argument("--outline-vtk needs a build with VTK");
#endif
    const dist::Processes& processes = dist::Processes::current();
    AnimationPath path;
    path.sweep = opt.sweep;
    const RenderOptions overrides = opt.render;
    const FrameSequence values(loadEditableScene(opt.render), path, [overrides](Scene& s) { overrides.applyTo(s); });

    warnAboutFixedSteps(values.scene(0));
    ProgressBar bar(processes.root() && !opt.render.quiet, "values ");
    std::vector<Row> rows(static_cast<std::size_t>(values.size()));
    std::vector<std::vector<Vec3>> outlines(rows.size());
    int done = 0;
    auto work = [&](int k) { return encodeFigures(figuresOf(values.scene(k), opt)); };
    auto deliver = [&](int k, std::string&& bytes) {
        Figures f = decodeFigures(bytes);
        rows[static_cast<std::size_t>(k)] = std::move(f.row);
        outlines[static_cast<std::size_t>(k)] = std::move(f.outline);
        bar(static_cast<double>(++done) / values.size());
    };
    if (processes.distributed())
        dist::runTasks(values.size(), work, deliver);
    else  // one process: exceptions as they are (messages, exit codes)
        for (int k = 0; k < values.size(); ++k) deliver(k, work(k));
    if (!processes.root()) return 0;

    // Columns in order of first appearance (image counts may grow with the value).
    std::vector<std::string> names;
    for (const Row& row : rows)
        for (const auto& entry : row)
            if (std::find(names.begin(), names.end(), entry.first) == names.end()) names.push_back(entry.first);
    std::vector<PlotColumn> columns;
    for (const auto& n : names) columns.push_back({n, std::vector<double>(rows.size(), std::nan(""))});
    std::vector<double> x;
    std::ostringstream csv;
    csv << opt.sweep.field;
    for (const auto& n : names) csv << ',' << n;
    csv << '\n';
    for (std::size_t k = 0; k < rows.size(); ++k) {
        x.push_back(opt.sweep.values.at(static_cast<int>(k)));
        for (const auto& [name, value] : rows[k])
            columns[static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin())].values[k] =
                value;
        csv << csvNumber(x.back());
        for (const auto& c : columns) csv << ',' << csvNumber(c.values[k]);
        csv << '\n';
    }
    // The outlines: CSV rows of camera angles and directions, sky curves for the plot, VTK lines.
    std::vector<SkyCurve> curves;
    std::vector<OutlineCurve> lines;
    std::ostringstream outlineCsv;
    outlineCsv << opt.sweep.field << ",point,polar_deg,azimuth_deg,right,up,forward\n";
    for (std::size_t k = 0; k < outlines.size() && !opt.outline.empty(); ++k) {
        SkyCurve curve{csvNumber(x[k]), {}, {}};
        for (std::size_t i = 0; i < outlines[k].size(); ++i) {
            const Vec3& n = outlines[k][i];
            const double polar = std::acos(std::clamp(n(2), -1.0, 1.0)) * 180 / kPi;
            const double azimuth = std::atan2(n(1), n(0)) * 180 / kPi;
            curve.polarDegrees.push_back(polar);
            curve.azimuthDegrees.push_back(azimuth);
            outlineCsv << csvNumber(x[k]) << ',' << i << ',' << csvNumber(polar) << ',' << csvNumber(azimuth) << ','
                       << csvNumber(n(0)) << ',' << csvNumber(n(1)) << ',' << csvNumber(n(2)) << '\n';
        }
        curves.push_back(std::move(curve));
        lines.push_back({x[k], outlines[k]});
    }
    io::OutputSet outputs;
    outputs.add(opt.table, csv.str(), "--table");
    if (!opt.plot.empty()) outputs.add(opt.plot, svgPlots(opt.sweep.field, x, columns, curves), "--plot");
    if (!opt.outline.empty()) outputs.add(opt.outline, outlineCsv.str(), "--outline");
#ifdef LIGHTCONE_WITH_VTK
    if (!opt.outlineVtk.empty()) outputs.add(opt.outlineVtk, outlinePolyData(opt.sweep.field, lines), "--outline-vtk");
#endif
    outputs.commit();
    std::printf("swept %s over %d values of %s: %zu columns\n", values.scene(0).source.c_str(), values.size(),
                opt.sweep.field.c_str(), names.size());
    printErrorEstimate(opt.sweep.field, x, columns);
    std::printf("wrote %s", opt.table.c_str());
    for (const std::string* extra : {&opt.plot, &opt.outline, &opt.outlineVtk})
        if (!extra->empty()) std::printf(", %s", extra->c_str());
    std::printf("\n");
    return 0;
}

}  // namespace lc::cli
