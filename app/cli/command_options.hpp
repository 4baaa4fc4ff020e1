// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What each command takes from its command line, parsed and range-checked before any file is
// read or any work starts: a bad value stops the command in milliseconds with the option's
// name and accepted range. No I/O happens here (the CLI fuzzer drives these functions).
#include "app/cli/cli_args.hpp"
#include "app/commands/frame_sequence.hpp"
#include "core/spacetime/integrator.hpp"
#include "core/scene/scene.hpp"

#include "core/render/lensing_image.hpp"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lc::cli {

struct RenderOptions {
    std::string scene, session, output = "lightcone.png", data;  // scene or session (a GUI session file)
    std::optional<int> width, height, windings, threads;
    std::optional<std::string> stepper;  // "auto" or a stepper name (parsed by setSceneStepper)
    std::optional<double> tolerance, maxAffine, escapeRadius, escapeAngle;
    std::optional<Vec3> lookAt;  // --look-at x,y,z: forward towards this spatial chart position
    std::optional<RenderSettings::Method> method;
    bool polygonDistortion = false, quiet = false, gpu = false, magnification = false;
    int orbitFrames = 36;
    std::vector<std::string> spectrum;  // --spectrum OUT.csv|OUT.svg (render; scenes with a disk)
    int tileRows = 0;                   // rows per band when distributed over MPI ranks (0: automatic)
    bool staticSchedule = false;        // --schedule static: task k on rank k % ranks (to measure imbalance)
    // The command line wins over the scene file; the result is validated again (camera).
    void applyTo(Scene& target) const;
};

struct AnimateOptions {
    RenderOptions render;                           // the scene and its overrides, as render takes them
    FramePattern output, data;                      // frame-file patterns (data: per-pixel EXR per frame)
    AnimationPath path;                             // from the command line; the scene's "animation" block otherwise
    std::optional<std::pair<int, int>> frameRange;  // --frames FIRST-LAST (job arrays)
    bool resume = false;                            // skip frames whose files exist
    std::string movie;                              // --movie out.mp4 (ffmpeg)
    int fps = 24;
};

struct SweepOptions {
    RenderOptions render;  // the scene and its overrides (--windings, --tolerance, ...)
    FieldSweep sweep;
    std::string table, plot;          // CSV; optional SVG
    std::string outline, outlineVtk;  // the shadow's outlines: CSV, VTK polylines
    int outlinePoints = 360;
    std::optional<Vec3> pointSource;  // --point-source: a source at infinity in this chart direction
};

struct TraceCommandOptions {
    std::string metric = "schwarzschild";
    std::string metricFile;  // --metric-file: a metric written as formulas, instead of --metric
    std::map<std::string, double> parameters;
    std::optional<double> impact;
    double distance = 1e6;
    Vec4 event = Vec4::Zero();
    Vec3 direction = Vec3::UnitX();
    bool future = false;
    // --observer: a named observer (core/spacetime/named_observer.hpp) or, when velocity is set,
    // the 4-velocity given.
    std::string observer = "static";
    std::optional<Vec4> observerVelocity;
    TraceOptions trace;
    // --source-plane X,Y,Z,NX,NY,NZ: the ray's Jacobi map and magnification where it meets that plane.
    std::optional<std::array<double, 6>> sourcePlane;
};

struct MetricCheckOptions {
    bool list = false;                         // `metric list`: every metric file found, and the built-ins
    bool show = false;                         // `metric show NAME`: one file described, a scene to start from
    std::string file;                          // a metric written as formulas (docs/METRICS.md)
    std::map<std::string, double> parameters;  // --param K=V
    Vec4 at = Vec4(0, 10, 1, 2);               // --at: where g is printed and checked
};

struct ImagesOptions {
    double a = 1;
    Vec4 observer = Vec4::Zero();
    Vec3 point = Vec3::Zero();
    int windings = 2;
    bool future = false;
};

struct ExportOptions {
    std::string scene, directory = "lightcone-export";
    int rays = 24;
    double maxMegabytes = 500;  // 0: no limit
    bool quiet = false;
};

// Which diagram `lightcone diagram --kind` draws (views/diagrams/vtkLightconeRPhiDiagram, vtkLightconeTRDiagram).
enum class DiagramKind { RPhi, TR };

