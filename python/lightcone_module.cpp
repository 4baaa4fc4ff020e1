// SPDX-License-Identifier: BSD-3-Clause
// lightcone._core: the physics core for Python (pybind11). Scenes are read by the same reader as
// the command line (file or dict, with edits: the same file:line:field errors), rendered by the
// same renderers into numpy arrays (the colour and the per-pixel record), saved to the same bytes
// as `lightcone render`; rays, the Goedel inverse problem, shadows and a disk's observables. Work
// runs with the GIL released; a progress callback may stop a render by raising.
#include "app/commands/commands.hpp"
#include "app/commands/render_report.hpp"
#include "core/analysis/disk_observables.hpp"
#include "core/analysis/shadow.hpp"
#include "core/input/ranges.hpp"
#include "core/spacetime/named_observer.hpp"
#include "core/godel/images.hpp"
#include "core/metrics/factory.hpp"
#include "core/render/render.hpp"
#include "core/render/special_relativity.hpp"
#include "core/scene/observer_ray.hpp"
#include "readers/io/metric_file.hpp"
#include "readers/io/provenance.hpp"
#include "readers/io/scene_edits.hpp"
#include "core/spacetime/metric_check.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <optional>

namespace py = pybind11;
using namespace lc;

namespace {

// A Python value (dict, list, number, string) as the JSON value the scene reader takes.
Json::Value toJson(const py::handle& value) {
    const std::string text = py::module_::import("json").attr("dumps")(value).cast<std::string>();
    Json::CharReaderBuilder builder;
    std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
    Json::Value v;
    std::string errors;
    if (!reader->parse(text.data(), text.data() + text.size(), &v, &errors))
        throw std::invalid_argument("not JSON: " + errors);
    return v;
}

// A scene as the reader made it, with the document it came from (so edits re-read it once).
class PyScene {
public:
    explicit PyScene(io::EditableScene s) : editable_(std::move(s)) {}
    const Scene& scene() const { return editable_.scene(); }
    const io::EditableScene& editable() const { return editable_; }
    PyScene edited(const py::dict& edits) const {
        io::EditableScene copy = editable_;
        std::vector<io::SceneEdit> list;
        for (const auto& [field, value] : edits) list.push_back({py::str(field).cast<std::string>(), toJson(value)});
        if (!list.empty()) copy.apply(list);
        return PyScene(std::move(copy));
    }
    py::object document() const {
        Json::StreamWriterBuilder w;
        w["indentation"] = "";
        return py::module_::import("json").attr("loads")(Json::writeString(w, editable_.document()));
    }

private:
    io::EditableScene editable_;
};

PyScene readScene(const py::object& source, const py::dict& edits) {
    const cli::RenderOptions none;
    if (py::isinstance<py::dict>(source)) {
        const Json::Value doc = toJson(source);
        const std::string cwd = std::filesystem::current_path().string();
        return PyScene(io::EditableScene::fromDocument(doc, "<dict>", cwd, cli::sceneReadOptions())).edited(edits);
    }
    const std::string path = py::str(source).cast<std::string>();
    return PyScene(io::EditableScene::load(path, cli::sceneReadOptions())).edited(edits);
}

template <class T>
py::array_t<T> grid(const RenderResult& r) {
    return py::array_t<T>({r.height, r.width});
}

// A finished render: numpy arrays of the colour and of every field of the per-pixel record.
class PyRender {
public:
    PyRender(const Scene& scene, ColouredImage image) : scene_(scene), image_(std::move(image)) {}
    py::dict arrays() const {
        const RenderResult& r = image_.records;
        py::array_t<float> rgb({r.height, r.width, 3});
        std::copy(image_.rgb.begin(), image_.rgb.end(), rgb.mutable_data());
        auto kind = grid<std::int8_t>(r), order = grid<std::int8_t>(r), stop = grid<std::int8_t>(r),
             end = grid<std::int8_t>(r);
        auto object = grid<std::int16_t>(r);
        std::map<std::string, py::array_t<float>> f;
        for (const char* name :
             {"u", "v", "frequency_ratio", "emission_time", "affine", "drift", "steps", "disk_radius", "intensity"})
            f.emplace(name, grid<float>(r));
        for (std::size_t n = 0; n < r.pixels.size(); ++n) {
            const PixelRecord& p = r.pixels[n];
            kind.mutable_data()[n] = p.kind;
            order.mutable_data()[n] = p.order;
            end.mutable_data()[n] = p.end;
            stop.mutable_data()[n] = p.stopReason;
            object.mutable_data()[n] = p.object;
            f["u"].mutable_data()[n] = p.u;
            f["v"].mutable_data()[n] = p.v;
            f["frequency_ratio"].mutable_data()[n] = p.frequencyRatio;
            f["emission_time"].mutable_data()[n] = p.emissionTime;
            f["affine"].mutable_data()[n] = p.affine;
            f["drift"].mutable_data()[n] = p.drift;
            f["steps"].mutable_data()[n] = p.steps;
            f["disk_radius"].mutable_data()[n] = p.diskRadius;
            f["intensity"].mutable_data()[n] = p.intensity;
        }
        py::dict out;
        out["rgb"] = rgb;
        out["kind"] = kind;
        out["object"] = object;
        out["image_order"] = order;
        out["stop_reason"] = stop;
        out["end"] = end;
        for (auto& [name, array] : f) out[name.c_str()] = array;
        if (r.lensing) {
            auto mu = grid<float>(r), shear = grid<float>(r), rotation = grid<float>(r);
            for (std::size_t n = 0; n < r.pixels.size(); ++n) {
                mu.mutable_data()[n] = r.pixels[n].magnification;
                shear.mutable_data()[n] = r.pixels[n].shear;
                rotation.mutable_data()[n] = r.pixels[n].rotation;
            }
            out["magnification"] = mu;
            out["shear"] = shear;
            out["rotation"] = rotation;
        }
        return out;
    }
    py::dict stats() const {
        const RenderStats& s = image_.records.stats;
        py::dict out;
        out["seconds"] = s.seconds;
        out["worst_drift"] = s.worstDrift;
        // The escape directions' estimated error in pixels (NaN without a sampled sky ray).
        out["error_estimate_px"] = s.errorRays > 0 ? s.errorMaxPixels : std::nan("");
        out["mean_steps"] = s.meanSteps;
        out["rays"] = s.rays;
        out["object_pixels"] = s.hits;
        py::dict stops;
        for (std::size_t k = 0; k < s.stopCounts.size(); ++k)
            if (s.stopCounts[k]) stops[stopReasonName(static_cast<StopReason>(k)).c_str()] = s.stopCounts[k];
        out["stops"] = stops;
        return out;
    }
    // The files `lightcone render -o IMAGE [--data DATA]` writes for this scene, byte for byte.
    void save(const std::string& image, const std::string& data) const {
        cli::writeRenderOutputs(image_, image, data, cli::ageLabels(scene_, ageImages(scene_)),
                                cli::renderReport(scene_, image_.records).figures());
    }
    py::dict disk() const {
        if (scene_.disks.empty()) throw std::invalid_argument("the scene has no accretion disk");
        const DiskObservables d = observeDisk(scene_, image_.records);
        py::dict out;
        out["flux"] = d.flux;
        // None where no disk light reaches the image (as the command line says), not NaN.
        out["mean_redshift"] = d.flux > 0 && std::isfinite(d.meanRedshift) ? py::object(py::float_(d.meanRedshift))
                                                                           : py::object(py::none());
        out["pixels_by_order"] = std::vector<std::size_t>(d.pixels.begin(), d.pixels.end());
        out["flux_by_order"] = std::vector<double>(d.orderFlux.begin(), d.orderFlux.end());
        std::vector<double> nu, fnu;
        for (const SpectrumBin& b : diskSpectrum(scene_, image_.records)) {
            nu.push_back(b.frequencyHz);
            fnu.push_back(b.fluxDensity);
        }
        out["frequency_hz"] = py::array_t<double>(nu.size(), nu.data());
        out["flux_density"] = py::array_t<double>(fnu.size(), fnu.data());
        return out;
    }

private:
    Scene scene_;
    ColouredImage image_;
};

PyRender renderScene(const PyScene& s, const std::optional<std::string>& method, std::optional<double> tolerance,
                     std::optional<int> threads, std::optional<int> width, std::optional<int> height,
                     const py::object& progress, bool magnification) {
    // The command line's ranges (core/input/ranges), checked before any work as render checks its
    // options: a thread count of 10^5 once crashed the interpreter in the thread pool.
    if (tolerance) input::kTolerance.require(*tolerance, "render: tolerance");
    if (threads) input::kThreads.require(*threads, "render: threads");
    if (width) input::kImageSide.require(*width, "render: width");
    if (height) input::kImageSide.require(*height, "render: height");
    cli::RenderOptions o;  // the command line's overrides, applied as render applies them
    if (method) o.method = parseRenderMethod(*method);
    o.tolerance = tolerance;
    o.threads = threads;
    o.width = width;
    o.height = height;
    o.magnification = magnification;
    Scene scene = s.scene();
    o.applyTo(scene);
    scene.settings.progress = false;
    std::optional<py::error_already_set> raised;
    ProgressCallback callback;
    if (!progress.is_none())
        callback = [&](double fraction) {
            py::gil_scoped_acquire gil;
            try {
                progress(fraction);
            } catch (py::error_already_set& e) {
                raised = std::move(e);
                throw RenderCancelled();
            }
        };
    ColouredImage image;
    try {
        py::gil_scoped_release free;  // other Python threads run while the rays are traced
        image = renderColouredImage(scene, callback);
    } catch (const RenderCancelled&) {
        if (raised) throw std::move(*raised);
        throw;
    }
    return PyRender(scene, std::move(image));
}

py::dict shadow(const PyScene& s, double tolerance) {
    ShadowSize m;
    {
        py::gil_scoped_release free;
        m = measureShadow(s.scene(), tolerance);
    }
    const double distance = s.scene().observer.tail<3>().norm();
    py::dict out;
    out["centre_up_deg"] = m.centreUpDegrees;
    out["left_deg"] = m.leftDegrees;
    out["right_deg"] = m.rightDegrees;
    out["width_deg"] = m.widthDegrees();
    out["offset_deg"] = m.offsetDegrees();
    out["height_deg"] = m.heightDegrees;
    out["width_M"] = m.widthImpact(distance);
    out["left_alpha_M"] = m.leftAlpha;
    out["right_alpha_M"] = m.rightAlpha;
    out["right_edge_sense"] = m.rightEdgeSense;
    out["edge_error_deg"] = m.edgeErrorDegrees;  // every angle's estimated error
    return out;
}

// The outline as numpy arrays: camera angles and the unit directions in the camera's axes.
py::dict shadowOutline(const PyScene& s, int points, double tolerance) {
    if (!(points >= 8 && points <= 100000))
        throw py::value_error("shadow_outline: points must be an integer in [8, 100000], got " +
                              std::to_string(points));
    if (!(tolerance >= 1e-14 && tolerance <= 1e-2))
        throw py::value_error("shadow_outline: tolerance must be in [1e-14, 1e-2]");
    ShadowOutline o;
    {
        py::gil_scoped_release free;
        o = traceShadowOutline(s.scene(), points, tolerance);
    }
    const auto n = static_cast<py::ssize_t>(o.points.size());
    py::array_t<double> polar(n), azimuth(n), directions({n, py::ssize_t(3)});
    for (py::ssize_t k = 0; k < n; ++k) {
        const Vec3& d = o.points[std::size_t(k)];
        polar.mutable_at(k) = o.polarDegrees(std::size_t(k));
        azimuth.mutable_at(k) = o.azimuthDegrees(std::size_t(k));
        directions.mutable_at(k, 0) = d.dot(o.right);
        directions.mutable_at(k, 1) = d.dot(o.up);
        directions.mutable_at(k, 2) = d.dot(o.forward);
    }
    py::dict out;
    out["polar_deg"] = polar;
    out["azimuth_deg"] = azimuth;
    out["directions"] = directions;
    out["solid_angle_sr"] = o.solidAngle;
    out["centroid"] = py::make_tuple(o.centroid.dot(o.right), o.centroid.dot(o.up), o.centroid.dot(o.forward));
    out["from_sky"] = o.fromSky;
    return out;
}

// A metric written as formulas (docs/METRICS.md), read from its JSON text as a metric file is.
struct PyMetric {
    std::shared_ptr<const formula::FormulaMetric> metric;
    std::string text;  // the formula's JSON, for scenes that name it inline

