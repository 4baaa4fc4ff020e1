// SPDX-License-Identifier: BSD-3-Clause
#include "app/cli/command_options.hpp"

#include "core/spacetime/named_observer.hpp"

#include "core/input/number_text.hpp"
#include "core/metrics/factory.hpp"
#include "core/metrics/godel.hpp"
#include "core/render/render.hpp"
#include "core/scene/frame_camera.hpp"
#include "readers/io/metric_file.hpp"

#include <cmath>

namespace lc::cli {
namespace {

using namespace input;

// The command's declaration (app/cli/command_declarations.cpp).
const CommandDeclaration& declared(const std::string& name) {
    const CommandDeclaration* c = findCommand(name);
    if (!c) throw std::logic_error("lightcone declares no command " + name);
    return *c;
}

Vec3 direction(const Args& args, const std::string& k) {
    const auto d = args.numbers(k, 3);
    const Vec3 v(d[0], d[1], d[2]);
    if (!(v.norm() > 0)) throw std::invalid_argument("option " + k + " must not be the zero vector");
    return v;
}

// Goedel events within reach of the isometries (as in scene files).
void requireNearAxis(const std::string& option, double x, double y, double a) {
    const double r = std::hypot(x, y) / a;
    if (!kGodelAxisDistance.contains(r))
        throw std::invalid_argument("option " + option +
                                    ": Goedel events must lie within r = " + formatBound(kGodelAxisDistance.max) +
                                    " a of the axis, this one is at r = " + formatBound(r) + " a");
}

}  // namespace

void RenderOptions::applyTo(Scene& target) const {
    if (width) target.camera.width = *width;
    if (height) target.camera.height = *height;
    if (stepper) setSceneStepper(target.settings, *stepper);
    if (tolerance) target.settings.trace.absTol = target.settings.trace.relTol = *tolerance;
    if (threads) target.settings.threads = *threads;
    if (method) target.settings.method = *method;
    if (escapeRadius) target.settings.trace.escapeRadius = *escapeRadius;
    if (escapeAngle) target.settings.trace.escapeAngle = *escapeAngle;
    if (magnification) target.settings.magnification = true;
    if (windings) {
        target.settings.windings = *windings;
        // Goedel rays are followed for the windings asked for.
        if (!target.spacetime->asymptoticallyFlat())
            target.settings.trace.maxAffine = affineLengthForWindings(*target.spacetime, *windings);
    }
    if (maxAffine) target.settings.trace.maxAffine = *maxAffine;  // after --windings: the explicit limit wins
    if (lookAt) target.camera.lookAt = *lookAt;
    try {
        target.camera.validate();
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string(e.what()) + " (after --width/--height)");
    }
    if (lookAt) try {
            (void)frameCamera(target);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("option --look-at: " + std::string(e.what()));
        }
}

