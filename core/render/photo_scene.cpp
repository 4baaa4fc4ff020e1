// SPDX-License-Identifier: BSD-3-Clause
#include "core/render/photo_scene.hpp"
#include "core/render/godel_lighting.hpp"

#include "core/godel/proper_time_world_line.hpp"
#include "core/input/number_text.hpp"

#include "core/spacetime/frame.hpp"
#include "core/metrics/godel.hpp"
#include "core/numerics/parallel.hpp"

#include <algorithm>
#include <memory>
#include <omp.h>
#include <stdexcept>

namespace lc {
namespace {

Vec2 sphericalUv(const Vec3& p) {
    return Vec2(0.5 + std::atan2(p(1), p(0)) / (2 * kPi), std::acos(std::clamp(p(2) / p.norm(), -1.0, 1.0)) / kPi);
}

// The freely falling body: every vertex falls freely with the centre's velocity relative to the
// static observer, given to each vertex relative to its own static observer (frame components,
// not chart components: off the axis g_tx != 0, and copied chart components of a fast body's
// velocity turn spacelike a fraction of a away from the centre).
godel::FreeFall vertexFall(double a, const Motion& m, const godel::Isometry& observerFromCentreChart, const Vec3& v) {
    const GodelCartesian chart(a);
    const godel::OriginGeodesic centreLine = godel::OriginGeodesic::timelike(a, m.k0, m.k3, m.phi0);
    const Vec4 u0 = centreLine.tangentCartesian(0);  // at the origin: frame components = chart components
    const Vec4 vertexEvent(0, v(0), v(1), v(2));
    const LocalFrame vertexFrame = LocalFrame::staticObserver(chart, vertexEvent);
    const Vec4 uVertex =
        u0(0) * vertexFrame.e[0] + u0(1) * vertexFrame.e[1] + u0(2) * vertexFrame.e[2] + u0(3) * vertexFrame.e[3];
    const godel::Isometry toVertex = godel::Isometry::movingToOrigin(a, vertexEvent);
    Vec4 u = toVertex.pushForward(vertexEvent, uVertex);
    const double n2 = u(0) * u(0) - u.tail<3>().squaredNorm();  // the chart is Minkowskian at the origin
    u /= std::sqrt(n2);
    const godel::OriginGeodesic line = godel::OriginGeodesic::timelike(a, u(0), u(3), std::atan2(u(2), u(1)));
    return godel::FreeFall(line, observerFromCentreChart.compose(toVertex.inverse()));
}

// A body carried along a given world line of its centre (events in the world chart, linear in
// between, parametrised by coordinate time): each vertex sits at its offset in the local frame
// of the centre's current event. Returned in the observer's chart.
godel::WorldLine vertexOnWorldLine(double a, const std::shared_ptr<const std::vector<Vec4>>& points,
                                   const godel::Isometry& toObserver, const Vec3& v) {
    // Binary search for the segment: the root finder evaluates this thousands of times per vertex,
    // and world lines may have 10^5 events.
    auto centreAt = [points](double t) {
        const std::vector<Vec4>& p = *points;
        const auto later =
            std::upper_bound(p.begin() + 1, p.end() - 1, t, [](double s, const Vec4& e) { return s < e(0); });
        const Vec4 &p0 = *(later - 1), &p1 = *later;
        const double f = (t - p0(0)) / (p1(0) - p0(0));
        return Vec4(p0 + f * (p1 - p0));
    };
    const Vec4 local(0, v(0), v(1), v(2));
    return {[=](double t) { return toObserver.apply(godel::Isometry::movingOriginTo(a, centreAt(t)).apply(local)); },
            {}};
}

// The stretches of a trip by proper time (world chart) where the observer at `observer` can see a
// point within `reach` of its centre with up to `maxWinding` windings: the image of a point
// leaves it at most 2 (n + 1) 2 pi (sqrt2 - 1) a + |dz| of chart time before (or, sent to the
// future, after) the observer's event (one winding takes 2 pi (sqrt2 - 1) a = 2.6 a, docs/
// PHYSICS.md section 3; the factor 2 is room for k3 != 0), and the isometries to the observer's
// and the point's charts shift t by less than 2 sqrt2 pi a each (twice for the observer's).
std::vector<godel::MovingImageOptions::Span> visibleSpans(double a, const godel::ProperTimeWorldLine& line,
                                                          const Vec4& observer, int maxWinding, double reach) {
    const double lag = 2 * (maxWinding + 1) * 2 * kPi * (kSqrt2 - 1) * a;
    const double shift = 3 * godel::Isometry::kTimeShiftBound * a + reach;
    const auto seen = [&](const godel::ProperTimeWorldLine::ChartBox& box) {
        const double dz = std::max(std::abs(box.zMin - observer(3)), std::abs(box.zMax - observer(3))) + reach;
        const double window = lag + dz + shift;
        return box.tMax - observer(0) >= -window && box.tMin - observer(0) <= window;
    };
    std::vector<godel::MovingImageOptions::Span> spans;
    for (const auto& [t0, t1] : line.spansWhere(seen)) {
        // Densely enough to separate the light cone's crossings that a world line running back in
        // coordinate time makes within one winding.
        const double samples = std::max(48.0 * (maxWinding + 1), std::ceil(24 * (t1 - t0) / a));
        spans.push_back({t0, t1, static_cast<int>(std::min(samples, 1e8))});
    }
    return spans;
}

// Where on a moving body's world line emissions can be seen, for `maxWinding` windings. Free
// fall: the centre event is the body's tau = 0 and emissions happen in the observer's past
// (dt/dtau >= 1, so |tau| <= |t|). A trip by proper time: the parts of it the observer can see
// (visibleSpans), so a long trip costs what its visible part costs. A given world line: its own span.
godel::MovingImageOptions emissionWindow(double a, const Motion& motion, const godel::Isometry& observerFromCentre,
                                         const Vec4& observer, int maxWinding, double reach) {
    godel::MovingImageOptions mo;
    mo.image.maxWinding = maxWinding;
    if (motion.kind == Motion::Kind::ProperTime) {
        mo.tauMin = 0;
        mo.tauMax = motion.properTimeLine->duration();
        mo.spans = visibleSpans(a, *motion.properTimeLine, observer, maxWinding, reach);
        return mo;
    }
    if (motion.kind == Motion::Kind::FreeFall) {
        const double span = (maxWinding + 1) * 2 * kPi * a * 1.5;
        const double tc = observerFromCentre.apply(Vec4::Zero())(0);
        mo.tauMin = std::min(-span + tc, -span);
        mo.tauMax = std::max(0.0, -tc) + 0.5;
    } else {
        mo.tauMin = motion.points.front()(0);
        mo.tauMax = motion.points.back()(0);
    }
    mo.samples = 48 * (maxWinding + 1);
    return mo;
}

// The world line, in the observer's chart, of the body's point at offset v from its centre.
godel::WorldLine pointWorldLine(double a, const Motion& motion, const godel::Isometry& toObserver,
                                const godel::Isometry& observerFromCentre,
                                const std::shared_ptr<const std::vector<Vec4>>& worldLinePoints, const Vec3& v) {
    if (motion.kind == Motion::Kind::FreeFall) return vertexFall(a, motion, observerFromCentre, v).worldLine();
    if (motion.kind == Motion::Kind::ProperTime) {
        const std::shared_ptr<const godel::ProperTimeWorldLine> line = motion.properTimeLine;
        const Vec4 local(0, v(0), v(1), v(2));
        return {[=](double tau) {
                    return toObserver.apply(godel::Isometry::movingOriginTo(a, line->position(tau)).apply(local));
                },
                {}};
    }
    return vertexOnWorldLine(a, worldLinePoints, toObserver, v);
}

}  // namespace

MovingCentre movingCentre(const Scene& scene, const SphereObject& body, int maxWinding) {
    const auto godelA = scene.spacetime->godelRadius();
    if (!godelA || !body.motion.moving() || body.motion.kind == Motion::Kind::ConstantVelocity)
        throw std::invalid_argument("images of a moving centre need the 'godel' metric and a free fall or world line");
    const double a = *godelA;
    const godel::Isometry toObserver = godel::Isometry::observerToOrigin(a, scene.observer);
    const godel::Isometry observerFromCentre = toObserver.compose(godel::Isometry::movingOriginTo(a, body.centre));
    const auto points = std::make_shared<const std::vector<Vec4>>(body.motion.points);
    return {pointWorldLine(a, body.motion, toObserver, observerFromCentre, points, Vec3::Zero()),
            emissionWindow(a, body.motion, observerFromCentre, scene.observer, maxWinding, 0)};
}

std::vector<godel::MovingImage> imagesOfMovingCentre(const Scene& scene, const SphereObject& body, int maxWinding) {
    const MovingCentre centre = movingCentre(scene, body, maxWinding);
    const double a = scene.spacetime->godelRadius().value();
    std::vector<godel::MovingImage> images = godel::imagesOfWorldLine(a, centre.line, centre.window);
    const godel::Isometry toWorld = godel::Isometry::observerToOrigin(a, scene.observer).inverse();
    for (auto& mi : images) mi.image.emissionTime = toWorld.apply(mi.image.event)(0);
    return images;
}

PhotoSceneOptions photoSceneOptions(const Scene& scene) {
    PhotoSceneOptions po;
    po.maxWinding = scene.settings.windings;
    po.latitudes = scene.settings.meshLatitudes;
    po.longitudes = scene.settings.meshLongitudes;
    po.threads = scene.settings.threads;
    return po;
}

namespace {

// What every object's photo-object layers are built from: the observer's chart and camera frame.
struct ObserverCamera {
    double a;
    godel::Isometry toObserver;
    std::array<Vec3, 3> axes;  // camera frame at the origin of the observer's chart
    Vec3 toCamera(const Vec3& d) const { return Vec3(d.dot(axes[0]), d.dot(axes[1]), d.dot(axes[2])); }
};

ObserverCamera observerCamera(double a, const Vec4& observer, bool cameraFrame) {
    const GodelCartesian chart(a);
    ObserverCamera cam{
        a, godel::Isometry::observerToOrigin(a, observer), {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()}};
    if (!cameraFrame) return cam;
    const LocalFrame frame = LocalFrame::staticObserver(chart, observer);
    for (int i = 0; i < 3; ++i) cam.axes[i] = cam.toObserver.pushForward(observer, frame.e[i + 1]).tail<3>();
    return cam;
}

// An object at rest: the inverse problem of each static vertex (PhotoObjectBuilder, stitched).
void restingLayers(const ObserverCamera& cam, const Vec4& observer, const PhotoSource& src,
                   const PhotoSceneOptions& opt, PhotoSceneObject& obj) {
    const godel::Isometry& toObserver = cam.toObserver;
    const std::size_t nv = src.mesh.vertices.size();
    godel::PhotoObjectOptions po;
    po.maxWinding = opt.maxWinding;
    po.threads = opt.threads;
    po.stitch = opt.stitch;
    const godel::PhotoObject photo = godel::PhotoObjectBuilder(cam.a, observer).build(src.mesh, src.centre, po);
    if (photo.status != godel::PhotoStatus::Ok)
        throw std::invalid_argument("object '" + src.name + "': " + photo.message);
    obj.beyondHorizon = photo.beyondHorizon;
    obj.weldedVertices = photo.weldedVertices;
    const godel::Isometry toWorld = toObserver.inverse();
    for (const auto& L : photo.layers) {
        PhotoSceneLayer layer{L.winding, L.branch, L.vertices, std::vector<double>(nv, 1.0), L.triangles, {}, 0};
        for (std::size_t v = 0; v < nv; ++v) {
            godel::VertexImage& vi = layer.vertices[v];
            vi.direction = cam.toCamera(vi.direction);
            // Emission time in the world chart, like the per-pixel renderers: the event is
            // the vertex (static) at the emission time of the observer's chart.
            if (vi.valid && v < photo.observerChart.size()) {
                Vec4 event = photo.observerChart[v];
                event(0) = vi.emissionTime;
                vi.emissionTime = toWorld.apply(event)(0);
            }
        }
        obj.layers.push_back(std::move(layer));
    }
}

// A world line may cross the past light cone several times in one (winding, branch): one layer
// per crossing, counted along the world line (the body seen at several ages at once).
constexpr int kCrossings = 4;

// A freely falling body or a world line: the emission event on each vertex's own world line.
void movingLayers(const ObserverCamera& cam, const Vec4& observer, const PhotoSource& src, const PhotoSceneOptions& opt,
                  PhotoSceneObject& obj) {
    const double a = cam.a;
    const godel::Isometry& toObserver = cam.toObserver;
    const std::size_t nv = src.mesh.vertices.size();
    obj.layers.resize(static_cast<std::size_t>(2 * (opt.maxWinding + 1) * kCrossings));
    for (int n = 0; n <= opt.maxWinding; ++n)
        for (int b = 0; b < 2; ++b)
            for (int c = 0; c < kCrossings; ++c) {
                PhotoSceneLayer& L = obj.layers[static_cast<std::size_t>((2 * n + b) * kCrossings + c)];
                L.winding = n;
                L.branch = b ? godel::Branch::Inbound : godel::Branch::Outbound;
                L.crossing = c;
                L.vertices.assign(nv, {});
                L.frequencyRatio.assign(nv, 1.0);
                L.properTime.assign(nv, 0.0);
            }
    const godel::Isometry observerFromCentre = toObserver.compose(godel::Isometry::movingOriginTo(a, src.centre));
    double reach = 0;  // the farthest vertex from the centre
    for (const Vec3& v : src.mesh.vertices) reach = std::max(reach, v.norm());
    const godel::MovingImageOptions mo =
        emissionWindow(a, src.motion, observerFromCentre, observer, opt.maxWinding, reach);
    const godel::Isometry toWorld = toObserver.inverse();  // once, not per image in the vertex loop
    std::vector<char> imaged(nv, 0);
    const int threads = opt.threads > 0 ? opt.threads : omp_get_max_threads();
    const auto worldLinePoints = std::make_shared<const std::vector<Vec4>>(src.motion.points);
    FirstError errors;
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
    for (std::size_t v = 0; v < nv; ++v) {
        errors.run([&] {
            // Inside run(): a progress callback that throws stops the other vertices too.
            if (opt.progress && v % 16 == 0 && omp_get_thread_num() == 0) opt.progress(static_cast<double>(v) / nv);
            const godel::WorldLine line =
                pointWorldLine(a, src.motion, toObserver, observerFromCentre, worldLinePoints, src.mesh.vertices[v]);
            std::vector<godel::MovingImage> images = godel::imagesOfWorldLine(a, line, mo);
            imaged[v] = !images.empty();
            std::stable_sort(images.begin(), images.end(),
                             [](const godel::MovingImage& x, const godel::MovingImage& y) { return x.tau < y.tau; });
            // One count per (winding, branch): a fixed 64 once dropped every winding from 32 on.
            std::vector<int> count(static_cast<std::size_t>(2 * (opt.maxWinding + 1)), 0);
            for (const auto& mi : images) {
                const int slot = 2 * mi.image.winding + (mi.image.branch == godel::Branch::Inbound);
                if (slot < 0 || slot >= static_cast<int>(count.size()) ||
                    count[static_cast<std::size_t>(slot)] >= kCrossings)
                    continue;
                const std::size_t index =
                    static_cast<std::size_t>(slot * kCrossings + count[static_cast<std::size_t>(slot)]++);
                if (index >= obj.layers.size()) continue;
                PhotoSceneLayer& L = obj.layers[index];
                godel::VertexImage& vi = L.vertices[v];
                vi.valid = true;
                vi.direction = cam.toCamera(mi.image.direction);
                vi.lambda = mi.image.lambda;
                vi.emissionTime = toWorld.apply(mi.image.event)(0);
                L.frequencyRatio[v] = mi.image.frequencyRatio;
                L.properTime[v] = mi.tau;
            }
        });
    }
    errors.rethrow();
    for (std::size_t v = 0; v < nv; ++v)
        if (!imaged[v]) obj.beyondHorizon.push_back(static_cast<int>(v));
    for (auto& L : obj.layers)
        for (const auto& t : src.mesh.triangles)
            if (L.vertices[t[0]].valid && L.vertices[t[1]].valid && L.vertices[t[2]].valid) L.triangles.push_back(t);
    // Crossings beyond the first that no vertex has are no layers at all.
    obj.layers.erase(std::remove_if(obj.layers.begin(), obj.layers.end(),
                                    [](const PhotoSceneLayer& L) {
                                        return L.crossing > 0 && std::none_of(L.vertices.begin(), L.vertices.end(),
                                                                              [](const auto& vi) { return vi.valid; });
                                    }),
                     obj.layers.end());
}

}  // namespace

std::vector<Vec2> sphericalUvs(const godel::Mesh& mesh) {
    std::vector<Vec2> uv;
    uv.reserve(mesh.vertices.size());
    for (const auto& p : mesh.vertices) uv.push_back(sphericalUv(p));
    return uv;
}

double photoObjectBytes(std::size_t vertices, std::size_t triangles, bool moving, int maxWinding) {
    const double layers = 2.0 * (maxWinding + 1) * (moving ? kCrossings : 1);
    const double perLayer = static_cast<double>(vertices) * (sizeof(godel::VertexImage) + 2 * sizeof(double)) +
                            static_cast<double>(triangles) * sizeof(std::array<int, 3>);
    const double meshAndLight = static_cast<double>(vertices) * (2 * sizeof(Vec3) + sizeof(Vec2)) +
                                static_cast<double>(triangles) * sizeof(std::array<int, 3>);
    return layers * perLayer + meshAndLight;
}

namespace {

// What the layers will hold, before any is built (1000 windings of a 100 x 200 sphere once asked
// for 2.6 GB at rest and 10 GB moving).
void requirePhotoObjectFits(const std::string& name, std::size_t vertices, std::size_t triangles, bool moving,
                            int maxWinding) {
    const double bytes = photoObjectBytes(vertices, triangles, moving, maxWinding);
    if (bytes <= kMaxPhotoObjectBytes) return;
    const double layers = 2.0 * (maxWinding + 1) * (moving ? kCrossings : 1);
    throw std::invalid_argument("object '" + name + "': its photo-object would hold " +
                                input::significantDigits(layers) + " layers (windings " + std::to_string(maxWinding) +
                                (moving ? ", " + std::to_string(kCrossings) + " crossings each" : "") + ") of " +
                                std::to_string(vertices) + " vertices, about " +
                                input::significantDigits(bytes / 1e9, 3) + " GB, beyond " +
                                input::significantDigits(kMaxPhotoObjectBytes / 1e9, 3) +
                                " GB: fewer windings or a coarser render.mesh_resolution");
}

// Each object's mesh size (spheres: godel::uvSphere's counts, without building the mesh) and motion.
template <class Visit>
void forEachPhotoObjectSize(const Scene& scene, const PhotoSceneOptions& opt, Visit visit) {
    const std::size_t lat = static_cast<std::size_t>(std::max(opt.latitudes, 2));
    const std::size_t lon = static_cast<std::size_t>(std::max(opt.longitudes, 3));
    const std::size_t sphereVertices = (lat - 1) * lon + 2, sphereTriangles = 2 * lon * (lat - 1);
    for (const auto& s : scene.spheres)
        visit(s.name, sphereVertices, sphereTriangles, s.motion.kind != Motion::Kind::Rest);
    for (const auto& m : scene.meshes)
        visit(m.name, m.positions.size(), m.triangles.size(), m.motion.kind != Motion::Kind::Rest);
}

}  // namespace

double photoSceneBytes(const Scene& scene, const PhotoSceneOptions& opt) {
    double bytes = 0;
    forEachPhotoObjectSize(scene, opt,
                           [&](const std::string&, std::size_t vertices, std::size_t triangles, bool moving) {
                               bytes += photoObjectBytes(vertices, triangles, moving, opt.maxWinding);
                           });
    return bytes;
}

std::vector<PhotoSource> photoSources(const Scene& scene, const PhotoSceneOptions& opt) {
    std::vector<PhotoSource> sources;
    for (const auto& s : scene.spheres)
        sources.push_back({s.name, s.centre, s.motion, godel::uvSphere(s.radius, opt.latitudes, opt.longitudes)});
    for (const auto& m : scene.meshes) {
        godel::Mesh mesh;
        mesh.vertices = m.positions;
        mesh.triangles = m.triangles;
        sources.push_back({m.name, m.centre, m.motion, mesh});
    }
    return sources;
}

PhotoSceneObject buildPhotoObject(double a, const Vec4& observer, const PhotoSource& src,
                                  const PhotoSceneOptions& opt) {
    requirePhotoObjectFits(src.name, src.mesh.vertices.size(), src.mesh.triangles.size(),
                           src.motion.kind != Motion::Kind::Rest, opt.maxWinding);
    const ObserverCamera cam = observerCamera(a, observer, opt.cameraFrame);
    PhotoSceneObject obj;
    obj.name = src.name;
    obj.mesh = src.mesh;
    obj.uv = sphericalUvs(src.mesh);
    if (src.motion.kind == Motion::Kind::Rest)
        restingLayers(cam, observer, src, opt, obj);
    else if (src.motion.kind != Motion::Kind::ConstantVelocity)
        movingLayers(cam, observer, src, opt, obj);
    else
        throw std::invalid_argument("object '" + src.name + "': constant velocity needs the minkowski metric");
    return obj;
}

std::vector<PhotoSceneObject> buildPhotoScene(const Scene& scene, const PhotoSceneOptions& opt) {
    const auto godelA = scene.spacetime->godelRadius();
    if (!godelA) throw std::invalid_argument("photo-objects need the 'godel' metric");
    if (scene.observerVelocity.tail<3>().norm() > 0) throw std::invalid_argument("photo-objects: static observer only");
    // Refused before anything is built: one object too big (its own reason), then all together.
    forEachPhotoObjectSize(scene, opt,
                           [&](const std::string& name, std::size_t vertices, std::size_t triangles, bool moving) {
                               requirePhotoObjectFits(name, vertices, triangles, moving, opt.maxWinding);
                           });
    const double bytes = photoSceneBytes(scene, opt);
    if (bytes > kMaxPhotoSceneBytes)
        throw std::invalid_argument("the scene's photo-objects (" +
                                    std::to_string(scene.spheres.size() + scene.meshes.size()) + " objects, windings " +
                                    std::to_string(opt.maxWinding) + ") would hold about " +
                                    input::significantDigits(bytes / 1e9, 3) + " GB, beyond " +
                                    input::significantDigits(kMaxPhotoSceneBytes / 1e9, 3) +
                                    " GB: fewer objects or windings, or a coarser render.mesh_resolution");
    const std::vector<PhotoSource> sources = photoSources(scene, opt);
    std::vector<PhotoSceneObject> out;
    // One lighting for every object: its shadow testers are built once per light.
    const std::unique_ptr<GodelLighting> lighting =
        !opt.vertexLight || scene.lights.empty()
            ? nullptr
            : std::make_unique<GodelLighting>(*godelA, scene, std::min(1, scene.settings.windings));
    for (std::size_t k = 0; k < sources.size(); ++k) {
        PhotoSceneOptions one = opt;
        if (opt.progress) {
            opt.progress(static_cast<double>(k) / sources.size());
            one.progress = [&opt, k, n = sources.size()](double f) { opt.progress((k + f) / n); };
        }
        out.push_back(buildPhotoObject(*godelA, scene.observer, sources[k], one));
        out.back().sceneIndex = static_cast<int>(k);
        if (lighting) out.back().light = vertexLight(*godelA, scene, *lighting, sources[k], k);
    }
    if (opt.progress) opt.progress(1.0);
    return out;
}

std::vector<Vec3> vertexLight(double a, const Scene& scene, const GodelLighting& lighting, const PhotoSource& source,
                              std::size_t object) {
    if (!lighting.active() || object >= scene.spheres.size() || source.motion.moving()) return {};
    std::vector<Vec3> light(source.mesh.vertices.size(), Vec3::Ones());
    const godel::Isometry fromLocal = godel::Isometry::movingOriginTo(a, source.centre);
    const long n = static_cast<long>(light.size());
    FirstError errors;
#pragma omp parallel for schedule(dynamic, 64)
    for (long k = 0; k < n; ++k)
        errors.run([&] {
            const Vec3& v = source.mesh.vertices[static_cast<std::size_t>(k)];
            const Vec4 x = fromLocal.apply(Vec4(0, v(0), v(1), v(2)));
            // A little ambient light so unlit sides stay visible (as lc::shadePixels).
            light[static_cast<std::size_t>(k)] = kAmbientLight * Vec3::Ones() + lighting.at(x, object);
        });
    errors.rethrow();
    return light;
}

std::vector<AgeImage> ageImages(const Scene& scene) {
    std::vector<AgeImage> out;
    const auto godelA = scene.spacetime->godelRadius();
    if (!godelA) return out;
    const ObserverCamera cam = observerCamera(*godelA, scene.observer, true);
    for (std::size_t k = 0; k < scene.spheres.size(); ++k) {
        const SphereObject& s = scene.spheres[k];
        if (s.motion.kind != Motion::Kind::ProperTime) continue;
        for (const auto& mi : imagesOfMovingCentre(scene, s, scene.settings.windings))
            out.push_back({static_cast<int>(k), s.name, mi.tau, mi.image.emissionTime, cam.toCamera(mi.image.direction),
                           std::atan(s.radius / std::max(mi.image.lambda, s.radius))});
    }
    return out;
}

}  // namespace lc
