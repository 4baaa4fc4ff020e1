// Per-vertex CPU renderer for the Goedel universe (seed 001 section 6, the method its GPU
// engine uses): each sphere is tessellated, every vertex gets all its images from the
// inverse problem (PhotoObjectBuilder), and each (winding, branch) layer is rasterised as an
// ordinary mesh in the observer's sky with the affine length as depth. This is the CPU twin
// of the shader path and the third route in the Goedel render benchmark.
#include "core/godel/photo_object.hpp"
#include "core/metrics/godel.hpp"
#include "core/frame.hpp"
#include "core/render.hpp"

#include <chrono>
#include <omp.h>
#include <stdexcept>

namespace lc {
namespace {

struct ScreenVertex {
    double x = 0, y = 0, depth = 0, u = 0, v = 0, t = 0;
    bool ok = false;
};

// Rasterises one triangle into rows [row0, row1) with a depth test on the affine length.
void rasterise(const ScreenVertex (&tri)[3], int object, int row0, int row1, RenderResult& out) {
    const double minX = std::min({tri[0].x, tri[1].x, tri[2].x}), maxX = std::max({tri[0].x, tri[1].x, tri[2].x});
    const double minY = std::min({tri[0].y, tri[1].y, tri[2].y}), maxY = std::max({tri[0].y, tri[1].y, tri[2].y});
    const int i0 = std::max(0, static_cast<int>(std::floor(minX - 0.5))), i1 = std::min(out.width - 1, static_cast<int>(std::ceil(maxX)));
    const int j0 = std::max(row0, static_cast<int>(std::floor(minY - 0.5))), j1 = std::min(row1 - 1, static_cast<int>(std::ceil(maxY)));
    const double area = (tri[1].x - tri[0].x) * (tri[2].y - tri[0].y) - (tri[2].x - tri[0].x) * (tri[1].y - tri[0].y);
    if (std::abs(area) < 1e-12) return;
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            const double px = i + 0.5, py = j + 0.5;
            double w[3];
            for (int k = 0; k < 3; ++k) {
                const ScreenVertex &a = tri[(k + 1) % 3], &b = tri[(k + 2) % 3];
                w[k] = ((b.x - a.x) * (py - a.y) - (px - a.x) * (b.y - a.y)) / area;
            }
            if (w[0] < 0 || w[1] < 0 || w[2] < 0) continue;
            const double depth = w[0] * tri[0].depth + w[1] * tri[1].depth + w[2] * tri[2].depth;
            PixelRecord& p = out.pixels[static_cast<std::size_t>(j) * out.width + i];
            if (p.kind == PixelRecord::Object && p.affine <= depth) continue;
            p.kind = PixelRecord::Object;
            p.stopReason = static_cast<std::int8_t>(StopReason::Hit);
            p.object = static_cast<std::int16_t>(object);
            p.affine = static_cast<float>(depth);
            p.u = static_cast<float>(w[0] * tri[0].u + w[1] * tri[1].u + w[2] * tri[2].u);
            p.v = static_cast<float>(w[0] * tri[0].v + w[1] * tri[1].v + w[2] * tri[2].v);
            p.emissionTime = static_cast<float>(w[0] * tri[0].t + w[1] * tri[1].t + w[2] * tri[2].t);
            p.frequencyRatio = 1;
        }
}

}  // namespace