// What render and animate share: the scene or session, and the overrides of its settings.
RenderOptions renderOptionsFrom(const Args& args, const std::string& command) {
    RenderOptions o;
    if (args.has("--session")) {
        if (!args.positional().empty())
            throw std::invalid_argument(command + " takes a scene file or --session, not both (got '" +
                                        args.positional()[0] + "')");
        o.session = args.get("--session");
        if (o.session.empty()) throw std::invalid_argument("option --session needs a session file");
    } else {
        if (args.positional().size() != 1)
            throw std::invalid_argument(command + " expects one scene file (or --session FILE)");
        o.scene = args.positional()[0];
    }
    o.output = args.get("-o", o.output);
    o.data = args.get("--data");
    if (args.has("--data") && o.data.empty()) throw std::invalid_argument("option --data needs a file name");
    if (args.has("--width")) o.width = args.integer("--width", 0);
    if (args.has("--height")) o.height = args.integer("--height", 0);
    if (o.width && o.height && !kImagePixels.contains(double(*o.width) * *o.height))
        throw std::invalid_argument("options --width x --height: " +
                                    kImagePixels.problem(double(*o.width) * *o.height) + " (" + kImagePixels.why + ")");
    if (args.has("--stepper")) o.stepper = args.get("--stepper");
    if (args.has("--tolerance")) o.tolerance = args.number("--tolerance", 0);
    if (args.has("--windings")) o.windings = args.integer("--windings", 0);
    if (args.has("--threads")) o.threads = args.integer("--threads", 0);
    if (args.has("--max-affine")) o.maxAffine = args.number("--max-affine", 0);
    if (args.has("--escape-radius")) o.escapeRadius = args.number("--escape-radius", 0);
    if (args.has("--escape-angle")) o.escapeAngle = args.number("--escape-angle", 0);
    if (args.has("--look-at")) {
        const auto p = args.numbers("--look-at", 3);
        o.lookAt = Vec3(p[0], p[1], p[2]);
    }
    if (args.has("--method")) {
        if (args.get("--method") == "polygon_distortion")
            o.polygonDistortion = true;
        else
            o.method = parseRenderMethod(args.get("--method"));
    }
    o.quiet = args.has("--quiet");
    o.gpu = args.has("--gpu");
    o.magnification = args.has("--magnification");
    o.orbitFrames = args.integer("--orbit-frames", o.orbitFrames);
    if (!o.data.empty() && o.data == o.output) throw std::invalid_argument("--data and -o name the same file");
    o.tileRows = args.integer("--tile-rows", o.tileRows);
    o.staticSchedule = args.get("--schedule") == "static";
    return o;
}

RenderOptions parseRenderOptions(const std::vector<std::string>& argv) {
    const Args args(argv, declared("render"));
    RenderOptions o = renderOptionsFrom(args, "render");
    o.spectrum = args.all("--spectrum");
    for (const std::string& s : o.spectrum)
        if (s.empty()) throw std::invalid_argument("option --spectrum needs a file name (.csv or .svg)");
    return o;
}

AnimateOptions parseAnimateOptions(const std::vector<std::string>& argv) {
    const Args args(argv, declared("animate"));
    AnimateOptions o;
    o.render = renderOptionsFrom(args, "animate");
    if (!args.has("-o"))  // -o and --output are one option
        throw std::invalid_argument("animate needs -o FRAMES, a pattern such as frames/%04d.png");
    o.output = FramePattern(o.render.output, "-o");
    if (!o.render.data.empty()) o.data = FramePattern(o.render.data, "--data");
    AnimationPath& p = o.path;
    if (args.has("--proper-time"))
        p.properTime = parseFrameInterval("--proper-time", args.get("--proper-time"), args.range("--proper-time"));
    if (args.has("--motion")) {
        p.motion = parseObserverMotion(args.get("--motion"));
    }
    if (args.has("--pan")) p.panDegrees = parseFrameInterval("--pan", args.get("--pan"), args.range("--pan"));
    if (args.has("--orbit")) p.orbitDegrees = parseFrameInterval("--orbit", args.get("--orbit"), args.range("--orbit"));
    if (args.all("--sweep").size() > 1) throw std::invalid_argument("give one --sweep (animate sweeps one field)");
    if (args.has("--sweep")) p.sweep = parseFieldSweep("--sweep", args.get("--sweep"));
    if (args.has("--frames")) {
        const std::string range = args.get("--frames");
        const auto dash = range.find('-', 1);
        if (dash == std::string::npos)
            throw std::invalid_argument("option --frames expects FIRST-LAST, got '" + range + "'");
        const int firstFrame =
            static_cast<int>(parseNamedNumber("--frames (FIRST)", range.substr(0, dash), args.range("--frames")));
        const int lastFrame =
            static_cast<int>(parseNamedNumber("--frames (LAST)", range.substr(dash + 1), args.range("--frames")));
        if (firstFrame > lastFrame) throw std::invalid_argument("option --frames: FIRST must not exceed LAST");
        o.frameRange = std::make_pair(firstFrame, lastFrame);
    }
    o.resume = args.has("--resume");
    o.movie = args.get("--movie");
    if (args.has("--movie") && o.movie.empty()) throw std::invalid_argument("option --movie needs a file name");
    o.fps = args.integer("--fps", o.fps);
    return o;
}

