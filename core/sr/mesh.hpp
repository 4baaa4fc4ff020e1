// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Triangle meshes for SR scenes (positions in the object's rest frame S').
#include <array>
#include <vector>

#include "core/numerics/types.hpp"

namespace lc::sr {

struct TriMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // one per position, unit
    std::vector<std::array<int, 3>> triangles;
};

// Axis-aligned cube of edge length `edge`, each face split into n x n squares of two
// triangles (2 n^2 triangles per face; n = 5 and 10 give seed 003's 50 and 200 per face).
// Faces do not share vertices, so normals are the flat face normals.
TriMesh makeCube(double edge, int n, const Vec3& centre = Vec3::Zero());

// UV sphere: `slices` around the polar (z) axis, `stacks` from pole to pole; smooth normals.
TriMesh makeUvSphere(double radius, int slices, int stacks, const Vec3& centre = Vec3::Zero());

}  // namespace lc::sr