RenderResult renderGodelPerVertex(const Scene& scene, int latitudes, int longitudes, double* vertexSeconds) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto* chart = dynamic_cast<const GodelCartesian*>(scene.spacetime.get());
    if (!chart) throw std::invalid_argument("the per-vertex renderer needs the 'godel' metric");
    if (scene.observerVelocity.tail<3>().norm() > 0)
        throw std::invalid_argument("the per-vertex renderer takes a static observer");
    const double a = chart->a();
    const Camera& cam = scene.camera;
    cam.validate();

    // Camera frame (Gram-Schmidt static frame) expressed at the origin of the observer's chart,
    // where the photo-object directions live.
    const godel::Isometry toObserver = godel::Isometry::movingToOrigin(a, scene.observer);
    const LocalFrame frame = LocalFrame::staticObserver(*chart, scene.observer);
    std::array<Vec3, 3> axes;
    for (int i = 0; i < 3; ++i) axes[i] = toObserver.pushForward(scene.observer, frame.e[i + 1]).tail<3>();

    const godel::PhotoObjectBuilder builder(a, scene.observer);
    godel::PhotoObjectOptions opt;
    opt.maxWinding = scene.settings.windings;
    opt.threads = scene.settings.threads;
    std::vector<godel::PhotoObject> photos;
    std::vector<godel::Mesh> meshes;
    for (const auto& s : scene.spheres) {
        meshes.push_back(godel::uvSphere(s.radius, latitudes, longitudes));
        photos.push_back(builder.build(meshes.back(), s.centre, opt));
    }
    if (vertexSeconds) *vertexSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    RenderResult out;
    out.width = cam.width;
    out.height = cam.height;
    out.pixels.resize(static_cast<std::size_t>(cam.width) * cam.height);
    const int threads = scene.settings.threads > 0 ? scene.settings.threads : omp_get_max_threads();
#pragma omp parallel num_threads(threads)
    {
        // Each thread owns a band of rows: no two threads write the same pixel.
        const int n = omp_get_num_threads(), id = omp_get_thread_num();
        const int row0 = cam.height * id / n, row1 = cam.height * (id + 1) / n;
        for (std::size_t o = 0; o < photos.size(); ++o) {
            const godel::Mesh& mesh = meshes[o];
            for (const godel::PhotoLayer& layer : photos[o].layers) {
                std::vector<ScreenVertex> sv(layer.vertices.size());
                for (std::size_t k = 0; k < sv.size(); ++k) {
                    const godel::VertexImage& vi = layer.vertices[k];
                    if (!vi.valid) continue;
                    const Vec3 d(vi.direction.dot(axes[0]), vi.direction.dot(axes[1]), vi.direction.dot(axes[2]));
                    sv[k].ok = cam.project(d, sv[k].x, sv[k].y);
                    sv[k].depth = vi.lambda;
                    sv[k].t = vi.emissionTime;
                    const Vec3& p = mesh.vertices[k];
                    sv[k].u = 0.5 + std::atan2(p(1), p(0)) / (2 * kPi);
                    sv[k].v = std::acos(std::clamp(p(2) / p.norm(), -1.0, 1.0)) / kPi;
                }
                for (const auto& t : layer.triangles) {
                    ScreenVertex tri[3] = {sv[t[0]], sv[t[1]], sv[t[2]]};
                    if (!tri[0].ok || !tri[1].ok || !tri[2].ok) continue;
                    // Panorama seam: a triangle straddling +-180 degrees is drawn on both sides.
                    const double span = std::max({tri[0].x, tri[1].x, tri[2].x}) - std::min({tri[0].x, tri[1].x, tri[2].x});
                    // Texture seam: keep u continuous across the triangle.
                    const double umax = std::max({tri[0].u, tri[1].u, tri[2].u});
                    for (auto& v : tri)
                        if (umax - v.u > 0.5) v.u += 1;
                    if (span > 0.5 * cam.width) {
                        for (auto& v : tri)
                            if (v.x < 0.5 * cam.width) v.x += cam.width;
                        rasterise(tri, static_cast<int>(o), row0, row1, out);
                        for (auto& v : tri) v.x -= cam.width;
                    }
                    rasterise(tri, static_cast<int>(o), row0, row1, out);
                }
            }
        }
    }
    for (auto& p : out.pixels) {
        if (p.kind != PixelRecord::Object) {
            p.stopReason = static_cast<std::int8_t>(StopReason::MaxAffine);
            continue;
        }
        p.u -= std::floor(p.u);
        ++out.stats.hits;
    }
    out.stats.rays = 0;
    out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

}  // namespace lc