SweepOptions parseSweepOptions(const std::vector<std::string>& argv) {
    const Args args(argv, declared("sweep"));
    SweepOptions o;
    o.render = renderOptionsFrom(args, "sweep");
    if (!args.has("--sweep")) throw std::invalid_argument("sweep needs --sweep FIELD=FROM:TO:VALUES");
    if (args.all("--sweep").size() > 1) throw std::invalid_argument("give one --sweep (a table has one swept field)");
    o.sweep = parseFieldSweep("--sweep", args.get("--sweep"));
    o.table = args.get("--table");
    if (o.table.empty()) throw std::invalid_argument("sweep needs --table OUT.csv");
    o.plot = args.get("--plot");
    if (args.has("--plot") && o.plot.empty()) throw std::invalid_argument("option --plot needs a file name");
    if (o.plot == o.table) throw std::invalid_argument("--plot and --table name the same file");
    o.outline = args.get("--outline");
    o.outlineVtk = args.get("--outline-vtk");
    o.outlinePoints = args.integer("--outline-points", o.outlinePoints);
    // Each point is a traced edge ray and a line of text: 1e5 values of 1e5 points would be 1e10.
    const double outlineRays = double(o.outlinePoints) * o.sweep.values.frames;
    if ((!o.outline.empty() || !o.outlineVtk.empty()) && outlineRays > 1e7)
        throw std::invalid_argument("--outline-points " + std::to_string(o.outlinePoints) + " for " +
                                    std::to_string(o.sweep.values.frames) + " values is " +
                                    input::significantDigits(outlineRays) +
                                    " edge rays, more than 1e7: fewer values or --outline-points");
    for (const std::string* name : {&o.outline, &o.outlineVtk})
        if (!name->empty() && (*name == o.table || *name == o.plot))
            throw std::invalid_argument("--outline and --outline-vtk need files of their own");
    if (args.has("--point-source")) o.pointSource = direction(args, "--point-source");
    return o;
}

namespace {
// --param NAME=VALUE, every one given.
std::map<std::string, double> namedParameters(const Args& args) {
    static const Range anyParameter{"metric parameter", -1e12, 1e12, false, "", ""};
    std::map<std::string, double> parameters;
    for (const auto& kv : args.all("--param")) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos || eq == 0)
            throw std::invalid_argument("--param expects NAME=VALUE, got '" + kv + "'");
        parameters[kv.substr(0, eq)] = parseNamedNumber("--param " + kv.substr(0, eq), kv.substr(eq + 1), anyParameter);
    }
    return parameters;
}
}  // namespace

SpacetimePtr traceSpacetime(const TraceCommandOptions& o) {
    if (!o.metricFile.empty()) return io::loadFormulaMetric(o.metricFile, o.parameters);
    try {
        return makeSpacetime(o.metric, o.parameters);
    } catch (const std::invalid_argument& e) {
        // Say which option and metric were refused (the constructor names its class only).
        std::string given;
        for (const auto& [name, value] : o.parameters)
            given += " --param " + name + "=" + input::significantDigits(value);
        throw std::invalid_argument("option --metric " + o.metric + given + ": " + e.what() +
                                    " (accepted parameters: lightcone ranges)");
    }
}

