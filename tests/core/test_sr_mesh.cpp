// SPDX-License-Identifier: BSD-3-Clause
// The SR renderer's meshes: closed, outward, subdivided (core/sr/mesh).
#include <gtest/gtest.h>

#include <cmath>

#include "core/sr/mesh.hpp"

using namespace lc;
using namespace lc::sr;

TEST(SrMesh, CubeIsClosedOutwardAndSubdivided) {
    const int n = 5;
    const TriMesh m = makeCube(2.0, n, Vec3(1, 2, 3));
    EXPECT_EQ(m.triangles.size(), 6u * 2u * n * n);  // seed 003: 50 triangles per face
    double area = 0.0;
    for (const auto& t : m.triangles) {
        const Vec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
        const Vec3 cr = (b - a).cross(c - a);
        area += 0.5 * cr.norm();
        EXPECT_GT(cr.normalized().dot(m.normals[t[0]]), 0.999);                    // counter-clockwise outside
        EXPECT_GT(((a + b + c) / 3.0 - Vec3(1, 2, 3)).dot(m.normals[t[0]]), 0.0);  // normal points out
    }
    EXPECT_NEAR(area, 6.0 * 4.0, 1e-12);
    for (const Vec3& p : m.positions) EXPECT_NEAR((p - Vec3(1, 2, 3)).cwiseAbs().maxCoeff(), 1.0, 1e-14);
}

TEST(SrMesh, UvSphereIsOnTheSphereAndOutward) {
    const TriMesh m = makeUvSphere(2.5, 24, 12);
    EXPECT_EQ(m.triangles.size(), 2u * 24u * 11u);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_NEAR(m.positions[i].norm(), 2.5, 1e-12);
        EXPECT_LT((m.normals[i] - m.positions[i] / 2.5).norm(), 1e-12);
    }
    double volume = 0.0;  // divergence theorem: outward winding gives a positive volume
    for (const auto& t : m.triangles) volume += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6.0;
    EXPECT_GT(volume, 0.95 * 4.0 / 3.0 * kPi * std::pow(2.5, 3));
    EXPECT_LT(volume, 4.0 / 3.0 * kPi * std::pow(2.5, 3));
}
