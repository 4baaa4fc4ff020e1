// SPDX-License-Identifier: BSD-3-Clause
// `lightcone curvature`: the curvature of a metric, the matter Einstein's equations make of it and
// the tides an observer feels (core/curvature): every tensor at one event as JSON, any quantity
// on a grid as VTK image data (vtkLightconeCurvatureSource), or the tides along a scene's
// observer world line as CSV and SVG.
#include "app/cli/progress_bar.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/svg_plot.hpp"
#include "app/commands/vtk_xml_bytes.hpp"
#include "core/curvature/curvature_field.hpp"
#include "core/godel/proper_time_world_line.hpp"
#include "core/scene/observer_world_line.hpp"
#include "curvature_slice_image.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/json_document.hpp"
#include "vtkLightconeCurvatureSource.h"

#include <json/json.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkXMLImageDataWriter.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace lc::cli {
namespace {

Json::Value jsonMatrix(const Eigen::MatrixXd& m) {
    Json::Value rows(Json::arrayValue);
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
        Json::Value row(Json::arrayValue);
        for (Eigen::Index j = 0; j < m.cols(); ++j) row.append(m(i, j));
        rows.append(row);
    }
    return rows;
}

Json::Value jsonVector(const Eigen::VectorXd& v) {
    Json::Value a(Json::arrayValue);
    for (Eigen::Index i = 0; i < v.size(); ++i) a.append(v(i));
    return a;
}

Json::Value jsonCondition(const EnergyCondition& c) {
    Json::Value v;
    v["holds"] = c.holds;
    v["violation"] = c.violation;
    return v;
}

ObserverField observerField(const CurvatureOptions& o) { return *observerFieldNamed(o.observers); }

// Everything at one event; throws where the metric is singular.
Json::Value readingAt(const Spacetime& st, const Vec4& x, const CurvatureOptions& o) {
    const CurvatureAt c = CurvatureProbe(st).at(x);
    if (!c.g.allFinite() || !std::isfinite(c.kretschmann))
        throw std::invalid_argument("option --at: the metric or its curvature is not finite there (a singularity?)");
    Json::Value out;
    out["metric"] = st.name();
    for (const auto& [k, v] : st.parameters()) out["parameters"][k] = v;
    out["coordinates"] = Json::Value(Json::arrayValue);
    for (const auto& name : st.coordinateNames()) out["coordinates"].append(name);
    out["event"] = io::jsonArray(x);
    out["conventions"] =
        "signature (+,-,-,-); Riemann and Ricci as MTW (R_bd = R^a_bad); G = 8 pi T + lambda g; tidal tensor "
        "E_ij = R_(i)(0)(j)(0) in MTW's sign (docs/PHYSICS.md section 13)";
    out["g"] = jsonMatrix(c.g);
    out["kretschmann"] = c.kretschmann;
    out["ricci_scalar"] = c.ricciScalar;
    out["ricci_squared"] = c.ricciSquared;
    out["weyl_squared"] = c.weylSquared;
    out["ricci"] = jsonMatrix(c.ricci);
    out["einstein"] = jsonMatrix(c.einstein);
    out["lambda"] = o.lambda;
    out["stress_energy"] = jsonMatrix(stressEnergyTensor(c, o.lambda));
    const auto frame = observerFrameAt(c.g, c.gInverse, x, observerField(o));
    Json::Value& seen = out["observer"];
    seen["field"] = o.observers;
    if (!frame) {
        seen["none"] =
            "no observer of this field here (static observers need d/dt timelike, normal ones t = const "
            "spacelike)";
        return out;
    }
    seen["velocity"] = io::jsonArray(frame->e[0]);
    const Mat4 T = inFrame(stressEnergyTensor(c, o.lambda), *frame);
    const MatterSeen m = matterSeenBy(T);
    seen["energy_density"] = m.energyDensity;
    seen["energy_flux"] = jsonVector(m.energyFlux);
    seen["stress"] = jsonMatrix(m.stress);
    seen["principal_pressures"] = jsonVector(m.principalPressures);
    seen["tidal_tensor"] = jsonMatrix(tidalTensor(c, *frame));
    seen["tidal_eigenvalues"] = jsonVector(tidalEigenvalues(c, *frame));
    const MatterClass k = classifyMatter(T);
    Json::Value& matter = out["matter"];
    matter["hawking_ellis_type"] = hawkingEllisName(k.type);
    if (k.type == HawkingEllisType::I) {
        matter["rest_density"] = k.restDensity;
        matter["rest_pressures"] = jsonVector(k.restPressures);
    }
    matter["null_energy_condition"] = jsonCondition(k.nullEnergy);
    matter["weak_energy_condition"] = jsonCondition(k.weak);
    matter["strong_energy_condition"] = jsonCondition(k.strong);
    matter["dominant_energy_condition"] = jsonCondition(k.dominant);
    matter["conditions_from"] = k.sampled ? "sampled directions (types II-IV)" : "the closed form of type I";
    return out;
}