MetricCheckOptions parseMetricCheckOptions(const std::vector<std::string>& argv) {
    const Args args(argv, declared("metric"));
    const auto& files = args.positional();
    MetricCheckOptions o;
    if (files.size() == 1 && files[0] == "list") {
        if (args.has("--at") || args.has("--param"))
            throw std::invalid_argument("metric list takes no options (they belong to 'metric check NAME')");
        o.list = true;
        return o;
    }
    if (files.size() != 2 || (files[0] != "check" && files[0] != "show"))
        throw std::invalid_argument(
            "metric expects 'check FILE.json' or 'check NAME' (a metric written as formulas, docs/METRICS.md), "
            "'show FILE.json|NAME', or 'list'");
    o.show = files[0] == "show";
    if (o.show && args.has("--at"))
        throw std::invalid_argument("metric show takes no --at (it belongs to 'metric check')");
    o.file = files[1];
    o.parameters = namedParameters(args);
    if (args.has("--at")) {
        const auto v = args.numbers("--at", 4);
        o.at = Vec4(v[0], v[1], v[2], v[3]);
    }
    return o;
}

TraceCommandOptions parseTraceOptions(const std::vector<std::string>& argv) {
    const Args args(argv, declared("trace"));
    if (!args.positional().empty())
        throw std::invalid_argument("trace takes no file, got '" + args.positional()[0] + "'");
    TraceCommandOptions o;
    o.metric = args.get("--metric", o.metric);
    o.parameters = namedParameters(args);
    o.metricFile = args.get("--metric-file");
    if (args.has("--metric-file") && o.metricFile.empty())
        throw std::invalid_argument("option --metric-file needs a file");
    const SpacetimePtr st = traceSpacetime(o);                         // names and ranges of the metric's parameters
    o.trace.stepper = parseStepper(args.get("--stepper", "dopri87"));  // best accuracy per cost for single rays
    o.trace.absTol = o.trace.relTol = args.number("--tolerance", 1e-12);
    if (o.trace.stepper == StepperKind::RK4 && args.has("--tolerance"))
        throw std::invalid_argument(
            "option --tolerance: rk4 takes fixed steps of --initial-step H and has no tolerance; give the step, or "
            "an adaptive stepper (cash_karp54, dopri5, dopri87, bulirsch_stoer)");
    // Rays of an asymptotically flat metric end by themselves (escape, horizon, --max-steps).
    o.trace.maxAffine = args.number("--max-affine", st->asymptoticallyFlat() ? INFINITY : 1e8);
    o.trace.maxSteps = static_cast<std::size_t>(args.integer("--max-steps", 1000000));
    o.trace.initialStep = args.number("--initial-step", 1e-2);
    o.future = args.has("--future");
    if (args.has("--impact")) {
        o.impact = args.number("--impact", 0);
        o.distance = args.number("--distance", o.distance);
    } else {
        if (!args.has("--event") || !args.has("--direction"))
            throw std::invalid_argument("trace needs --event t,x,y,z and --direction nx,ny,nz (or --impact B)");
        const auto e = args.numbers("--event", 4);
        o.event = Vec4(e[0], e[1], e[2], e[3]);
        o.direction = direction(args, "--direction");
        if (args.has("--observer")) {
            o.observer = args.get("--observer");
            if (!namedObserverFrom(o.observer)) {
                if (o.observer.find(',') == std::string::npos)
                    throw std::invalid_argument("option --observer: expected one of " + namedObserverNames() +
                                                ", or four numbers u^t,u^x,u^y,u^z; got '" + o.observer + "'");
                const auto u = args.numbers("--observer", 4, &input::kObserverVelocityComponent);
                o.observerVelocity = Vec4(u[0], u[1], u[2], u[3]);
                o.observer = "given";
            }
        }
    }
    if (args.has("--source-plane")) {
        if (o.future) throw std::invalid_argument("option --source-plane follows the ray to its source: drop --future");
        const auto v = args.numbers("--source-plane", 6);
        std::array<double, 6> plane;
        std::copy(v.begin(), v.end(), plane.begin());
        if (!(Vec3(plane[3], plane[4], plane[5]).norm() > 0))
            throw std::invalid_argument("option --source-plane: the normal (the last three numbers) must not be zero");
        o.sourcePlane = plane;
    }
    return o;
}

