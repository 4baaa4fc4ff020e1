// SPDX-License-Identifier: BSD-3-Clause
// The table of app/cli/command_line.hpp: each command's usage, options and examples. What an option
// means is said here once; app/cli/command_options.cpp turns the parsed values into each command's
// options struct.
#include "app/cli/command_line.hpp"

#include "core/curvature/curvature_field.hpp"
#include "core/metrics/factory.hpp"
#include "core/scene/scene.hpp"
#include "core/spacetime/integrator.hpp"

#include <utility>

namespace lc::cli {
namespace {

using namespace input;

// One option, built up: option("--width", "N", "image width").range(kImageSide).
struct Option {
    OptionDeclaration d;
    Option(std::string names, std::string value, std::string help) {
        d.names = std::move(names);
        d.value = std::move(value);
        d.help = std::move(help);
    }
    Option& range(const Range& r) {
        d.range = &r;
        return *this;
    }
    Option& repeatable() {
        d.repeatable = true;
        return *this;
    }
    Option& choices(std::vector<std::string> words) {
        d.choices = std::move(words);
        return *this;
    }
    Option& needs(std::string other) {
        d.needs.push_back(std::move(other));
        return *this;
    }
    Option& excludes(std::string other) {
        d.excludes.push_back(std::move(other));
        return *this;
    }
};

using Options = std::vector<OptionDeclaration>;

void add(Options& to, const std::string& group, std::initializer_list<Option> options) {
    for (const Option& o : options) {
        to.push_back(o.d);
        to.back().group = group;
    }
}

std::vector<std::string> metricNames() {
    std::vector<std::string> names;
    for (const auto& m : knownMetrics()) names.push_back(m.name);
    return names;
}

// The Goedel radius a of `images --a`, as the metric's parameter table bounds it.
const Range& godelRadiusRange() {
    static const Range range = [] {
        for (const auto& m : knownMetrics())
            if (m.name == "godel") return m.parameters.front().range();
        return kLength;
    }();
    return range;
}

const char* const kScene = "Scene and output";
const char* const kImage = "Image";
const char* const kAccuracy = "Method and accuracy";

// What render, animate and sweep share: the scene's tracing settings overridden.
void addTracingOverrides(Options& o) {
    add(o, kAccuracy,
        {Option("--stepper", "NAME",
                "Odeint stepper of the numeric tracer (default: the scene's; auto: dopri5 for images, dopri87 "
                "for shadow edges)")
             .choices(sceneStepperNames()),
         Option("--tolerance", "T", "absolute and relative error per step of the numeric tracer").range(kTolerance),
         Option("--windings", "N", "Goedel: how many times a ray may wind round the axis (images up to order N)")
             .range(kWindings),
         Option("--threads", "N", "worker threads, 0 = every core (default: the scene's)").range(kThreads)});
}

// render's and animate's scene, outputs and overrides of the scene's camera and settings.
Options renderFamilyOptions(const std::string& output, const std::string& outputHelp, const std::string& data) {
    Options o;
    add(o, kScene,
        {Option("--session", "FILE.lcsession",
                "a workbench session (docs/SESSIONS.md) instead of SCENE.json: its scene with the edits"),
         Option("-o,--output", output, outputHelp),
         Option("--data", data,
                "the per-pixel data as well (object, u, v, redshift, emission time, drift, ...; EXR or TIFF), "
                "re-shaded later by `lightcone shade`")
             .excludes("--gpu"),
         Option("--quiet", "", "no progress bar")});
    add(o, kImage,
        {Option("--width", "N", "image width (default: the scene's camera)").range(kImageSide),
         Option("--height", "N", "image height (default: the scene's camera)").range(kImageSide),
         Option("--look-at", "X,Y,Z", "turn the camera from the observer towards this position of the chart")
             .range(kCoordinate)});
    add(o, kAccuracy,
        {Option("--method", "NAME",
                "how rays are found (default auto: the exact method the scene allows; README's table)")
             .choices({"auto", "numeric", "closed_form", "per_vertex", "polygon_distortion"})});
    addTracingOverrides(o);
    add(o, kAccuracy,
        {Option("--max-affine", "L", "numeric tracer: the affine length after which a ray stops").range(kMaxAffine),
         Option("--escape-radius", "R", "numeric tracer: a ray beyond this radius has escaped (0: automatic)")
             .range(kEscapeRadius),
         Option("--escape-angle", "RAD", "numeric tracer: bending still allowed after escape").range(kEscapeAngle)});
    add(o, "GPU", {Option("--gpu", "", "draw with the OpenGL shaders (VTK; needs an X server, e.g. xvfb-run -a)")});
    add(o, "MPI (under mpirun)",
        {Option("--tile-rows", "N", "rows per band of the image shared among the ranks (default: automatic)")
             .range(kImageSide),
         Option("--schedule", "NAME", "dynamic: bands to whichever rank is free; static: band k to rank k % ranks")
             .choices({"dynamic", "static"})});
    return o;
}

CommandDeclaration render() {
    CommandDeclaration c{"render", "the observer's image of a scene, on the CPU (or --gpu)", {}, {}, {}, false};
    c.usage = {"(SCENE.json | --session FILE.lcsession) -o IMAGE.png [OPTIONS]"};
    c.options = renderFamilyOptions("IMAGE.png",
                                    "the image: .png, .jpg, .tif, or .exr in linear light (default "
                                    "lightcone.png)",
                                    "DATA.exr");
    add(c.options, kScene,
        {Option("--spectrum", "OUT.csv|OUT.svg", "an accretion disk's observed spectrum, as a table or a plot")
             .repeatable()
             .excludes("--gpu"),
         Option("--magnification", "",
                "every ray carries a thin bundle (its Jacobi map): the data gains each pixel's magnification, "
                "shear and rotation (docs/PHYSICS.md 13a; the scene's render.magnification)")
             .needs("--data")});
    add(c.options, "GPU",
        {Option("--orbit-frames", "N", "special relativity: frames of the timed camera orbit after the image")
             .range(kOrbitFrames)
             .needs("--gpu")});
    c.examples = {
        "lightcone render data/default.json -o default.png",
        "lightcone render data/kerr_disk.json -o disk.png --spectrum spectrum.svg",
        "lightcone render data/kerr.json -o kerr.png --width 640 --height 480 --tolerance 1e-10",
        "lightcone render data/kerr.json -o kerr.png --data kerr.exr --magnification --width 160 --height 120"};
    return c;
}

CommandDeclaration animate() {
    CommandDeclaration c{
        "animate", "frames (and a movie) along a path: proper time, pan, orbit, a field sweep", {}, {}, {}, false};
    c.usage = {"(SCENE.json | --session FILE) -o FRAMES/%04d.png [PATH] [OPTIONS]"};
    c.options = renderFamilyOptions("FRAMES/%04d.png", "the frame files: a pattern with one frame number (required)",
                                    "FRAMES/%04d.exr");
    add(c.options, "Path (default: the scene's \"animation\" block)",
        {Option("--proper-time", "T0:T1:N", "the observer's proper time from T0 to T1 in N frames").range(kCoordinate),
         Option("--motion", "NAME", "the observer's world line along --proper-time (default: from its velocity)")
             .choices({"static", "free_fall"})
             .needs("--proper-time"),
         Option("--pan", "D0:D1:N", "turn the camera about its up direction, in degrees").range(kTurnDegrees),
         Option("--orbit", "D0:D1:N", "orbit the camera round the scene, in degrees").range(kTurnDegrees),
         Option("--sweep", "FIELD=V0:V1:N", "one number of the scene (e.g. metric.a, objects[0].radius) per frame")});
    add(c.options, "Frames and movie",
        {Option("--frames", "FIRST-LAST", "only these frames (job arrays)").range(kFrameIndex),
         Option("--resume", "", "skip frames whose files exist"),
         Option("--movie", "OUT.mp4", "encode the frames with ffmpeg"),
         Option("--fps", "F", "frames per second of --movie (default 24)").range(kFramesPerSecond).needs("--movie")});
    c.examples = {
        "lightcone animate data/godel_free_fall_earth.json -o earth/%04d.png --width 550 --height 63 --movie "
        "earth.mp4",
        "lightcone animate data/godel_time_traveller.json -o trip/%03d.png --movie trip.mp4",
        "lightcone animate data/kerr.json -o spin/%03d.png --sweep metric.a=0:0.99:50"};
    return c;
}

CommandDeclaration sweep() {
    CommandDeclaration c{
        "sweep",
        "a table per value of one field: Kerr shadow size and offset, a disk's flux and mean redshift, "
        "Goedel images and emission times",
        {},
        {},
        {},
        false};
    c.usage = {"(SCENE.json | --session FILE) --sweep FIELD=V0:V1:N --table OUT.csv [--plot OUT.svg] [OPTIONS]"};
    add(c.options, kScene,
        {Option("--session", "FILE.lcsession", "a workbench session instead of SCENE.json"),
         Option("--sweep", "FIELD=V0:V1:N",
                "the swept number of the scene (e.g. metric.a) and its N values (required)"),
         Option("--table", "OUT.csv", "the table (required)"), Option("--plot", "OUT.svg", "the table plotted"),
         Option("--quiet", "", "no progress bar")});
    add(c.options, "Shadow outline",
        {Option("--outline", "OUT.csv",
                "black holes: the shadow's whole outline per value (camera angles and directions); adds its solid "
                "angle and centroid to the table and its curves to the plot"),
         Option("--outline-vtk", "OUT.vtp", "the outlines as VTK polylines on the unit sphere of directions")
             .needs("--outline"),
         Option("--outline-points", "N", "edge points round each outline (default 360)")
             .range(kOutlinePoints)
             .needs("--outline")});
    add(c.options, "Lensing",
        {Option("--point-source", "X,Y,Z",
                "a point source at infinity in this chart direction (asymptotically flat metrics): every image "
                "of it the camera sees, found with the rays' Jacobi maps, and their total magnification "
                "(docs/PHYSICS.md 13b)")
             .range(kCoordinate)});
    addTracingOverrides(c.options);
    c.examples = {"lightcone sweep data/kerr.json --sweep metric.a=0:0.99:12 --table shadow.csv --plot shadow.svg",
                  "lightcone sweep data/schwarzschild_infall.json --sweep \"observer.position[1]=10:2.2:5\" --table "
                  "infall.csv --outline outlines.csv --plot infall.svg",
                  "lightcone sweep data/kerr.json --sweep metric.a=0:0.99:3 --table lensed.csv --point-source "
                  "-1,0.06,0"};
    return c;
}

CommandDeclaration trace() {
    CommandDeclaration c{"trace", "one null geodesic of any metric, as JSON (states, drift, deflection)", {}, {}, {},
                         false};
    c.usage = {"--metric NAME [--param K=V]... --event t,x,y,z --direction nx,ny,nz [OPTIONS]",
               "--metric NAME [--param K=V]... --impact B [--distance D] [OPTIONS]"};
    add(c.options, "Spacetime",
        {Option("--metric", "NAME", "the metric (default schwarzschild)")
             .choices(metricNames())
             .excludes("--metric-file"),
         Option("--metric-file", "METRIC.json", "a metric written as formulas (docs/METRICS.md) instead of --metric"),
         Option("--param", "K=V", "a parameter of the metric (lightcone ranges lists them)").repeatable()});
    add(c.options, "Launch",
        {Option("--event", "t,x,y,z", "the event the ray starts from").range(kCoordinate).needs("--direction"),
         Option("--direction", "nx,ny,nz",
                "a chart direction at the event, seen in the observer's rest space; the ray runs along it: "
                "the ray the observer sees looking that way, traced back to its source, or with --future the "
                "photon it sends that way")
             .range(kDirectionComponent)
             .needs("--event"),
         Option("--observer", "NAME|ut,ux,uy,uz",
                "who launches the ray: static (default), zamo, carter, free_fall, normal (e.g. a warp drive's "
                "Eulerian observer, inside its bubble), or a 4-velocity")
             .needs("--event"),
         Option("--impact", "B", "asymptotically flat metrics: a ray from far away with this impact parameter")
             .range(kImpactParameter)
             .excludes("--event")
             .excludes("--direction"),
         Option("--distance", "D", "where the --impact ray starts (default 1e6)")
             .range(kLaunchDistance)
             .needs("--impact"),
         Option("--future", "",
                "the photon the observer sends, followed to the future (default: the ray it sees, "
                "followed back to its source)"),
         Option("--source-plane", "X,Y,Z,NX,NY,NZ",
                "the ray's Jacobi map where it meets the plane through (X,Y,Z) with normal (NX,NY,NZ), and the "
                "image's magnification for a source there")
             .range(kCoordinate)
             .needs("--event")});
    add(c.options, kAccuracy,
        {Option("--stepper", "NAME", "Odeint stepper (default dopri87)").choices(stepperNames()),
         Option("--tolerance", "T", "absolute and relative error per step of an adaptive stepper (default 1e-12)")
             .range(kTolerance),
         Option("--max-affine", "L",
                "stop after this affine length (default: unbounded when asymptotically flat, "
                "else 1e8)")
             .range(kMaxAffine),
         Option("--max-steps", "N",
                "stop after this many steps (default 1e6); a ray stopped so before its end (escape, the "
                "horizon, --max-affine) exits with status 4 and says so (no deflection)")
             .range(kMaxSteps),
         Option("--initial-step", "H", "the adaptive stepper's first step (default 0.01)").range(kInitialStep)});
    c.examples = {
        "lightcone trace --metric schwarzschild --impact 10 --tolerance 1e-12",
        "lightcone trace --metric godel --param a=1 --event 0,0.5,0,0 --direction 0,1,0 --max-affine 20",
        "lightcone trace --metric alcubierre --param v=2 --event 0,0,0,0 --observer normal --direction -1,0,0 "
        "--future --max-affine 10"};
    return c;
}

CommandDeclaration metric() {
    CommandDeclaration c{"metric",
                         "metrics written as formulas: the catalogue found (list), one described with a scene to start "
                         "from (show), or one parsed, checked, its derived properties and cost (check)",
                         {},
                         {},
                         {},
                         false};
    c.usage = {"check METRIC.json|NAME [--at t,x,y,z] [--param K=V]...", "show METRIC.json|NAME [--param K=V]...",
               "list"};
    add(c.options, "Spacetime",
        {Option("--at", "t,x,y,z", "the event where g is printed and checked (default 0,10,1,2)").range(kCoordinate),
         Option("--param", "K=V", "a parameter of the metric (default: the file's)").repeatable()});
    c.examples = {"lightcone metric check data/metrics/kerr.json --param a=0.5",
                  "lightcone metric check ellis_wormhole --at 0,0.5,0,0",
                  "lightcone metric show cosmic_string --param mu=0.1", "lightcone metric list"};
    return c;
}

CommandDeclaration images() {
    CommandDeclaration c{"images",
                         "every image of a point in the Goedel universe (the inverse problem), as JSON; each image's "
                         "direction (psi, phi0) "
                         "in the observer's static frame, the camera's (docs/PHYSICS.md section 8)",
                         {},
                         {},
                         {},
                         false};
    c.usage = {"[--a A] [--observer t,x,y,z] (--point x,y,z | --cylindrical r,phi,z) [--windings N] [--future]"};
    add(c.options, "Goedel",
        {Option("--a", "A", "the Goedel radius a (default 1)").range(godelRadiusRange()),
         Option("--observer", "t,x,y,z", "the observer's event (default the origin)").range(kCoordinate),
         Option("--point", "x,y,z", "the point whose images are sought, in Cartesian chart coordinates")
             .range(kCoordinate)
             .excludes("--cylindrical"),
         Option("--cylindrical", "r,phi,z", "the point in cylindrical chart coordinates").range(kCoordinate),
         Option("--windings", "N", "images up to this many windings round the axis (default 2)").range(kWindings),
         Option("--future", "", "light the observer sends to the point (default: light from it)")});
    c.examples = {"lightcone images --a 1 --cylindrical 1.0,0.7,0.3 --windings 0"};
    return c;
}

CommandDeclaration diagram() {
    CommandDeclaration c{"diagram", "the r-phi diagram (or t-r spacetime diagram) of a Goedel scene", {}, {}, {}, true};
    c.usage = {"SCENE.json -o DIAGRAM.svg|.pdf|.png [-o ...] [--windings N] [--rays N] [--size PX] [--kind KIND]"};
    add(c.options, kScene,
        {Option("-o,--output", "DIAGRAM.svg", "the diagram: .svg, .pdf or .png; may be repeated (default diagram.svg)")
             .repeatable(),
         Option("--kind", "KIND", "r-phi: the observer's plane; t-r: the spacetime diagram (default r-phi)")
             .choices({"r-phi", "t-r"}),
         Option("--windings", "N", "light paths up to this many windings (default: the scene's)")
             .range(kDiagramWindings),
         Option("--rays", "N", "rays per fan or cone (default 24)").range(kRays),
         Option("--size", "PX", "image height (default 900)").range(kDiagramSize)});
    c.examples = {"xvfb-run -a lightcone diagram data/default.json -o rphi.svg -o rphi.png"};
    return c;
}

CommandDeclaration figure() {
    CommandDeclaration c{"figure",
                         "a render as a figure for a paper: the image on angular axes in degrees, a colour bar for "
                         "the quantity shown and a caption with the scene's parameters",
                         {},
                         {},
                         {},
                         true};
    c.usage = {"SCENE.json -o FIGURE.svg|.pdf|.png [-o ...] [--quantity Q] [--size PX]"};
    add(c.options, kScene,
        {Option("-o,--output", "FIGURE.pdf", "the figure: .svg, .pdf or .png; may be repeated (default figure.pdf)")
             .repeatable(),
         Option("--quantity", "Q",
                "what the colours show: image (the render), redshift (g = nu_observed / nu_emitted, with a "
                "colour bar) or emission-time (coordinate time of emission, with a colour bar); default image")
             .choices({"image", "redshift", "emission-time"}),
         Option("--size", "PX", "the figure's height in pixels (default 700)").range(kDiagramSize)});
    c.examples = {"xvfb-run -a lightcone figure data/default.json -o times.pdf -o times.png --quantity emission-time"};
    return c;
}

CommandDeclaration exportFiles() {
    CommandDeclaration c{
        "export", "the scene's geometry, light paths and horizon as VTK files for ParaView", {}, {}, {}, true};
    c.usage = {"SCENE.json -o DIR [--rays N] [--max-size MB]"};
    add(c.options, kScene,
        {Option("-o,--output", "DIR", "the folder written into (default lightcone-export)"),
         Option("--rays", "N", "rays per fan or cone (default 24)").range(kRays),
         Option("--max-size", "MB",
                "refuse an export larger than this, estimated before the light paths are traced and "
                "counted as files are made, writing nothing (default 500; 0: no limit)")
             .range(kExportMegabytes),
         Option("--quiet", "", "no progress bar")});
    c.examples = {"lightcone export data/default.json -o export"};
    return c;
}

CommandDeclaration shade() {
    CommandDeclaration c{"shade", "a new image from stored per-pixel data (render --data), without tracing", {}, {}, {},
                         false};
    c.usage = {"SCENE.json DATA.exr -o IMAGE.png [OPTIONS]"};
    add(c.options, kScene,
        {Option("-o,--output", "IMAGE.png", "the image, or a frame pattern with --sweep (default shaded.png)")});
    add(c.options, "Textures",
        {Option("--texture", "[OBJECT=]TEXTURE", "another texture for every object or one (index or name)")
             .repeatable(),
         Option("--outside-texture", "TEXTURE", "the texture of light emitted outside --time-window")
             .needs("--time-window"),
         Option("--uv-offset", "du,dv", "shift the textures, in texture periods").range(kUvOffset),
         Option("--uv-scale", "su,sv", "repeat the textures (negative mirrors)").range(kUvScale)});
    add(c.options, "Light",
        {Option("--time-window", "t0,t1", "only light emitted between these coordinate times").range(kCoordinate),
         Option("--temperature", "K", "the objects' black-body temperature").range(kTemperature),
         Option("--blink", "P,DUTY,PHASE,OFF", "objects blink with period P, on for DUTY of it, OFF brightness off")});
    add(c.options, "Frames",
        {Option("--sweep", "FIELD=FROM:TO:FRAMES",
                "frames of one setting: temperature, u-offset, v-offset, time-window (moves t0) or blink-phase")});
    add(c.options, "Lensing",
        {Option("--show", "QUANTITY",
                "the data's lensing channels (render --magnification) as a picture instead of the light: "
                "magnification (log10 |mu| from 0.1 to 100, mirrored images blue), shear (0 to 1) or rotation "
                "(-10 to +10 degrees)")
             .choices({"magnification", "shear", "rotation"})
             .excludes("--sweep")});
    c.examples = {"lightcone render data/default.json -o default.png --data default.exr  # the pixel data, once",
                  "lightcone shade data/default.json default.exr -o hot.png --temperature 12000",
                  "lightcone shade data/default.json default.exr -o window/%03d.png --time-window -2,0 --sweep "
                  "time-window=-6:0:30",
                  "lightcone shade data/kerr.json kerr.exr -o magnification.png --show magnification  # render "
                  "--magnification"};
    return c;
}

CommandDeclaration curvature() {
    CommandDeclaration c{"curvature",
                         "curvature, the matter it implies and tides: at an event, on a grid (.vti) or along the "
                         "observer's world line",
                         {},
                         {},
                         {},
                         true};
    c.usage = {"(SCENE.json | --metric NAME | --metric-file METRIC.json) [--param K=V]... --at t,x,y,z",
               "(SCENE.json | --metric NAME | --metric-file METRIC.json) -o FIELD.vti [--bounds ...] [--dims ...] "
               "[--quantity NAME]... [--image SLICE.png]",
               "SCENE.json --tides TIDES.csv [--object NAME] [--plot TIDES.svg] [--proper-time TAU] [--samples N]"};
    add(c.options, "Spacetime",
        {Option("--metric", "NAME", "a built-in metric instead of a scene's (default schwarzschild)")
             .choices(metricNames())
             .excludes("--metric-file"),
         Option("--metric-file", "METRIC.json", "a metric written as formulas (docs/METRICS.md)"),
         Option("--param", "K=V", "a parameter of the metric (lightcone ranges lists them)").repeatable(),
         Option("--lambda", "L", "the cosmological constant in G = 8 pi T + L g (default 0)")
             .range(kCosmologicalConstant),
         Option("--observers", "FIELD",
                "who measures matter and tides: static (along d/dt), normal (to t = const) or auto "
                "(static where it can be, the default)")
             .choices({"auto", "static", "normal"})});
    add(c.options, "At an event",
        {Option("--at", "t,x,y,z", "print every tensor and reading at this event as JSON").range(kCoordinate)});
    add(c.options, "On a grid",
        {Option("-o,--output", "FIELD.vti", "the grid's values as VTK image data (ParaView opens it)"),
         Option("--bounds", "x0,x1,y0,y1,z0,z1", "the box of chart coordinates (default -10,10,-10,10,0,0)")
             .range(kCoordinate),
         Option("--dims", "nx,ny,nz", "points per axis (default 101,101,1: a slice)").range(kGridSide),
         Option("--time", "T", "the chart time of the grid (default 0)").range(kCoordinate),
         Option("--quantity", "NAME", "a quantity sampled (default kretschmann; docs/CURVATURE.md lists them)")
             .repeatable()
             .choices([] {
                 std::vector<std::string> names;
                 for (const auto& q : curvatureQuantities()) names.emplace_back(q.name);
                 return names;
             }()),
         Option("--image", "SLICE.png", "a slice of the grid (one axis of one point) drawn with a colour bar"),
         Option("--log", "", "the image colours log10 of the magnitude (curvature spans decades)").needs("--image"),
         Option("--quiet", "", "no progress bar")});
    add(c.options, "Along the observer",
        {Option("--tides", "TIDES.csv", "the tidal eigenvalues and invariants along the scene's observer world line"),
         Option("--plot", "TIDES.svg", "the same as an SVG plot").needs("--tides"),
         Option("--object", "NAME",
                "an object's world line by proper time (world-line segments) instead of the observer's")
             .needs("--tides"),
         Option("--proper-time", "TAU",
                "how far along the world line (default 10, an object's whole line; negative: the past)")
             .range(kCoordinate)
             .needs("--tides"),
         Option("--samples", "N", "points along it (default 200)").range(kTideSamples).needs("--tides")});
    c.examples = {"lightcone curvature --metric kerr --param a=0.9 --at 0,3,1,0.5",
                  "xvfb-run -a lightcone curvature --metric alcubierre --quantity energy_density --observers normal "
                  "--bounds -3,3,-3,3,0,0 --dims 201,201,1 -o warp_energy.vti --image warp_energy.png",
                  "lightcone curvature data/schwarzschild_infall.json --tides tides.csv --plot tides.svg"};
    return c;
}

CommandDeclaration ranges() {
    CommandDeclaration c{"ranges", "the accepted range of every number, as docs/SCENES.md lists them", {}, {}, {},
                         false};
    c.usage = {""};
    return c;
}

CommandDeclaration completion() {
    CommandDeclaration c{"completion", "a bash completion script: source <(lightcone completion bash)", {}, {}, {},
                         false};
    c.usage = {"bash"};
    return c;
}

CommandDeclaration help() {
    CommandDeclaration c{"help", "every command, or one command's options (also COMMAND --help)", {}, {}, {}, false};
    c.usage = {"[COMMAND]", "--markdown", "--man DIR"};
    add(c.options, "Help",
        {Option("--markdown", "", "every command's help as Markdown (docs/CLI.md)"),
         Option("--man", "DIR", "a man page per command (lightcone-COMMAND.1) and lightcone.1 written into DIR")});
    return c;
}

}  // namespace

std::string OptionDeclaration::longName() const {
    const auto comma = names.rfind(',');
    return comma == std::string::npos ? names : names.substr(comma + 1);
}

const OptionDeclaration* CommandDeclaration::option(const std::string& optionName) const {
    for (const OptionDeclaration& o : options) {
        std::size_t start = 0;
        for (;;) {
            const auto comma = o.names.find(',', start);
            if (o.names.substr(start, comma == std::string::npos ? std::string::npos : comma - start) == optionName)
                return &o;
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    }
    return nullptr;
}

const std::vector<CommandDeclaration>& commandDeclarations() {
    static const std::vector<CommandDeclaration> commands = [] {
        std::vector<CommandDeclaration> all{render(),    animate(), sweep(),      trace(),       metric(),
                                            images(),    diagram(), figure(),     exportFiles(), shade(),
                                            curvature(), ranges(),  completion(), help()};
#ifndef LIGHTCONE_WITH_VTK
        std::vector<CommandDeclaration> built;
        for (auto& c : all)
            if (!c.needsVtk) built.push_back(std::move(c));
        all = std::move(built);
#endif
        return all;
    }();
    return commands;
}

const CommandDeclaration* findCommand(const std::string& name) {
    for (const CommandDeclaration& c : commandDeclarations())
        if (c.name == name) return &c;
    return nullptr;
}

}  // namespace lc::cli
