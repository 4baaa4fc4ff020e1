// SPDX-License-Identifier: BSD-3-Clause
#include "core/godel/photo_object.hpp"

#include "core/numerics/parallel.hpp"

#include <cmath>
#include <sstream>

#ifdef _OPENMP
#include <omp.h>
#else
inline int omp_get_max_threads() { return 1; }
#endif

namespace lc::godel {

PhotoObjectBuilder::PhotoObjectBuilder(double a, const Vec4& observerEvent)
    : a_(a), toObserver_(Isometry::observerToOrigin(a, observerEvent)), solver_(a) {}

PhotoObject PhotoObjectBuilder::build(const Mesh& mesh, const Vec4& centre, const PhotoObjectOptions& opt) const {
    return build(mesh, Isometry::movingOriginTo(a_, centre), opt);
}

PhotoObject PhotoObjectBuilder::build(const Mesh& mesh, const Isometry& placement,
                                      const PhotoObjectOptions& opt) const {
    PhotoObject po;
    const int nv = int(mesh.vertices.size());
    for (const auto& tri : mesh.triangles)
        for (int v : tri)
            if (v < 0 || v >= nv) {
                std::ostringstream os;
                os << "triangle index " << v << " outside 0.." << nv - 1;
                po.status = PhotoStatus::InvalidMesh;
                po.message = os.str();
                return po;
            }
    const int N = std::max(0, opt.maxWinding);
    po.layers.resize(2 * (N + 1));
    for (int n = 0; n <= N; ++n)
        for (int b = 0; b < 2; ++b) {
            PhotoLayer& L = po.layers[2 * n + b];
            L.winding = n;
            L.branch = b ? Branch::Inbound : Branch::Outbound;
            L.vertices.assign(nv, VertexImage{});
        }
    po.observerChart.assign(nv, Vec4::Zero());
    std::vector<char> beyond(nv, 0);
    const Isometry M = toObserver_ * placement;  // centre-at-origin chart -> observer chart
    ImageOptions io;
    io.maxWinding = N;
    io.k0 = -1;
    io.tObserver = 0;
    const int threads = opt.threads > 0 ? opt.threads : omp_get_max_threads();
    // Vertices are independent: each thread writes only its own vertex slots.
    FirstError errors;
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
    for (int i = 0; i < nv; ++i) {
        errors.run([&] {
            const Vec3& v = mesh.vertices[i];
            const Vec4 x = M.apply(Vec4(0, v(0), v(1), v(2)));
            po.observerChart[i] = x;
            const ImageSolver::Point P = solver_.prepare(x.segment<3>(1));
            if (P.status != ImageStatus::Ok) {
                beyond[i] = 1;
                return;
            }
            std::optional<Image> out[2];
            for (int n = 0; n <= N; ++n) {
                if (solver_.solveWinding(P, n, io, out) == 0) continue;
                for (int b = 0; b < 2; ++b) {
                    if (!out[b]) continue;
                    VertexImage& vi = po.layers[2 * n + b].vertices[i];
                    vi.valid = true;
                    vi.direction = out[b]->direction;
                    vi.lambda = out[b]->lambda;
                    vi.emissionTime = out[b]->emissionTime;
                }
            }
        });
    }
    errors.rethrow();
    for (int i = 0; i < nv; ++i)
        if (beyond[i]) po.beyondHorizon.push_back(i);
    for (int n = 0; n <= N; ++n) {
        PhotoLayer& out = po.layers[2 * n];
        PhotoLayer& in = po.layers[2 * n + 1];
        if (opt.stitch) {
            po.weldedVertices += stitchWinding(mesh, out, in);
        } else {
            for (PhotoLayer* L : {&out, &in})
                for (const auto& t : mesh.triangles)
                    if (L->vertices[t[0]].valid && L->vertices[t[1]].valid && L->vertices[t[2]].valid)
                        L->triangles.push_back(t);
        }
    }
    if (!po.beyondHorizon.empty()) {
        std::ostringstream os;
        os << po.beyondHorizon.size() << " of " << nv << " vertices are beyond the observer's Goedel horizon";
        po.message = os.str();
    }
    return po;
}

int stitchWinding(const Mesh& mesh, PhotoLayer& out, PhotoLayer& in) {
    const std::size_t nv = mesh.vertices.size();
    int welded = 0;
    // One branch only (e.g. a ring slot on the axis): take the other branch's image.
    for (std::size_t i = 0; i < nv; ++i) {
        VertexImage &o = out.vertices[i], &n = in.vertices[i];
        if (o.valid != n.valid) {
            VertexImage& missing = o.valid ? n : o;
            missing = o.valid ? o : n;
            missing.welded = true;
            ++welded;
        }
    }
    // Keep triangles with three images; mark the vertices of kept and of dropped triangles.
    std::vector<char> inKept(nv, 0), inDropped(nv, 0);
    out.triangles.clear();
    in.triangles.clear();
    for (const auto& t : mesh.triangles) {
        const bool ok = out.vertices[t[0]].valid && out.vertices[t[1]].valid && out.vertices[t[2]].valid;
        for (int v : t) (ok ? inKept : inDropped)[v] = 1;
        if (ok) {
            out.triangles.push_back(t);
            in.triangles.push_back(t);
        }
    }
    // Rim vertices (in kept and dropped triangles, imaged): weld the two branches together.
    for (std::size_t i = 0; i < nv; ++i) {
        VertexImage &o = out.vertices[i], &n = in.vertices[i];
        if (!(inKept[i] && inDropped[i] && o.valid) || (o.welded && n.welded)) continue;
        Vec3 d = o.direction + n.direction;
        d = d.norm() > 0 ? Vec3(d.normalized()) : o.direction;
        VertexImage w;
        w.valid = true;
        w.welded = true;
        w.direction = d;
        w.lambda = 0.5 * (o.lambda + n.lambda);
        w.emissionTime = 0.5 * (o.emissionTime + n.emissionTime);
        o = w;
        n = w;
        ++welded;
    }
    return welded;
}

Mesh uvSphere(double R, int nLat, int nLon) {
    Mesh m;
    nLat = std::max(nLat, 2);
    nLon = std::max(nLon, 3);
    m.vertices.push_back(Vec3(0, 0, R));
    for (int i = 1; i < nLat; ++i) {
        const double th = kPi * i / nLat;
        for (int j = 0; j < nLon; ++j) {
            const double ph = 2 * kPi * j / nLon;
            m.vertices.push_back(R * Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)));
        }
    }
    m.vertices.push_back(Vec3(0, 0, -R));
    const int south = int(m.vertices.size()) - 1;
    auto idx = [&](int ring, int j) { return 1 + ring * nLon + (j % nLon); };
    for (int j = 0; j < nLon; ++j) m.triangles.push_back({0, idx(0, j), idx(0, j + 1)});
    for (int i = 0; i + 1 < nLat - 1; ++i)
        for (int j = 0; j < nLon; ++j) {
            m.triangles.push_back({idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)});
            m.triangles.push_back({idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)});
        }
    for (int j = 0; j < nLon; ++j) m.triangles.push_back({south, idx(nLat - 2, j + 1), idx(nLat - 2, j)});
    return m;
}

}  // namespace lc::godel