ImagesOptions parseImagesOptions(const std::vector<std::string>& argv) {
    const Args args(argv, declared("images"));
    if (!args.positional().empty())
        throw std::invalid_argument("images takes no file, got '" + args.positional()[0] + "'");
    ImagesOptions o;
    o.a = args.number("--a", o.a);
    if (args.has("--observer")) {
        const auto v = args.numbers("--observer", 4);
        o.observer = Vec4(v[0], v[1], v[2], v[3]);
        requireNearAxis("--observer", v[1], v[2], o.a);
    }
    if (!args.has("--cylindrical") && !args.has("--point"))  // both: refused by the declaration
        throw std::invalid_argument("images needs exactly one of --point x,y,z and --cylindrical r,phi,z");
    if (args.has("--cylindrical")) {
        const auto c = args.numbers("--cylindrical", 3);
        if (c[0] < 0) throw std::invalid_argument("option --cylindrical: the radius r must be >= 0");
        o.point = Vec3(c[0] * std::cos(c[1]), c[0] * std::sin(c[1]), c[2]);
    } else {
        const auto p = args.numbers("--point", 3);
        o.point = Vec3(p[0], p[1], p[2]);
    }
    requireNearAxis(args.has("--point") ? "--point" : "--cylindrical", o.point(0), o.point(1), o.a);
    o.windings = args.integer("--windings", o.windings);
    o.future = args.has("--future");
    return o;
}

ExportOptions parseExportOptions(const std::vector<std::string>& argv) {
    const Args args(argv, declared("export"));
    if (args.positional().size() != 1) throw std::invalid_argument("export expects one scene file");
    ExportOptions o;
    o.scene = args.positional()[0];
    o.directory = args.get("-o", o.directory);
    if (o.directory.empty()) throw std::invalid_argument("option -o needs a folder name");
    o.rays = args.integer("--rays", o.rays);
    o.maxMegabytes = args.number("--max-size", o.maxMegabytes);
    o.quiet = args.has("--quiet");
    return o;
}

DiagramOptions parseDiagramOptions(const std::vector<std::string>& argv) {
    const Args args(argv, declared("diagram"));
    if (args.positional().size() != 1) throw std::invalid_argument("diagram expects one scene file");
    DiagramOptions o;
    o.scene = args.positional()[0];
    o.outputs = args.all("-o");
    if (o.outputs.empty()) o.outputs.push_back("diagram.svg");
    if (args.has("--windings")) o.windings = args.integer("--windings", 0);
    o.rays = args.integer("--rays", o.rays);
    o.size = args.integer("--size", o.size);
    o.kind = args.get("--kind") == "t-r" ? DiagramKind::TR : DiagramKind::RPhi;
    return o;
}

FigureOptions parseFigureOptions(const std::vector<std::string>& argv) {
    const Args args(argv, declared("figure"));
    if (args.positional().size() != 1) throw std::invalid_argument("figure expects one scene file");
    FigureOptions o;
    o.scene = args.positional()[0];
    o.outputs = args.all("-o");
    if (o.outputs.empty()) o.outputs.push_back("figure.pdf");
    o.quantity = args.get("--quantity", o.quantity);
    o.size = args.integer("--size", o.size);
    return o;
}