    static PyMetric fromText(const std::string& text, const std::map<std::string, double>& parameters) {
        return {io::parseFormulaMetric(text, "<formula>", parameters), text};
    }
    static Vec4 event(const std::array<double, 4>& x) { return Vec4(x[0], x[1], x[2], x[3]); }
    py::array_t<double> g(const std::array<double, 4>& x) const {
        const Mat4 m = metric->metric(event(x));
        py::array_t<double> out({4, 4});
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b) out.mutable_at(a, b) = m(a, b);
        return out;
    }
    py::array_t<double> derivatives(const std::array<double, 4>& x) const {
        Mat4 m;
        std::array<Mat4, 4> dg;
        metric->metricAndDerivatives(event(x), m, dg);
        py::array_t<double> out({4, 4, 4});
        for (int k = 0; k < 4; ++k)
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < 4; ++b) out.mutable_at(k, a, b) = dg[static_cast<std::size_t>(k)](a, b);
        return out;
    }
};

// The launching observer: a name (core/spacetime/named_observer.hpp) or four numbers.
Vec4 observerVelocityFrom(const py::object& observer, const Spacetime& st, const Vec4& event) {
    if (py::isinstance<py::str>(observer)) {
        const std::string name = observer.cast<std::string>();
        const std::optional<NamedObserver> named = namedObserverFrom(name);
        if (!named)
            throw py::value_error("trace: observer must be one of " + namedObserverNames() + " or a 4-velocity, got '" +
                                  name + "'");
        return namedObserverVelocity(st, event, *named);
    }
    const auto u = observer.cast<std::array<double, 4>>();
    return Vec4(u[0], u[1], u[2], u[3]);
}