void writeGrid(const SpacetimePtr& st, const CurvatureOptions& o) {
    vtkNew<vtkLightconeCurvatureSource> source;
    source->SetSpacetime(st);
    source->SetTime(o.time);
    const auto& b = o.bounds;
    source->SetOrigin(b[0], b[2], b[4]);
    double spacing[3];
    for (int axis = 0; axis < 3; ++axis) {
        const int n = o.dims[static_cast<std::size_t>(axis)];
        spacing[axis] = n > 1 ? (b[2 * axis + 1] - b[2 * axis]) / (n - 1) : 1.0;
    }
    source->SetSpacing(spacing);
    source->SetDimensions(o.dims[0], o.dims[1], o.dims[2]);
    for (const std::string& q : o.quantities) source->AddQuantity(q.c_str());
    source->SetCosmologicalConstant(o.lambda);
    source->SetObserverField(o.observers == "static"   ? vtkLightconeCurvatureSource::STATIC
                             : o.observers == "normal" ? vtkLightconeCurvatureSource::NORMAL
                                                       : vtkLightconeCurvatureSource::AUTO);
    // The source's errors and progress, to the command line's own reporting.
    struct Reports {
        std::string error;
        ProgressBar bar;
    } reports{"", ProgressBar(!o.quiet, "curvature ")};
    vtkNew<vtkCallbackCommand> onEvent;
    onEvent->SetClientData(&reports);
    onEvent->SetCallback([](vtkObject*, unsigned long event, void* client, void* data) {
        auto* r = static_cast<Reports*>(client);
        if (event == vtkCommand::ErrorEvent && data) r->error = static_cast<const char*>(data);
        if (event == vtkCommand::ProgressEvent && data) r->bar(*static_cast<double*>(data));
    });
    source->AddObserver(vtkCommand::ErrorEvent, onEvent);
    source->AddObserver(vtkCommand::ProgressEvent, onEvent);
    source->Update();
    if (!reports.error.empty()) {
        const auto colon = reports.error.rfind(": ");
        throw std::invalid_argument("curvature grid: " +
                                    (colon == std::string::npos ? reports.error : reports.error.substr(colon + 2)));
    }
    vtkImageData* image = source->GetOutput();
    // Both outputs committed together: a refused image leaves no .vti behind, and the reverse.
    io::OutputSet outputs;
    if (!o.output.empty()) {
        vtkNew<vtkXMLImageDataWriter> writer;
        outputs.add(o.output, vtkXmlBytes(writer, image, o.output), "-o");
    }
    if (!o.image.empty()) {
        views::CurvatureSliceStyle style;
        style.logMagnitude = o.logScale;
        std::ostringstream caption;
        caption << st->name();
        for (const auto& [k, v] : st->parameters()) caption << " " << k << " = " << v;
        caption << ", t = " << o.time;
        style.caption = caption.str();
        const std::string array = o.quantities.empty() ? "kretschmann" : o.quantities.front();
        const std::vector<unsigned char> rgb = views::curvatureSliceImage(image, array, style);
        io::ImageChannels picture;
        picture.width = style.width;
        picture.height = style.height;
        picture.names = {"R", "G", "B"};
        for (unsigned char c : rgb) picture.data.push_back(io::srgbDecode(c / 255.0f));
        outputs.add(o.image, io::encodeImage(o.image, picture), "--image");
    }
    outputs.commit();
    auto count = [image](const char* name) { return image->GetFieldData()->GetArray(name)->GetTuple1(0); };
    std::cout << "wrote "
              << (o.output.empty()  ? o.image
                  : o.image.empty() ? o.output
                                    : o.output + " and " + o.image)
              << ": " << o.dims[0] << " x " << o.dims[1] << " x " << o.dims[2] << " points of " << st->name();
    for (int i = 0; i < source->GetNumberOfQuantities(); ++i) std::cout << (i ? ", " : " (") << source->GetQuantity(i);
    std::cout << (source->GetNumberOfQuantities() ? ")" : " (kretschmann)") << "; " << count("singular_points")
              << " singular points, " << count("points_without_observer") << " without a " << o.observers
              << " observer (NaN there)\n";
}

