// SPDX-License-Identifier: BSD-3-Clause
#include "core/sr/renderer.hpp"

#include "core/numerics/parallel.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/sr/doppler.hpp"
#include "core/sr/local_ray_tracing.hpp"
#include "core/sr/photo_object.hpp"

namespace lc::sr {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Prepared {
    const SrObject* object;
    std::vector<RestTriangle> triangles;
};

// Closest emission along a pixel's ray: the smallest apparent distance, i.e. the latest
// emission time t_obs - depth, whatever frame each triangle rests in.
struct Sample {
    double depth = kInf;
    float doppler = 0.0f;
    float u = 0.0f, v = 0.0f;  // barycentric weights of p[1], p[2] (only used for shading)
    int object = -1, triangle = -1;

    void offer(double d, double D, const Vec3& bary, int obj, int tri) {
        if (d < depth) {
            depth = d;
            doppler = static_cast<float>(D);
            u = static_cast<float>(bary[1]);
            v = static_cast<float>(bary[2]);
            object = obj;
            triangle = tri;
        }
    }
};

PixelRect flatFootprint(const std::array<Vec3, 3>& tri, const ObserverCamera& cam) {
    if (cam.projection == Camera::Projection::Panorama) {
        const Vec3 up = cam.axes().up;
        return panoramaFootprint(
            tri, [&](const Vec3& p) -> std::optional<Vec3> { return p - cam.position; },
            intersectFlat(tri, cam.position, up).has_value(), intersectFlat(tri, cam.position, -up).has_value(), cam);
    }
    double lox = kInf, loy = kInf, hix = -kInf, hiy = -kInf;
    for (const Vec3& p : tri) {
        double px, py;
        if (!cam.projectPoint(p, px, py)) return PixelRect{0, 0, cam.width - 1, cam.height - 1};
        lox = std::min(lox, px), hix = std::max(hix, px), loy = std::min(loy, py), hiy = std::max(hiy, py);
    }
    auto clampI = [](double v, int n) { return static_cast<int>(std::clamp(v, -1.0, static_cast<double>(n))); };
    return PixelRect{std::max(0, clampI(std::ceil(lox - 1.5), cam.width)),
                     std::max(0, clampI(std::ceil(loy - 1.5), cam.height)),
                     std::min(cam.width - 1, clampI(std::floor(hix + 0.5), cam.width)),
                     std::min(cam.height - 1, clampI(std::floor(hiy + 0.5), cam.height))};
}

// One (object, triangle) with the pixel rectangle where it may appear.
struct Item {
    int object, triangle;
    PixelRect rect;
};

// Every triangle of the scene in its rest frame, and where on the screen each can appear: the
// flat apparent triangle's projection (polygon distortion) or the apparent footprint of the
// rest triangle (local ray tracing).
struct Footprints {
    std::vector<Prepared> prep;
    std::vector<std::vector<std::array<Vec3, 3>>> flat;  // polygon distortion only
    std::vector<Item> items;
};

Footprints footprints(const SrScene& scene, const ObserverCamera& cam, const Vec4& observer, SrRenderMode mode,
                      int threads) {
    const int nObj = static_cast<int>(scene.objects.size());
    Footprints f;
    f.prep.resize(nObj);
    f.flat.resize(nObj);
    for (int o = 0; o < nObj; ++o) {
        f.prep[o].object = &scene.objects[o];
        const TriMesh& m = scene.objects[o].mesh;
        for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
            f.prep[o].triangles.push_back(RestTriangle::fromMesh(m, t));
        for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
            f.items.push_back({o, t, PixelRect{0, 0, cam.width - 1, cam.height - 1}});
    }
    if (mode == SrRenderMode::PolygonDistortion) {
        for (int o = 0; o < nObj; ++o) {
            const std::vector<Vec3> app =
                apparentPositions(scene.objects[o].frame, scene.objects[o].mesh.positions, observer);
            for (const auto& t : scene.objects[o].mesh.triangles)
                f.flat[o].push_back({app[t[0]], app[t[1]], app[t[2]]});
        }
        for (Item& it : f.items) it.rect = flatFootprint(f.flat[it.object][it.triangle], cam);
    } else if (mode == SrRenderMode::LocalRayTracing) {
        const int nItems = static_cast<int>(f.items.size());
        FirstError errors;
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
        for (int i = 0; i < nItems; ++i)
            errors.run([&] {
                Item& it = f.items[i];
                it.rect = apparentFootprint(f.prep[it.object].triangles[it.triangle], scene.objects[it.object].frame,
                                            observer, cam)
                              .rect;
            });
        errors.rethrow();
    }
    return f;
}

// Per pixel the closest emission over every triangle whose footprint covers it.
std::vector<Sample> nearestSamples(const SrScene& scene, const ObserverCamera& cam, const Vec4& observer,
                                   const Footprints& f, SrRenderMode mode, int threads) {
    const int W = cam.width, H = cam.height;
    const int nObj = static_cast<int>(scene.objects.size());
    std::vector<Sample> samples(static_cast<size_t>(W) * H);
    FirstError rowErrors;
#pragma omp parallel num_threads(threads)
    {
        std::vector<Vec3> dirs(W);
        std::vector<RestRay> rays(static_cast<size_t>(W) * std::max(nObj, 1));
#pragma omp for schedule(dynamic, 2)
        for (int y = 0; y < H; ++y) {
            rowErrors.run([&] {
                // Rays only for the columns some footprint covers in this row.
                int xMin = W, xMax = -1;
                for (const Item& it : f.items)
                    if (y >= it.rect.y0 && y <= it.rect.y1)
                        xMin = std::min(xMin, it.rect.x0), xMax = std::max(xMax, it.rect.x1);
                if (xMax < xMin) return;
                for (int x = xMin; x <= xMax; ++x) dirs[x] = cam.direction(x, y);
                for (int o = 0; o < nObj; ++o)
                    for (int x = xMin; x <= xMax; ++x)
                        rays[o * W + x] = makeRestRay(scene.objects[o].frame, observer, dirs[x]);
                Sample* row = &samples[static_cast<size_t>(y) * W];
                for (const Item& it : f.items) {
                    if (y < it.rect.y0 || y > it.rect.y1) continue;
                    for (int x = it.rect.x0; x <= it.rect.x1; ++x) {
                        const RestRay& ray = rays[it.object * W + x];
                        if (mode == SrRenderMode::PolygonDistortion) {
                            if (auto h = intersectFlat(f.flat[it.object][it.triangle], cam.position, dirs[x]))
                                row[x].offer(h->distance, ray.doppler, h->barycentric, it.object, it.triangle);
                        } else if (auto h = intersectRest(f.prep[it.object].triangles[it.triangle], ray)) {
                            row[x].offer(h->depth, h->doppler, h->barycentric, it.object, it.triangle);
                        }
                    }
                }
            });
        }
    }
    rowErrors.rethrow();
    return samples;
}

// The colour of a pixel's sample seen along d: Phong in the emitter's rest frame with the light
// and view directions aberrated there (seed 003 Fig. 9), the observed black-body temperature.
Vec3 shadeSample(const SrScene& scene, const SrRenderOptions& opt, const colour::BlackbodyTable& table, const Sample& s,
                 const RestTriangle& tri, const Vec3& eye, const Vec3& d) {
    const SrObject& obj = scene.objects[s.object];
    const SrMaterial& m = obj.material;
    const Vec2 shade =
        srShading<double>(d, s.depth, s.doppler, s.u, s.v, tri.n[0], tri.n[1], tri.n[2], obj.frame.beta(),
                          m.temperatureK, Eigen::Vector4d(m.ambient, m.diffuse, m.specular, m.shininess),
                          scene.lightPosition - eye, scene.lightTemperatureK, opt.shading ? 1.0 : 0.0,
                          opt.doppler ? 1.0 : 0.0, opt.colourSource == SrColourSource::ReflectedLight ? 1.0 : 0.0);
    const double f = shade[0], T = shade[1];
    return (f * table.lookup(T, opt.toneMap)).cwiseMin(1.0).cwiseMax(0.0);
}

}  // namespace