py::dict traceIn(const SpacetimePtr& st, const std::array<double, 4>& event, const std::array<double, 3>& direction,
                 double tolerance, bool future, std::optional<double> maxAffine, const std::string& stepper,
                 const py::object& observer) {
    input::kTolerance.require(tolerance, "trace: tolerance");
    if (maxAffine) input::kMaxAffine.require(*maxAffine, "trace: max_affine");
    if (!(Vec3(direction[0], direction[1], direction[2]).norm() > 0))
        throw py::value_error("trace: direction must not be the zero vector");
    TraceOptions opt;
    opt.absTol = opt.relTol = tolerance;
    opt.stepper = parseStepper(stepper);
    if (maxAffine) opt.maxAffine = *maxAffine;
    // As `lightcone trace --event --direction --observer`.
    const Vec4 at(event[0], event[1], event[2], event[3]);
    const PhasePoint start = observerRay(*st, at, observerVelocityFrom(observer, *st, at),
                                         Vec3(direction[0], direction[1], direction[2]), future);
    if (!start.p.allFinite()) throw std::invalid_argument("the ray cannot start at this event");
    if (st->asymptoticallyFlat()) opt.escapeRadius = escapeRadiusForRayFrom(start.x);
    std::vector<std::pair<double, PhasePoint>> samples;
    TraceResult r;
    {
        py::gil_scoped_release free;
        samples = sampleGeodesic(*st, start, opt, &r);
    }
    const py::ssize_t n = static_cast<py::ssize_t>(samples.size());
    py::array_t<double> affine(n), x({n, py::ssize_t(4)}), p({n, py::ssize_t(4)});
    for (py::ssize_t k = 0; k < n; ++k) {
        affine.mutable_at(k) = samples[static_cast<std::size_t>(k)].first;
        for (int i = 0; i < 4; ++i) {
            x.mutable_at(k, i) = samples[static_cast<std::size_t>(k)].second.x(i);
            p.mutable_at(k, i) = samples[static_cast<std::size_t>(k)].second.p(i);
        }
    }
    py::dict out;
    out["affine"] = affine;
    out["x"] = x;
    out["p"] = p;
    out["reason"] = stopReasonName(r.reason);
    out["steps"] = r.steps;
    out["max_hamiltonian_drift"] = r.maxHamiltonianDrift;  // named as by lightcone trace
    return out;
}

