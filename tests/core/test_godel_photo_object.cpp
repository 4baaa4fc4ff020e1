// SPDX-License-Identifier: BSD-3-Clause
// Per-vertex photo-objects: every vertex image lands on the placed vertex (forward closed form),
// horizon bookkeeping against a direct radius check, stitching rules, threads, degenerate meshes.
#include "core/godel/photo_object.hpp"

#include <gtest/gtest.h>

using namespace lc;
using namespace lc::godel;

namespace {
void expectLayersLand(const PhotoObject& po, const Mesh& m, double a) {
    for (const PhotoLayer& L : po.layers)
        for (std::size_t i = 0; i < m.vertices.size(); ++i) {
            const VertexImage& v = L.vertices[i];
            if (!v.valid || v.welded) continue;
            // Direction (psi, phi0) -> closed-form past-directed ray; after lambda it is at the vertex.
            const double psi = std::acos(std::clamp(v.direction(2), -1.0, 1.0));
            const double phi0 = std::atan2(v.direction(1), v.direction(0));
            const Vec4 x =
                OriginGeodesic::nullFromDirection(a, v.direction(2), std::sin(psi), phi0, -1).cartesian(v.lambda);
            EXPECT_LT((x.segment<3>(1) - po.observerChart[i].segment<3>(1)).norm(), 1e-9)
                << "vertex " << i << " winding " << L.winding;
            EXPECT_NEAR(x(0), v.emissionTime, 1e-9);
        }
}
}  // namespace

TEST(GodelPhotoObject, SphereImagesLandOnTheirVertices) {
    const double a = 1.0;
    const PhotoObjectBuilder B(a, Vec4(0.5, 0.3, -0.2, 0.1));
    const Mesh m = uvSphere(0.2, 8, 12);
    PhotoObjectOptions o;
    o.maxWinding = 2;
    const PhotoObject po = B.build(m, Vec4(0, -0.4, 0.5, 0.3), o);
    ASSERT_EQ(po.status, PhotoStatus::Ok);
    EXPECT_TRUE(po.beyondHorizon.empty());
    ASSERT_EQ(po.layers.size(), 6u);
    expectLayersLand(po, m, a);
    // Fully inside: every vertex imaged, every triangle kept, nothing welded.
    for (const PhotoLayer& L : po.layers) {
        EXPECT_EQ(L.triangles.size(), m.triangles.size());
        for (const VertexImage& v : L.vertices) EXPECT_TRUE(v.valid);
    }
    EXPECT_EQ(po.weldedVertices, 0);
    // Homogeneity: the placed vertex sits at chart distance |v| from the centre in the centre's
    // own chart (map it back with the isometry that moves the centre to the origin).
    const Isometry back = Isometry::movingToOrigin(a, Vec4(0, -0.4, 0.5, 0.3)) *
                          Isometry::observerToOrigin(a, Vec4(0.5, 0.3, -0.2, 0.1)).inverse();
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
        EXPECT_LT((back.apply(po.observerChart[i]).segment<3>(1) - m.vertices[i]).norm(), 1e-12);
}

TEST(GodelPhotoObject, PartlyBeyondTheHorizon) {
    const double a = 1.0;
    const PhotoObjectBuilder B(a, Vec4::Zero());
    const Mesh m = uvSphere(0.5, 16, 24);
    PhotoObjectOptions o;
    o.maxWinding = 1;
    const Vec4 centre(0, 1.8, 0, 0);  // straddles r = 2a
    const PhotoObject po = B.build(m, centre, o);
    ASSERT_EQ(po.status, PhotoStatus::Ok);
    ASSERT_FALSE(po.beyondHorizon.empty());
    EXPECT_FALSE(po.message.empty());
    // Oracle: the radius of each placed vertex.
    std::vector<char> beyond(m.vertices.size(), 0);
    for (int i : po.beyondHorizon) beyond[i] = 1;
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
        const double r = po.observerChart[i].segment<2>(1).norm();
        EXPECT_EQ(bool(beyond[i]), r >= 2 * a) << i;
        for (const PhotoLayer& L : po.layers) {
            if (beyond[i]) {
                EXPECT_FALSE(L.vertices[i].valid);
            }
        }
    }
    // Dropped triangles are exactly those touching a vertex without an image.
    for (const PhotoLayer& L : po.layers) {
        EXPECT_LT(L.triangles.size(), m.triangles.size());
        for (const auto& t : L.triangles)
            for (int v : t) EXPECT_TRUE(L.vertices[v].valid);
    }
    // Welded rim vertices share one image in both branches, the normalised mean of the two.
    EXPECT_GT(po.weldedVertices, 0);
    const ImageSolver solver(a);
    ImageOptions io;
    io.maxWinding = 1;
    for (int n = 0; n <= 1; ++n) {
        const PhotoLayer& O = po.layer(n, Branch::Outbound);
        const PhotoLayer& I = po.layer(n, Branch::Inbound);
        for (std::size_t i = 0; i < m.vertices.size(); ++i) {
            if (!O.vertices[i].welded) continue;
            EXPECT_LT((O.vertices[i].direction - I.vertices[i].direction).norm(), 1e-15);
            const ImageSolver::Point P = solver.prepare(po.observerChart[i].segment<3>(1));
            std::optional<Image> im[2];
            ASSERT_EQ(solver.solveWinding(P, n, io, im), 2);
            EXPECT_LT((O.vertices[i].direction - (im[0]->direction + im[1]->direction).normalized()).norm(), 1e-12);
            EXPECT_NEAR(O.vertices[i].lambda, 0.5 * (im[0]->lambda + im[1]->lambda), 1e-12);
        }
    }
    expectLayersLand(po, m, a);
}