CurvatureOptions parseCurvatureOptions(const std::vector<std::string>& argv) {
    const Args args(argv, declared("curvature"));
    CurvatureOptions o;
    if (args.positional().size() > 1)
        throw std::invalid_argument("curvature expects at most one scene file, got '" + args.positional()[1] + "'");
    if (!args.positional().empty()) {
        o.scene = args.positional()[0];
        for (const char* k : {"--metric", "--metric-file", "--param"})
            if (args.has(k))
                throw std::invalid_argument(std::string("option ") + k +
                                            " names a metric, but the scene file gives one already");
    }
    o.metric = args.get("--metric", o.metric);
    o.metricFile = args.get("--metric-file");
    if (args.has("--metric-file") && o.metricFile.empty())
        throw std::invalid_argument("option --metric-file needs a file");
    o.parameters = namedParameters(args);
    if (args.has("--at")) {
        const auto v = args.numbers("--at", 4);
        o.at = Vec4(v[0], v[1], v[2], v[3]);
    }
    o.output = args.get("--output");
    if (args.has("--output") && o.output.empty()) throw std::invalid_argument("option -o needs a file");
    o.image = args.get("--image");
    if (args.has("--image") && o.image.empty()) throw std::invalid_argument("option --image needs a file");
    o.logScale = args.has("--log");
    for (const char* k : {"--bounds", "--dims", "--time", "--quantity"})
        if (args.has(k) && o.output.empty() && o.image.empty())
            throw std::invalid_argument(std::string("option ") + k +
                                        " shapes the grid: give -o FIELD.vti or --image SLICE.png too");
    if (args.has("--bounds")) {
        const auto b = args.numbers("--bounds", 6);
        std::copy(b.begin(), b.end(), o.bounds.begin());
        for (int axis = 0; axis < 3; ++axis)
            if (o.bounds[2 * axis] > o.bounds[2 * axis + 1])
                throw std::invalid_argument("option --bounds: the lower bound of axis " + std::to_string(axis + 1) +
                                            " exceeds its upper bound");
    }
    if (args.has("--dims")) {
        const auto d = args.numbers("--dims", 3);
        for (int axis = 0; axis < 3; ++axis) o.dims[static_cast<std::size_t>(axis)] = static_cast<int>(d[axis]);
    }
    for (int axis = 0; axis < 3; ++axis)
        if (o.dims[static_cast<std::size_t>(axis)] == 1 && o.bounds[2 * axis] != o.bounds[2 * axis + 1])
            throw std::invalid_argument("option --dims: axis " + std::to_string(axis + 1) +
                                        " has one point but --bounds gives it a range; give it 2 points or more, "
                                        "or equal bounds");
    o.time = args.number("--time", o.time);
    o.quantities = args.all("--quantity");
    o.lambda = args.number("--lambda", o.lambda);
    o.observers = args.get("--observers", o.observers);
    o.tides = args.get("--tides");
    if (args.has("--tides") && o.scene.empty())
        throw std::invalid_argument("option --tides follows the scene's observer: give a scene file");
    o.plot = args.get("--plot");
    o.object = args.get("--object");
    o.properTimeGiven = args.has("--proper-time");
    o.properTime = args.number("--proper-time", o.properTime);
    if (o.properTime == 0) throw std::invalid_argument("option --proper-time must not be 0");
    o.samples = args.integer("--samples", o.samples);
    o.quiet = args.has("--quiet");
    if (!o.at && o.output.empty() && o.image.empty() && o.tides.empty())
        throw std::invalid_argument(
            "curvature needs --at t,x,y,z, -o FIELD.vti, --image SLICE.png or --tides TIDES.csv");
    if (o.scene.empty()) (void)curvatureSpacetime(o);  // the metric's name and parameters, checked now
    return o;
}

SpacetimePtr curvatureSpacetime(const CurvatureOptions& o) {
    if (!o.metricFile.empty()) return io::loadFormulaMetric(o.metricFile, o.parameters);
    return makeSpacetime(o.metric, o.parameters);
}