void SrMaterial::validate() const {
    for (double v : {temperatureK, ambient, diffuse, specular, shininess})
        if (!(std::isfinite(v) && v >= 0)) throw std::invalid_argument("material values must be finite and >= 0");
}

SrRenderer::SrRenderer(std::shared_ptr<const colour::BlackbodyTable> table) : table_(std::move(table)) {
    // The shared table spans 500 K to 10^7 K: at beta = 0.95 head-on D ~ 6, 6000 K is seen near 37000 K.
    if (!table_) table_ = colour::standardBlackbodyTable();
}

SrImage SrRenderer::render(const SrScene& scene, const ObserverCamera& cam, const SrRenderOptions& opt) const {
    cam.validate();
    const int W = cam.width, H = cam.height;
    const int nt = opt.threads > 0 ? opt.threads : omp_get_max_threads();
    const Vec4 observer(scene.observerTime, cam.position.x(), cam.position.y(), cam.position.z());
    const Footprints f = footprints(scene, cam, observer, opt.mode, nt);
    const std::vector<Sample> samples = nearestSamples(scene, cam, observer, f, opt.mode, nt);

    SrImage img;
    img.width = W;
    img.height = H;
    img.rgb.assign(3 * samples.size(), 0.0f);
    img.depth.assign(samples.size(), std::numeric_limits<float>::infinity());
    img.object.assign(samples.size(), -1);
    img.triangle.assign(samples.size(), -1);
    img.doppler.assign(samples.size(), 0.0f);
    FirstError shadeErrors;
#pragma omp parallel for schedule(static) num_threads(nt)
    for (int i = 0; i < W * H; ++i) {
        shadeErrors.run([&] {
            const Sample& s = samples[i];
            Vec3 c = opt.background;
            if (s.object >= 0) {
                const Vec3 d = cam.direction(i % W, i / W);
                c = shadeSample(scene, opt, *table_, s, f.prep[s.object].triangles[s.triangle], cam.position, d);
                img.depth[i] = static_cast<float>(s.depth);
                img.object[i] = s.object;
                img.triangle[i] = s.triangle;
                img.doppler[i] = static_cast<float>(s.doppler);
            }
            for (int k = 0; k < 3; ++k) img.rgb[3 * i + k] = static_cast<float>(c[k]);
        });
    }
    shadeErrors.rethrow();
    return img;
}

}  // namespace lc::sr
