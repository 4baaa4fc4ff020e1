// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeMeshLoader.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataReader.h>

#include "core/input/ranges.hpp"
#include "readers/io/file_extension.hpp"
#include "readers/io/mesh_file.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lc::io {

namespace {

// What VTK's readers produced, checked before any filter builds cell links from it: every point
// id of every cell inside the point list, every coordinate finite, counts within the limits.
void checkReaderOutput(vtkPolyData* pd) {
    if (!pd) throw std::runtime_error("the reader produced no mesh");
    const vtkIdType np = pd->GetNumberOfPoints();
    if (np > input::kMeshVertices.max)
        throw std::runtime_error(std::to_string(np) + " vertices, over the limit of " +
                                 input::formatBound(input::kMeshVertices.max));
    for (vtkIdType i = 0; i < np; ++i) {
        double p[3];
        pd->GetPoint(i, p);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throw std::runtime_error("vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
    const vtkIdType minimumSize[4] = {1, 2, 3, 3};  // verts, lines, polys, strips
    int kind = 0;
    for (vtkCellArray* cells : {pd->GetVerts(), pd->GetLines(), pd->GetPolys(), pd->GetStrips()}) {
        const vtkIdType minimum = minimumSize[kind++];
        if (!cells) continue;
        // Offsets monotonic and matching the ids (a corrupt VTP strip crashed vtkTriangleFilter).
        if (!cells->IsValid()) throw std::runtime_error("the cells' offsets and point ids disagree (corrupt file)");
        for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
            if (cells->GetCellSize(c) < minimum)
                throw std::runtime_error("a cell has " + std::to_string(cells->GetCellSize(c)) +
                                         " points, fewer than its type needs");
        const vtkIdType n = cells->GetNumberOfConnectivityIds();
        for (vtkIdType k = 0; k < n; ++k) {
            const vtkIdType id = cells->GetConnectivityArray()->GetComponent(k, 0);
            if (id < 0 || id >= np)
                throw std::runtime_error("a cell refers to vertex " + std::to_string(id) + " but the mesh has " +
                                         std::to_string(np));
        }
    }
}

// Our own walker's polygons as vtkPolyData: every index already checked against the points.
vtkSmartPointer<vtkPolyData> polygonsToPolyData(const PolygonMesh& mesh) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.points.size()));
    for (std::size_t i = 0; i < mesh.points.size(); ++i)
        points->SetPoint(static_cast<vtkIdType>(i), mesh.points[i].data());
    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfValues(static_cast<vtkIdType>(mesh.offsets.size()));
    for (std::size_t i = 0; i < mesh.offsets.size(); ++i) offsets->SetValue(static_cast<vtkIdType>(i), mesh.offsets[i]);
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(mesh.corners.size()));
    for (std::size_t i = 0; i < mesh.corners.size(); ++i)
        connectivity->SetValue(static_cast<vtkIdType>(i), mesh.corners[i]);
    vtkNew<vtkCellArray> polys;
    polys->SetData(offsets, connectivity);
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(points);
    pd->SetPolys(polys);
    return pd;
}

// A VTP through VTK's XML reader, after checkVtpFile, and its output checked.
vtkSmartPointer<vtkPolyData> readVtp(const std::string& path) {
    checkVtpFile(path);  // the attributes VTK sizes its arrays from
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    try {
        reader->Update();
    } catch (const std::bad_alloc&) {  // a corrupt array size (fuzz_mesh_loader: a VTP asking for 64 GiB)
        throw std::runtime_error("the file asks for more memory than there is (corrupt array sizes?)");
    }
    if (reader->GetErrorCode() != 0) throw std::runtime_error("the reader failed (corrupt or unreadable file)");
    vtkPolyData* raw = reader->GetOutput();
    checkReaderOutput(raw);
    if (raw->GetNumberOfPoints() == 0)
        throw std::runtime_error(
            "no triangles in the file (the reader found nothing it could read: corrupt or unreadable?)");
    if (raw->GetNumberOfPolys() + raw->GetNumberOfStrips() == 0) throw std::runtime_error("no triangles in the file");
    return raw;
}

}  // namespace

void loadMeshWithVtk(const std::string& path, MeshObject& into) {
    // OBJ, PLY and STL by our own walkers (VTK 9.1's readers crash on hostile files), VTP by VTK.
    const vtkSmartPointer<vtkPolyData> raw =
        lowerCaseExtension(path) == ".vtp" ? readVtp(path) : polygonsToPolyData(readPolygonMesh(path));
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(raw);
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(triangles->GetOutputPort());
    normals->SplittingOff();
    normals->ConsistencyOn();
    normals->AutoOrientNormalsOn();  // closed meshes: outward, whatever the file's winding
    normals->Update();
    vtkPolyData* pd = normals->GetOutput();
    if (!pd || pd->GetNumberOfPolys() == 0) throw std::runtime_error("no triangles in the file");
    vtkDataArray* n = pd->GetPointData()->GetNormals();
    into.positions.clear();
    into.normals.clear();
    into.triangles.clear();
    for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i) {
        double p[3];
        pd->GetPoint(i, p);
        into.positions.emplace_back(p[0], p[1], p[2]);
        double nn[3] = {0, 0, 1};
        if (n) n->GetTuple(i, nn);
        into.normals.emplace_back(nn[0], nn[1], nn[2]);
    }
    vtkCellArray* polys = pd->GetPolys();
    vtkNew<vtkIdList> ids;
    polys->InitTraversal();
    while (polys->GetNextCell(ids))
        if (ids->GetNumberOfIds() == 3)
            into.triangles.push_back(
                {static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(1)), static_cast<int>(ids->GetId(2))});
    if (into.triangles.empty()) throw std::runtime_error("no triangles in the file");
    if (static_cast<double>(into.triangles.size()) > input::kMeshTriangles.max)
        throw std::runtime_error(std::to_string(into.triangles.size()) + " triangles, over the limit of " +
                                 input::formatBound(input::kMeshTriangles.max));
}

void meshToPolyData(const MeshObject& mesh, vtkPolyData* out) {
    vtkNew<vtkPoints> pts;
    pts->SetDataTypeToDouble();
    vtkNew<vtkFloatArray> normals;
    normals->SetNumberOfComponents(3);
    normals->SetName("Normals");
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        pts->InsertNextPoint(mesh.positions[i].data());
        const Vec3 n = i < mesh.normals.size() ? mesh.normals[i] : Vec3(0, 0, 1);
        normals->InsertNextTuple3(n(0), n(1), n(2));
    }
    vtkNew<vtkCellArray> cells;
    for (const auto& t : mesh.triangles) {
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        cells->InsertNextCell(3, ids);
    }
    out->SetPoints(pts);
    out->SetPolys(cells);
    out->GetPointData()->SetNormals(normals);
}

}  // namespace lc::io