ShadeOptions parseShadeOptions(const std::vector<std::string>& argv) {
    const Args args(argv, declared("shade"));
    if (args.positional().size() != 2)
        throw std::invalid_argument("shade expects a scene file and a data file (render --data)");
    ShadeOptions o;
    o.scene = args.positional()[0];
    o.data = args.positional()[1];
    o.output = args.get("-o", o.output);
    if (args.has("--time-window")) {
        const auto w = args.numbers("--time-window", 2);
        if (!(w[0] <= w[1])) throw std::invalid_argument("option --time-window: t0 must not exceed t1");
        o.timeWindow = std::make_pair(w[0], w[1]);
    }
    if (args.has("--temperature")) o.temperature = args.number("--temperature", 0);
    if (args.has("--show")) {
        o.showName = args.get("--show");
        o.show = parseLensingQuantity(o.showName);
    }
    for (const std::string& t : args.all("--texture")) {
        const auto eq = t.find('=');
        if (t.empty() || eq == 0 || eq + 1 == t.size())
            throw std::invalid_argument(
                "option --texture expects TEXTURE or OBJECT=TEXTURE (e.g. checker, 0=earth), got '" + t + "'");
        o.textures.emplace_back(eq == std::string::npos ? "" : t.substr(0, eq),
                                eq == std::string::npos ? t : t.substr(eq + 1));
    }
    o.outsideTexture = args.get("--outside-texture");
    if (args.has("--uv-offset")) {
        const auto d = args.numbers("--uv-offset", 2);
        o.uOffset = d[0];
        o.vOffset = d[1];
    }
    if (args.has("--uv-scale")) {
        const auto d = args.numbers("--uv-scale", 2);
        o.uScale = d[0];
        o.vScale = d[1];
    }
    if (args.has("--blink")) {
        const auto b = args.numbers("--blink", 4, &kCoordinate);  // each part checked below
        if (!kBlinkPeriod.contains(b[0]))
            throw std::invalid_argument("option --blink (period): " + kBlinkPeriod.problem(b[0]));
        for (int k : {1, 3})
            if (!kUnitFraction.contains(b[k]))
                throw std::invalid_argument(std::string("option --blink (") + (k == 1 ? "duty" : "off level") +
                                            "): " + kUnitFraction.problem(b[k]));
        o.blink = std::array<double, 4>{b[0], b[1], b[2], b[3]};
    }
    if (args.has("--sweep")) {
        FieldSweep s = parseFieldSweep("--sweep", args.get("--sweep"));
        const std::map<std::string, const input::Range*> fields{{"temperature", &kTemperature},
                                                                {"u-offset", &kUvOffset},
                                                                {"v-offset", &kUvOffset},
                                                                {"time-window", &kCoordinate},
                                                                {"blink-phase", &kCoordinate}};
        const auto f = fields.find(s.field);
        if (f == fields.end())
            throw std::invalid_argument("option --sweep: cannot sweep '" + s.field +
                                        "' (use temperature, u-offset, v-offset, time-window or blink-phase)");
        for (double v : {s.values.from, s.values.to})
            if (!f->second->contains(v))
                throw std::invalid_argument("option --sweep (" + s.field + "): " + f->second->problem(v));
        if (s.field == "time-window" && !o.timeWindow)
            throw std::invalid_argument("option --sweep time-window moves t0 of --time-window: give --time-window too");
        if (s.field == "blink-phase" && !o.blink)
            throw std::invalid_argument("option --sweep blink-phase needs --blink");
        o.sweep = s;
        o.frames = FramePattern(o.output, "-o");
    }
    return o;
}

void parseCommandLine(const std::vector<std::string>& argv) {
    if (argv.empty()) throw std::invalid_argument("no command");
    const std::vector<std::string> rest(argv.begin() + 1, argv.end());
    const std::string& cmd = argv[0];
    if (cmd == "render")
        parseRenderOptions(rest);
    else if (cmd == "trace")
        parseTraceOptions(rest);
    else if (cmd == "images")
        parseImagesOptions(rest);
    else if (cmd == "metric")
        parseMetricCheckOptions(rest);
    else if (cmd == "export")
        parseExportOptions(rest);
    else if (cmd == "diagram")
        parseDiagramOptions(rest);
    else if (cmd == "figure")
        parseFigureOptions(rest);
    else if (cmd == "shade")
        parseShadeOptions(rest);
    else if (cmd == "animate")
        parseAnimateOptions(rest);
    else if (cmd == "sweep")
        parseSweepOptions(rest);
    else if (cmd == "curvature")
        parseCurvatureOptions(rest);
    else
        throw std::invalid_argument("unknown command '" + cmd + "'");
}

}  // namespace lc::cli
