// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeMeshLoader_h
#define vtkLightconeMeshLoader_h
// Triangle meshes for scene files (OBJ, PLY, STL by lc::io::readPolygonMesh, VTP by VTK), triangulated,
// with point normals. Plugs into lc::io::SceneReadOptions::meshLoader.
#include "core/scene/scene.hpp"

#include <string>

class vtkPolyData;

namespace lc::io {

// Throws std::runtime_error naming the file and what is wrong (unknown extension, unreadable,
// no triangles).
void loadMeshWithVtk(const std::string& path, MeshObject& into);

// The geometry of a MeshObject as vtkPolyData (for filters and rendering).
void meshToPolyData(const MeshObject& mesh, vtkPolyData* out);

}  // namespace lc::io

#endif