struct DiagramOptions {
    std::string scene;
    std::vector<std::string> outputs;
    std::optional<int> windings;
    int rays = 24, size = 900;
    DiagramKind kind = DiagramKind::RPhi;
};

struct FigureOptions {
    std::string scene;
    std::vector<std::string> outputs;
    std::string quantity = "image";
    int size = 700;
};

// The post-rendering settings of `lightcone shade` (core/render/post_render.hpp), textures still
// named (they are loaded once the scene's folder is known).
struct ShadeOptions {
    std::string scene, data, output = "shaded.png";
    std::vector<std::pair<std::string, std::string>> textures;  // (object index or name, "" = all; texture name)
    std::string outsideTexture;                                 // shown outside the time window
    double uOffset = 0, vOffset = 0, uScale = 1, vScale = 1;
    std::optional<std::pair<double, double>> timeWindow;
    std::optional<double> temperature;
    std::optional<std::array<double, 4>> blink;  // period, duty, phase, off level
    // --sweep temperature|u-offset|v-offset|time-window|blink-phase=FROM:TO:FRAMES; -o is then a
    // frame pattern ("frames/t_%03d.png"). A time-window sweep moves t0 and keeps the width.
    std::optional<FieldSweep> sweep;
    FramePattern frames;
    // --show magnification|shear|rotation: the lensing channels as a picture instead of the light.
    std::optional<LensingQuantity> show;
    std::string showName;
};

// `lightcone curvature`: the curvature, matter and tides of a metric (core/curvature) at an event,
// on a grid (.vti) or along a scene's observer world line.
struct CurvatureOptions {
    std::string scene;  // its metric and observer; else the metric options below
    std::string metric = "schwarzschild", metricFile;
    std::map<std::string, double> parameters;
    std::optional<Vec4> at;                                // --at: everything at one event, as JSON
    std::string output;                                    // -o FILE.vti: the grid
    std::string image;                                     // --image FILE.png: a slice of the grid, drawn
    bool logScale = false;                                 // --log: the image colours log10 |value|
    std::array<double, 6> bounds{-10, 10, -10, 10, 0, 0};  // x0,x1,y0,y1,z0,z1
    std::array<int, 3> dims{101, 101, 1};
    double time = 0;
    std::vector<std::string> quantities;  // default kretschmann
    double lambda = 0;
    std::string observers = "auto";
    std::string tides, plot;  // --tides FILE.csv [--plot FILE.svg]: along the scene's observer
    std::string object;       // --object NAME: its world line instead of the observer's
    double properTime = 10;
    bool properTimeGiven = false;
    int samples = 200;
    bool quiet = false;
};

// argv: the arguments after the command name. Throw std::invalid_argument naming the option.
RenderOptions parseRenderOptions(const std::vector<std::string>& argv);
AnimateOptions parseAnimateOptions(const std::vector<std::string>& argv);
SweepOptions parseSweepOptions(const std::vector<std::string>& argv);
TraceCommandOptions parseTraceOptions(const std::vector<std::string>& argv);
// The metric trace names: built in (--metric) or written as formulas (--metric-file).
SpacetimePtr traceSpacetime(const TraceCommandOptions& o);
// `metric check FILE [--at t,x,y,z] [--param K=V]...`
MetricCheckOptions parseMetricCheckOptions(const std::vector<std::string>& argv);
ImagesOptions parseImagesOptions(const std::vector<std::string>& argv);
ExportOptions parseExportOptions(const std::vector<std::string>& argv);
DiagramOptions parseDiagramOptions(const std::vector<std::string>& argv);
ShadeOptions parseShadeOptions(const std::vector<std::string>& argv);
FigureOptions parseFigureOptions(const std::vector<std::string>& argv);
CurvatureOptions parseCurvatureOptions(const std::vector<std::string>& argv);
// The metric `curvature` reads: the scene's, a formula file's or a built-in's.
SpacetimePtr curvatureSpacetime(const CurvatureOptions& o);

// argv[0] is the command: parses its options as the command would, without running it.
void parseCommandLine(const std::vector<std::string>& argv);

}  // namespace lc::cli