// Events along a world line by proper time, with the 4-velocity there.
struct WorldLineSample {
    double tau;
    Vec4 x, u;
};

// The scene's observer world line at `samples` proper times from 0 to `properTime`, as far as it
// goes: where it ends (a horizon, a singularity) the samples stop, and `endsBecause` says why.
std::vector<WorldLineSample> observerSamples(const Scene& scene, const CurvatureOptions& o, std::string& endsBecause) {
    std::vector<double> taus;
    for (int i = 0; i < o.samples; ++i) taus.push_back(o.properTime * i / (o.samples - 1));
    const ObserverMotion motion = defaultObserverMotion(scene.observerVelocity);
    auto line = [&](const std::vector<double>& t) {
        return observerWorldLine(*scene.spacetime, scene.observer, scene.observerVelocity, motion, t,
                                 scene.settings.trace);
    };
    std::vector<ObserverEvent> events;
    try {
        events = line(taus);
    } catch (const std::invalid_argument& e) {
        // The longest prefix of the samples that the world line reaches, by bisection.
        endsBecause = e.what();
        std::size_t good = 1, bad = taus.size();
        while (bad - good > 1) {
            const std::size_t mid = (good + bad) / 2;
            try {
                (void)line(std::vector<double>(taus.begin(), taus.begin() + static_cast<long>(mid)));
                good = mid;
            } catch (const std::invalid_argument&) {
                bad = mid;
            }
        }
        taus.resize(good);
        events = line(taus);
    }
    std::vector<WorldLineSample> samples;
    for (std::size_t i = 0; i < events.size(); ++i)
        samples.push_back({taus[i], events[i].position, events[i].velocity});
    return samples;
}

// An object's world line by proper time (segments: the time traveller), from 0 to its end or to
// --proper-time.
std::vector<WorldLineSample> objectSamples(const Scene& scene, const CurvatureOptions& o) {
    const Motion* motion = nullptr;
    for (const auto& s : scene.spheres)
        if (s.name == o.object) motion = &s.motion;
    for (const auto& m : scene.meshes)
        if (m.name == o.object) motion = &m.motion;
    if (!motion) throw std::invalid_argument("option --object: the scene has no object named '" + o.object + "'");
    if (motion->kind != Motion::Kind::ProperTime || !motion->properTimeLine)
        throw std::invalid_argument("option --object: '" + o.object +
                                    "' has no world line by proper time (motion segments); at rest, falling or on "
                                    "listed events it is not followed yet");
    const godel::ProperTimeWorldLine& line = *motion->properTimeLine;
    const double end = o.properTimeGiven ? std::min(std::abs(o.properTime), line.duration()) : line.duration();
    std::vector<WorldLineSample> samples;
    for (int i = 0; i < o.samples; ++i) {
        const double tau = end * i / (o.samples - 1);
        samples.push_back({tau, line.position(tau), line.velocity(tau)});
    }
    return samples;
}