// As the command line, the ray's event and direction have no default: a ray from a made-up
// place would answer a question nobody asked.
template <typename T>
const T& required(const std::optional<T>& value, const char* what) {
    if (!value) throw py::type_error(std::string(what) + " is needed (as lightcone's --" + what + ")");
    return *value;
}

py::dict trace(const py::object& metricOrName, const std::map<std::string, double>& parameters,
               const std::optional<std::array<double, 4>>& event, const std::optional<std::array<double, 3>>& direction,
               double tolerance, bool future, std::optional<double> maxAffine, const std::string& stepper,
               const py::object& observer) {
    SpacetimePtr st;
    if (py::isinstance<PyMetric>(metricOrName)) {
        if (!parameters.empty()) throw std::invalid_argument("a Metric has its parameters: give them to from_formula");
        st = metricOrName.cast<const PyMetric&>().metric;
    } else {
        st = makeSpacetime(metricOrName.cast<std::string>(), parameters);
    }
    return traceIn(st, required(event, "event"), required(direction, "direction"), tolerance, future, maxAffine,
                   stepper, observer);
}

py::dict godelImages(double a, const std::optional<std::array<double, 3>>& wanted,
                     const std::array<double, 4>& observer, int windings, bool future) {
    const std::array<double, 3>& point = required(wanted, "point");
    input::kWindings.require(windings, "godel_images: windings");  // as lightcone images --windings
    const godel::ObserverView view(a, Vec4(observer[0], observer[1], observer[2], observer[3]));
    const godel::ImageSet set = view.images(Vec3(point[0], point[1], point[2]), windings, future ? 1 : -1);
    if (set.status == godel::ImageStatus::InvalidInput) throw std::invalid_argument(set.message);
    py::list images;
    for (const godel::Image& im : set.images) {
        py::dict d;
        d["winding"] = im.winding;
        d["branch"] = im.branch == godel::Branch::Outbound ? "outbound" : "inbound";
        // Where the observer's camera sees it: its static frame (docs/PHYSICS.md section 8).
        const Vec3 seen = view.inObserverFrame(im.direction);
        const godel::SkyAngles angles = godel::skyAngles(seen);
        // The command line's names and units (lightcone images): radians, as the VTK arrays.
        d["psi"] = angles.psi;
        d["phi0"] = angles.phi0;
        d["k3"] = im.k3;
        d["emission_time"] = im.emissionTime;
        d["frequency_ratio"] = im.frequencyRatio;
        d["affine"] = im.lambda;
        d["direction"] = std::array<double, 3>{seen(0), seen(1), seen(2)};
        d["event"] = std::array<double, 4>{im.event(0), im.event(1), im.event(2), im.event(3)};
        d["ring"] = im.ring;
        images.append(d);
    }
    py::dict out;
    out["status"] = godel::imageStatusName(set.status);
    out["images"] = images;
    return out;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
    m.doc() = "Lightcone's physics core: scenes, renders into numpy arrays, rays, Goedel images, shadows";
    // A value the readers refuse (a scene, an edit, a metric's parameter) is a ValueError, as every
    // other refused argument: the message keeps the file, line and field.
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const io::InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });
    // The codes of Render.arrays' kind and stop_reason, by code: lightcone.PixelKind and
    // lightcone.StopReason are made from them (python/lightcone/__init__.py).
    m.attr("_pixel_kind_names") = pixelKindNames();
    m.attr("__version__") = io::versionNumber();  // as `lightcone --version`
    m.attr("_stop_reason_names") = stopReasonNames();

    py::class_<PyScene>(m, "Scene", "A scene as lightcone's reader made it (read_scene).")
        .def("edited", &PyScene::edited, py::arg("edits"),
             "A copy with fields set, e.g. {'metric.a': 0.5}; refused edits raise with the reader's reason.")
        .def_property_readonly("document", &PyScene::document, "The scene file's JSON with every edit applied.")
        .def_property_readonly("source", [](const PyScene& s) { return s.scene().source; })
        .def_property_readonly("metric", [](const PyScene& s) { return s.scene().spacetime->name(); })
        .def_property_readonly("method", [](const PyScene& s) { return renderMethodName(resolveMethod(s.scene())); })
        .def_property_readonly("size", [](const PyScene& s) {
            return std::pair<int, int>(s.scene().camera.width, s.scene().camera.height);
        });

    py::class_<PyRender>(m, "Render", "A finished render: its colour, per-pixel data and statistics.")
        .def_property_readonly(
            "arrays", &PyRender::arrays,
            "numpy arrays: rgb (H, W, 3, linear), kind, object, u, v, frequency_ratio, "
            "emission_time, affine, drift, steps, disk_radius, intensity, image_order, stop_reason, end "
            "(the asymptotic end a sky pixel's ray reached: 0 this side, 1 a wormhole's far side)")
        .def_property_readonly("stats", &PyRender::stats)
        .def("save", &PyRender::save, py::arg("image"), py::arg("data") = "",
             "Writes what `lightcone render -o IMAGE [--data DATA]` writes, byte for byte.")
        .def("disk", &PyRender::disk, "An accretion disk's observed flux, mean redshift and spectrum.");

    m.def(
        "_catalogue_files",
        [] {
            std::vector<std::string> files;
            for (const auto& file : lc::io::catalogueFiles()) files.push_back(file.string());
            return files;
        },
        "The catalogue's metric files, as `lightcone metric list` finds them.");
    m.def("read_scene", &readScene, py::arg("source"), py::arg("edits") = py::dict(),
          "A scene file (path) or a scene as a dict, with optional edits {'field.path': value}.");
    m.def("render", &renderScene, py::arg("scene"), py::arg("method") = py::none(), py::arg("tolerance") = py::none(),
          py::arg("threads") = py::none(), py::arg("width") = py::none(), py::arg("height") = py::none(),
          py::arg("progress") = py::none(), py::arg("magnification") = false,
          "Renders on the CPU (the GIL released); progress(fraction) may raise to stop it. magnification=True: "
          "every ray carries a thin bundle, and arrays() gains magnification, shear and rotation.");
    m.def("measure_shadow", &shadow, py::arg("scene"), py::arg("tolerance") = 1e-11,
          "The black-hole shadow as the scene's camera sees it (docs/PHYSICS.md section 9), with edge_error_deg, every "
          "angle's estimated error.");
    m.def("shadow_outline", &shadowOutline, py::arg("scene"), py::arg("points") = 360, py::arg("tolerance") = 1e-10,
          "The shadow's whole outline (docs/PHYSICS.md section 9b): polar_deg (from the camera's forward), "
          "azimuth_deg (from its right towards up), directions (N x 3, right/up/forward), solid_angle_sr, centroid, "
          "from_sky.");
    py::class_<PyMetric>(m, "Metric", "A metric written as formulas (docs/METRICS.md): Metric.from_formula.")
        .def_static("_from_text", &PyMetric::fromText, py::arg("text"), py::arg("parameters"))
        .def_property_readonly("name", [](const PyMetric& p) { return p.metric->name(); })
        .def_property_readonly("parameters", [](const PyMetric& p) { return p.metric->parameters(); })
        .def_property_readonly("coordinates", [](const PyMetric& p) { return p.metric->coordinateNames(); })
        .def_property_readonly(
            "text", [](const PyMetric& p) { return p.text; }, "The formula's JSON text.")
        .def("g", &PyMetric::g, py::arg("event"), "g_mn at the event, in the signature (+,-,-,-).")
        .def("derivatives", &PyMetric::derivatives, py::arg("event"),
             "d g_mn / d x^k at the event, exact, as an array [k, m, n].")
        .def(
            "signature",
            [](const PyMetric& p, const std::array<double, 4>& x) {
                return signatureAt(*p.metric, PyMetric::event(x));
            },
            py::arg("event"))
        .def(
            "problem",
            [](const PyMetric& p, const std::array<double, 4>& x) {
                return metricProblemAt(*p.metric, PyMetric::event(x));
            },
            py::arg("event"), "Why the metric cannot serve at the event ('' when it can).");
    m.def("trace", &trace, py::arg("metric") = "schwarzschild", py::arg("parameters") = std::map<std::string, double>{},
          py::arg("event") = py::none(), py::arg("direction") = py::none(), py::arg("tolerance") = 1e-12,
          py::arg("future") = false, py::arg("max_affine") = py::none(), py::arg("stepper") = "dopri87",
          py::arg("observer") = "static",
          "One null geodesic launched by an observer (static by default; zamo, carter, free_fall, normal or a "
          "4-velocity) along a chart direction, traced back to its source or, with future, sent forward: "
          "affine, x and p per step.");
    m.def("godel_images", &godelImages, py::arg("a") = 1.0, py::arg("point") = py::none(),
          py::arg("observer") = std::array<double, 4>{0, 0, 0, 0}, py::arg("windings") = 2, py::arg("future") = false,
          "Every image of a static point in the Goedel universe (the inverse problem, docs/PHYSICS.md section 3).");
}
