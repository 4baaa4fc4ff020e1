// SPDX-License-Identifier: BSD-3-Clause
// Per-vertex CPU renderer for the Goedel universe (seed 001 section 6, the method its GPU
// engine uses): each sphere is tessellated, every vertex gets all its images from the
// inverse problem (PhotoObjectBuilder), and each (winding, branch) layer is rasterised as an
// ordinary mesh in the observer's sky with the affine length as depth. This is the CPU twin
// of the shader path and the third route in the Goedel render benchmark.
#include "core/render/photo_scene.hpp"
#include "core/scene/frame_camera.hpp"
#include "core/numerics/parallel.hpp"
#include "core/render/render.hpp"

#include <algorithm>
#include <chrono>
#include <omp.h>
#include <stdexcept>

namespace lc {
namespace {

struct ScreenVertex {
    double x = 0, y = 0, depth = 0, u = 0, v = 0, t = 0, f = 1;
    bool ok = false;
};

// Rasterises one triangle into rows [row0, row1) with a depth test on the affine length.
void rasterise(const ScreenVertex (&tri)[3], int object, int row0, int row1, RenderResult& out) {
    const double minX = std::min({tri[0].x, tri[1].x, tri[2].x}), maxX = std::max({tri[0].x, tri[1].x, tri[2].x});
    const double minY = std::min({tri[0].y, tri[1].y, tri[2].y}), maxY = std::max({tri[0].y, tri[1].y, tri[2].y});
    // Clamped in double before the cast: a vertex far off screen (a 1e-8 degree field of view,
    // a point near 90 degrees off axis) projects to |x| ~ 1e13, beyond int.
    const auto pixel = [](double v, int lo, int hi) { return static_cast<int>(std::clamp(v, double(lo), double(hi))); };
    const int i0 = pixel(std::floor(minX - 0.5), 0, out.width), i1 = pixel(std::ceil(maxX), -1, out.width - 1);
    const int j0 = pixel(std::floor(minY - 0.5), row0, row1), j1 = pixel(std::ceil(maxY), row0 - 1, row1 - 1);
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
            p.frequencyRatio = static_cast<float>(w[0] * tri[0].f + w[1] * tri[1].f + w[2] * tri[2].f);
        }
}

}  // namespace

RenderResult renderGodelPerVertex(const Scene& scene, int latitudes, int longitudes, double* vertexSeconds,
                                  const ProgressCallback& progress, const std::vector<PhotoSceneObject>* prebuilt) {
    const auto t0 = std::chrono::steady_clock::now();
    scene.camera.validate();
    const Camera cam = frameCamera(scene);  // the photo-objects' directions are in the static frame
    PhotoSceneOptions po = photoSceneOptions(scene);
    po.latitudes = latitudes;
    po.longitudes = longitudes;
    if (progress) po.progress = [&progress](double f) { progress(0.9 * f); };  // the raster is the last tenth
    std::vector<PhotoSceneObject> built;
    if (!prebuilt) built = buildPhotoScene(scene, po);
    const std::vector<PhotoSceneObject>& objects = prebuilt ? *prebuilt : built;
    if (vertexSeconds) *vertexSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    RenderResult out = blankResult(cam);
    const int threads = renderThreads(scene.settings);
    const bool panorama = cam.projection == Camera::Projection::Panorama;
    const double period = cam.width * 360.0 / cam.fovXDeg;
    FirstError errors;
#pragma omp parallel num_threads(threads)
    {
        errors.run([&] {
            // Each thread owns a band of rows: no two threads write the same pixel.
            const int n = omp_get_num_threads(), id = omp_get_thread_num();
            const int row0 = cam.height * id / n, row1 = cam.height * (id + 1) / n;
            for (const PhotoSceneObject& obj : objects) {
                for (const PhotoSceneLayer& layer : obj.layers) {
                    std::vector<ScreenVertex> sv(layer.vertices.size());
                    for (std::size_t k = 0; k < sv.size(); ++k) {
                        const godel::VertexImage& vi = layer.vertices[k];
                        if (!vi.valid) continue;
                        sv[k].ok = cam.project(vi.direction, sv[k].x, sv[k].y);
                        sv[k].depth = vi.lambda;
                        sv[k].t = vi.emissionTime;
                        sv[k].u = obj.uv[k](0);
                        sv[k].v = obj.uv[k](1);
                        sv[k].f = layer.frequencyRatio[k];
                    }
                    for (const auto& t : layer.triangles) {
                        ScreenVertex tri[3] = {sv[t[0]], sv[t[1]], sv[t[2]]};
                        if (!tri[0].ok || !tri[1].ok || !tri[2].ok) continue;
                        // Panorama seam: a triangle straddling +-180 degrees is drawn on both sides.
                        const double span =
                            std::max({tri[0].x, tri[1].x, tri[2].x}) - std::min({tri[0].x, tri[1].x, tri[2].x});
                        // Texture seam: keep u continuous across the triangle.
                        const double umax = std::max({tri[0].u, tri[1].u, tri[2].u});
                        for (auto& v : tri)
                            if (umax - v.u > 0.5) v.u += 1;
                        // The azimuth wraps every 360 degrees: cam.width px only for a full panorama.
                        if (panorama && span > 0.5 * period) {
                            for (auto& v : tri)
                                if (v.x < 0.5 * cam.width) v.x += period;
                            rasterise(tri, obj.sceneIndex, row0, row1, out);
                            for (auto& v : tri) v.x -= period;
                        }
                        rasterise(tri, obj.sceneIndex, row0, row1, out);
                    }
                }
            }
        });
    }
    errors.rethrow();
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
    if (progress) progress(1.0);
    return out;
}

}  // namespace lc
