// SPDX-License-Identifier: BSD-3-Clause
#include "sr_mesh.hpp"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lc::views {

sr::TriMesh srTriMesh(vtkPolyData* mesh) {
    sr::TriMesh out;
    if (!mesh) return out;
    if (mesh->GetNumberOfStrips() > 0)
        throw std::invalid_argument("the mesh has triangle strips: triangulate first (vtkTriangleFilter)");
    vtkDataArray* normals = mesh->GetPointData()->GetNormals();
    if (!normals) normals = mesh->GetPointData()->GetArray("Normals");
    const vtkIdType np = mesh->GetNumberOfPoints();
    if (np > 0 && (!normals || normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != np))
        throw std::invalid_argument("the mesh has no point normals (3 components per point; vtkPolyDataNormals)");
    out.positions.resize(static_cast<std::size_t>(np));
    out.normals.resize(static_cast<std::size_t>(np));
    for (vtkIdType i = 0; i < np; ++i) {
        double p[3], n[3];
        mesh->GetPoint(i, p);
        normals->GetTuple(i, n);
        out.positions[static_cast<std::size_t>(i)] = Vec3(p[0], p[1], p[2]);
        // As given, like lc::sr::RestTriangle::fromMesh: vtkPolyDataNormals leaves (0, 0, 0) on
        // unused points and degenerate faces, which SrRenderer draws too.
        const Vec3 nv(n[0], n[1], n[2]);
        out.normals[static_cast<std::size_t>(i)] = nv.norm() > 0 ? nv.normalized() : nv;
    }
    vtkCellArray* polys = mesh->GetPolys();
    if (!polys) return out;
    out.triangles.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()));
    vtkNew<vtkIdList> ids;
    vtkIdType cell = 0;
    for (polys->InitTraversal(); polys->GetNextCell(ids); ++cell) {
        if (ids->GetNumberOfIds() != 3)
            throw std::invalid_argument("polygon " + std::to_string(cell) + " has " +
                                        std::to_string(ids->GetNumberOfIds()) +
                                        " points, not 3: triangulate first (vtkTriangleFilter)");
        std::array<int, 3> t{};
        for (int k = 0; k < 3; ++k) {
            const vtkIdType v = ids->GetId(k);
            if (v < 0 || v >= np)
                throw std::invalid_argument("polygon " + std::to_string(cell) + " refers to point " +
                                            std::to_string(v) + " of " + std::to_string(np));
            // Only what a triangle uses must be finite: unused points may hold anything.
            const std::size_t u = static_cast<std::size_t>(v);
            if (!out.positions[u].allFinite() || !out.normals[u].allFinite())
                throw std::invalid_argument("point " + std::to_string(v) + " or its normal is not finite");
            t[static_cast<std::size_t>(k)] = static_cast<int>(v);
        }
        out.triangles.push_back(t);
    }
    return out;
}

vtkSmartPointer<vtkPolyData> srMeshPolyData(const sr::TriMesh& mesh) {
    const bool shared = !mesh.normals.empty();
    const vtkIdType np =
        shared ? static_cast<vtkIdType>(mesh.positions.size()) : 3 * static_cast<vtkIdType>(mesh.triangles.size());
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(np);
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(np);
    vtkNew<vtkCellArray> cells;
    cells->AllocateExact(static_cast<vtkIdType>(mesh.triangles.size()), np);
    if (shared) {
        for (vtkIdType i = 0; i < np; ++i) {
            points->SetPoint(i, mesh.positions[static_cast<std::size_t>(i)].data());
            normals->SetTuple(i, mesh.normals[static_cast<std::size_t>(i)].data());
        }
        for (const auto& t : mesh.triangles) {
            const vtkIdType c[3] = {t[0], t[1], t[2]};
            cells->InsertNextCell(3, c);
        }
    } else {
        vtkIdType v = 0;
        for (const auto& t : mesh.triangles) {
            const Vec3& a = mesh.positions[static_cast<std::size_t>(t[0])];
            const Vec3& b = mesh.positions[static_cast<std::size_t>(t[1])];
            const Vec3& c = mesh.positions[static_cast<std::size_t>(t[2])];
            const Vec3 n = (b - a).cross(c - a).normalized();
            const vtkIdType ids[3] = {v, v + 1, v + 2};
            for (const Vec3* p : {&a, &b, &c}) {
                points->SetPoint(v, p->data());
                normals->SetTuple(v++, n.data());
            }
            cells->InsertNextCell(3, ids);
        }
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetPolys(cells);
    poly->GetPointData()->SetNormals(normals);
    return poly;
}

}  // namespace lc::views
