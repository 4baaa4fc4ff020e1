// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the special-relativity algorithms share: a triangle mesh at rest in its moving frame as
// vtkPolyData and as lc::sr::TriMesh (the core's).
#include "core/sr/mesh.hpp"

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace lc::views {

// The mesh of the input: points, point normals (the active normals or "Normals", made unit; a
// zero normal stays zero, as lc::sr::RestTriangle::fromMesh takes it) and the triangles. Throws
// std::invalid_argument naming what is wrong: a cell that is not a triangle (triangulate first,
// e.g. vtkTriangleFilter), no point normals (vtkPolyDataNormals), a point id out of range, a
// non-finite point or normal used by a triangle.
sr::TriMesh srTriMesh(vtkPolyData* mesh);

// The inverse, for the renderer: a mesh without normals is given its flat face normals, each
// triangle then owning its three vertices (the shading of lc::sr::RestTriangle::fromMesh).
vtkSmartPointer<vtkPolyData> srMeshPolyData(const sr::TriMesh& mesh);

}  // namespace lc::views
