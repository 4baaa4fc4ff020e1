#pragma once
// Mesh files are checked before VTK's readers see them: those readers trust the file, and a face
// naming a vertex that does not exist (OBJ `f 1 2 99999`) or a negative PLY list length crashes
// them or the filters after them. The checks walk the file once, in the format's own terms, and
// throw std::runtime_error naming the line (OBJ, ASCII PLY) or element (binary PLY) at fault.
#include <string>

namespace lc::io {

// Regular file within input::kMeshFileBytes; for .obj and .ply also every index in range, every
// list length in [3, 65536], counts within input::kMeshVertices / kMeshTriangles, coordinates
// finite, and the file long enough for what its header promises; for binary .stl the size that
// its triangle count implies.
void checkMeshFile(const std::string& path);

}  // namespace lc::io
