// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Mesh files read by our own walkers, not by VTK's readers: VTK 9.1's OBJ, PLY and STL readers
// trust the file, and fuzz_mesh_loader found five classes of crash in them (a face naming a
// vertex that does not exist, a negative PLY list length, a PLY line without its newline, ...).
// Each walker reads the file once, in the format's own terms, checks every index, count and
// coordinate, and throws std::runtime_error naming the line (OBJ, ASCII PLY, ASCII STL) or the
// element (binary PLY and STL) at fault. VTP stays with VTK's XML reader, after checkVtpFile.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace lc::io {

// Polygons as VTK's cell arrays hold them: polygon i has the corners
// corners[offsets[i]] .. corners[offsets[i+1] - 1], each an index into points.
struct PolygonMesh {
    std::vector<std::array<double, 3>> points;
    std::vector<std::int64_t> offsets{0};
    std::vector<std::int64_t> corners;
    std::size_t polygonCount() const { return offsets.size() - 1; }
};

// .obj, .ply or .stl: a regular file within input::kMeshFileBytes, every index in range, every
// list length in [3, 65536], counts within input::kMeshVertices / kMeshTriangles, coordinates
// finite, and the file long enough for what its header promises. Vertices of an STL that share
// coordinates are merged (STL repeats them per facet). OBJ texture coordinates and normals are
// checked but not kept: the loader computes normals from the surface.
PolygonMesh readPolygonMesh(const std::string& path);

// .vtp: the Piece and DataArray attributes VTK's XML reader sizes its arrays from.
void checkVtpFile(const std::string& path);

// Any of the four formats by extension, the mesh discarded (the hostile-input tests).
void checkMeshFile(const std::string& path);

}  // namespace lc::io