TEST(GodelPhotoObject, TallObjectLosesLowWindingsAndIsStitched) {
    // A tall thin object: its top is too high for winding 0 (|z| > Zpk), its bottom is not.
    const double a = 1.0;
    const PhotoObjectBuilder B(a, Vec4::Zero());
    Mesh m;
    const int rows = 60;
    for (int i = 0; i <= rows; ++i) {
        const double z = 6.0 * i / rows;
        m.vertices.push_back(Vec3(-0.05, 0, z));
        m.vertices.push_back(Vec3(0.05, 0, z));
    }
    for (int i = 0; i < rows; ++i) {
        m.triangles.push_back({2 * i, 2 * i + 1, 2 * i + 3});
        m.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 2});
    }
    PhotoObjectOptions o;
    o.maxWinding = 0;
    const PhotoObject po = B.build(m, Vec4(0, 1.0, 0, 0), o);
    const PhotoLayer& O = po.layer(0, Branch::Outbound);
    int imaged = 0;
    for (const VertexImage& v : O.vertices) imaged += v.valid;
    EXPECT_GT(imaged, 0);
    EXPECT_LT(imaged, int(m.vertices.size()));
    EXPECT_GT(po.weldedVertices, 0);
    EXPECT_LT(O.triangles.size(), m.triangles.size());
    EXPECT_GT(O.triangles.size(), 0u);
    // Without stitching nothing is welded, and rim images differ between branches.
    o.stitch = false;
    EXPECT_EQ(B.build(m, Vec4(0, 1.0, 0, 0), o).weldedVertices, 0);
}

TEST(GodelPhotoObject, ThreadsGiveIdenticalResults) {
    const double a = 1.0;
    const PhotoObjectBuilder B(a, Vec4(0, 0.2, 0.1, 0));
    const Mesh m = uvSphere(0.6, 30, 40);
    PhotoObjectOptions o;
    o.maxWinding = 2;
    o.threads = 1;
    const PhotoObject p1 = B.build(m, Vec4(0, 1.2, 0.3, 0.5), o);
    o.threads = 2;
    const PhotoObject p2 = B.build(m, Vec4(0, 1.2, 0.3, 0.5), o);
    ASSERT_EQ(p1.layers.size(), p2.layers.size());
    for (std::size_t l = 0; l < p1.layers.size(); ++l) {
        EXPECT_EQ(p1.layers[l].triangles, p2.layers[l].triangles);
        for (std::size_t i = 0; i < m.vertices.size(); ++i) {
            EXPECT_EQ(p1.layers[l].vertices[i].valid, p2.layers[l].vertices[i].valid);
            EXPECT_EQ(p1.layers[l].vertices[i].direction, p2.layers[l].vertices[i].direction);
            EXPECT_EQ(p1.layers[l].vertices[i].lambda, p2.layers[l].vertices[i].lambda);
        }
    }
    EXPECT_EQ(p1.beyondHorizon, p2.beyondHorizon);
}

TEST(GodelPhotoObject, DegenerateMeshes) {
    const double a = 1.0;
    const PhotoObjectBuilder B(a, Vec4::Zero());
    // Empty.
    const PhotoObject e = B.build(Mesh{}, Vec4(0, 0.5, 0, 0));
    EXPECT_EQ(e.status, PhotoStatus::Ok);
    for (const PhotoLayer& L : e.layers) {
        EXPECT_TRUE(L.vertices.empty());
        EXPECT_TRUE(L.triangles.empty());
    }
    // Zero-area triangles, duplicate vertices, a vertex exactly on the observer's axis.
    Mesh d;
    d.vertices = {Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0.2, 0, 0), Vec3(0.1, 0, 0)};
    d.triangles = {{0, 1, 2}, {2, 3, 4}, {0, 0, 0}, {1, 3, 4}};
    const PhotoObject p = B.build(d, Isometry::zShift(a, 0.4));  // vertex 0, 1 on the axis at z = 0.4
    ASSERT_EQ(p.status, PhotoStatus::Ok);
    for (const PhotoLayer& L : p.layers)
        for (const VertexImage& v : L.vertices)
            if (v.valid) {
                EXPECT_TRUE(v.direction.allFinite());
                EXPECT_TRUE(std::isfinite(v.lambda));
            }
    // Duplicates get identical images.
    for (const PhotoLayer& L : p.layers) {
        EXPECT_EQ(L.vertices[2].direction, L.vertices[4].direction);
        EXPECT_EQ(L.vertices[0].valid, L.vertices[1].valid);
    }
    // Out-of-range index: reported, not UB.
    Mesh bad = d;
    bad.triangles.push_back({0, 1, 7});
    const PhotoObject pb = B.build(bad, Vec4(0, 0.5, 0, 0));
    EXPECT_EQ(pb.status, PhotoStatus::InvalidMesh);
    EXPECT_FALSE(pb.message.empty());
    // Whole mesh beyond the horizon.
    const PhotoObject far = B.build(uvSphere(0.1, 4, 6), Vec4(0, 3.0, 0, 0));
    EXPECT_EQ(far.beyondHorizon.size(), uvSphere(0.1, 4, 6).vertices.size());
    for (const PhotoLayer& L : far.layers) EXPECT_TRUE(L.triangles.empty());
}