// The tides (and the Kretschmann scalar) along the scene's observer or an object, as CSV and SVG.
void writeTides(const Scene& scene, const CurvatureOptions& o) {
    std::string endsBecause;
    const std::vector<WorldLineSample> line =
        o.object.empty() ? observerSamples(scene, o, endsBecause) : objectSamples(scene, o);
    const CurvatureProbe probe(*scene.spacetime);
    std::ostringstream csv;
    csv << std::setprecision(12) << "tau,t,x1,x2,x3,u_t,u_1,u_2,u_3,tidal_1,tidal_2,tidal_3,kretschmann\n";
    std::vector<PlotColumn> columns{{"tidal eigenvalue 1 (stretch < 0)", {}},
                                    {"tidal eigenvalue 2", {}},
                                    {"tidal eigenvalue 3", {}},
                                    {"Kretschmann R_abcd R^abcd", {}}};
    std::vector<double> taus;
    for (const WorldLineSample& s : line) {
        const CurvatureAt c = probe.at(s.x);
        const auto frame = LocalFrame::fromMetric(c.g, s.x, s.u);
        if (!frame)
            throw std::runtime_error("the world line is not timelike at tau = " + std::to_string(s.tau) +
                                     " (its 4-velocity there is not a velocity)");
        const Vec3 tides = tidalEigenvalues(c, *frame);
        csv << s.tau;
        for (int k = 0; k < 4; ++k) csv << "," << s.x(k);
        for (int k = 0; k < 4; ++k) csv << "," << frame->e[0](k);
        csv << "," << tides(0) << "," << tides(1) << "," << tides(2) << "," << c.kretschmann << "\n";
        for (int k = 0; k < 3; ++k) columns[static_cast<std::size_t>(k)].values.push_back(tides(k));
        columns[3].values.push_back(c.kretschmann);
        taus.push_back(s.tau);
    }
    io::OutputSet outputs;  // the table and its plot together
    outputs.add(o.tides, csv.str(), "--tides");
    if (!o.plot.empty()) outputs.add(o.plot, svgPlots("proper time tau", taus, columns), "--plot");
    outputs.commit();
    std::cout << "wrote " << o.tides << (o.plot.empty() ? "" : " and " + o.plot) << ": " << line.size()
              << " events along "
              << (o.object.empty()
                      ? "the " + observerMotionName(defaultObserverMotion(scene.observerVelocity)) + " observer"
                      : "'" + o.object + "'")
              << ", tau from 0 to " << taus.back();
    if (!endsBecause.empty()) std::cout << " (the world line ends there: " << endsBecause << ")";
    std::cout << "\n";
}

}  // namespace

int runCurvature(const std::vector<std::string>& argv) {
    const CurvatureOptions o = parseCurvatureOptions(argv);
    if (!o.output.empty()) io::checkOutputPath(o.output, {".vti"}, "-o");
    if (!o.image.empty()) io::checkOutputPath(o.image, io::imageExtensions(), "--image");
    // The slice's shape and its picture's display, before the grid is computed: the picture is
    // drawn by VTK through GLX, and without an X server VTK aborts the process.
    if (!o.image.empty()) views::sliceAxis(o.dims.data());
    if (!o.image.empty() && !std::getenv("DISPLAY"))
        throw std::runtime_error(
            "--image is drawn by VTK through GLX and needs an X display (hint: run under "
            "xvfb-run -a, or leave out --image: the .vti alone needs none)");
    if (!o.tides.empty()) io::checkOutputPath(o.tides, {".csv"}, "--tides");
    if (!o.plot.empty()) io::checkOutputPath(o.plot, {".svg"}, "--plot");
    Scene scene;
    SpacetimePtr st;
    if (!o.scene.empty()) {
        scene = io::readScene(o.scene, sceneReadOptions());
        st = scene.spacetime;
    } else {
        st = curvatureSpacetime(o);
    }
    if (o.at) {
        Json::StreamWriterBuilder w;
        w["indentation"] = "  ";
        w["precision"] = 17;
        std::cout << Json::writeString(w, readingAt(*st, *o.at, o)) << "\n";
    }
    if (!o.output.empty() || !o.image.empty()) writeGrid(st, o);
    if (!o.tides.empty()) writeTides(scene, o);
    return 0;
}

}  // namespace lc::cli
