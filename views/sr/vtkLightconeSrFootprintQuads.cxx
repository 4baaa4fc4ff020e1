// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeSrFootprintQuads.h"

#include "offscreen_parts.hpp"
#include "source_checks.hpp"
#include "sr_mesh.hpp"

#include "core/numerics/parallel.hpp"
#include "core/sr/local_ray_tracing.hpp"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>
#include <exception>
#include <vector>

vtkStandardNewMacro(vtkLightconeSrFootprintQuads);

vtkLightconeSrFootprintQuads::vtkLightconeSrFootprintQuads() { this->SetNumberOfInputPorts(1); }

int vtkLightconeSrFootprintQuads::FillInputPortInformation(int, vtkInformation* info) {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    return 1;
}

void vtkLightconeSrFootprintQuads::SetCamera(const lc::sr::ObserverCamera& camera) {
    if (camera == this->Camera) return;
    this->Camera = camera;
    this->Modified();
}

namespace {

// Every triangle's apparent footprint on the screen (both cores); throws the first failure.
std::vector<lc::sr::ApparentFootprint> apparentFootprints(const lc::sr::TriMesh& mesh, const lc::sr::MovingFrame& frame,
                                                          const lc::Vec4& observer, const lc::sr::ObserverCamera& cam) {
    const long n = static_cast<long>(mesh.triangles.size());
    std::vector<lc::sr::ApparentFootprint> footprints(static_cast<std::size_t>(n));
    lc::FirstError errors;
#pragma omp parallel for schedule(dynamic, 64)
    for (long i = 0; i < n; ++i)
        errors.run([&] {
            footprints[i] = lc::sr::apparentFootprint(lc::sr::RestTriangle::fromMesh(mesh, static_cast<int>(i)), frame,
                                                      observer, cam);
        });
    errors.rethrow();
    return footprints;
}

// Quad quadOf[i] (two triangles) covers triangle i's footprint and carries its rest-frame
// vertices and normals (lcP0..2 with the triangle's index in lcP0.w, lcN0..2) to the fragment
// shader, which intersects each pixel's ray with that triangle.
void writeQuads(const lc::sr::TriMesh& mesh, const std::vector<lc::sr::ApparentFootprint>& footprints,
                const std::vector<long>& quadOf, long nq, vtkPolyData* output) {
    const long n = static_cast<long>(mesh.triangles.size());
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(4 * nq);
    auto p0 = lc::views::floatArray("lcP0", 4, 4 * nq), p1 = lc::views::floatArray("lcP1", 3, 4 * nq),
         p2 = lc::views::floatArray("lcP2", 3, 4 * nq);
    auto n0 = lc::views::floatArray("lcN0", 3, 4 * nq), n1 = lc::views::floatArray("lcN1", 3, 4 * nq),
         n2 = lc::views::floatArray("lcN2", 3, 4 * nq);
    auto* pts = static_cast<float*>(points->GetVoidPointer(0));
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
        const long q = quadOf[i];
        if (q < 0) continue;
        const lc::sr::RestTriangle tri = lc::sr::RestTriangle::fromMesh(mesh, static_cast<int>(i));
        const lc::sr::PixelRect& r = footprints[i].rect;
        const float xs[4] = {float(r.x0), float(r.x1 + 1), float(r.x1 + 1), float(r.x0)};
        const float ys[4] = {float(r.y0), float(r.y0), float(r.y1 + 1), float(r.y1 + 1)};
        for (int k = 0; k < 4; ++k) {
            const vtkIdType v = 4 * q + k;
            pts[3 * v] = xs[k], pts[3 * v + 1] = ys[k], pts[3 * v + 2] = 0.0f;
            float* a = p0->GetPointer(4 * v);
            a[0] = float(tri.p[0].x()), a[1] = float(tri.p[0].y()), a[2] = float(tri.p[0].z()), a[3] = float(i);
            lc::views::putVec3(p1, v, tri.p[1]);
            lc::views::putVec3(p2, v, tri.p[2]);
            lc::views::putVec3(n0, v, tri.n[0]);
            lc::views::putVec3(n1, v, tri.n[1]);
            lc::views::putVec3(n2, v, tri.n[2]);
        }
    }
    vtkNew<vtkCellArray> cells;
    cells->AllocateExact(2 * nq, 6 * nq);
    for (vtkIdType q = 0; q < nq; ++q) {
        const vtkIdType a[3] = {4 * q, 4 * q + 1, 4 * q + 2}, b[3] = {4 * q, 4 * q + 2, 4 * q + 3};
        cells->InsertNextCell(3, a);
        cells->InsertNextCell(3, b);
    }
    output->SetPoints(points);
    output->SetPolys(cells);
    for (vtkFloatArray* a : {p0.Get(), p1.Get(), p2.Get(), n0.Get(), n1.Get(), n2.Get()})
        output->GetPointData()->AddArray(a);
}

}  // namespace

int vtkLightconeSrFootprintQuads::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                              vtkInformationVector* outputVector) {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    if (!input || !output) return 0;
    this->Quads = this->FullScreenQuads = 0;
    this->FootprintPixels = 0;
    lc::sr::TriMesh mesh;
    lc::sr::MovingFrame frame;
    try {
        if (!std::isfinite(this->ObserverTime)) throw std::invalid_argument("the observer time must be finite");
        this->Camera.validate();
        const std::string problem = lc::filters::CheckMovingFrame(this->Beta, this->ObjectOrigin);
        if (!problem.empty()) throw std::invalid_argument(problem);
        frame = lc::sr::MovingFrame::throughEvent(
            lc::Vec3(this->Beta[0], this->Beta[1], this->Beta[2]),
            lc::Vec4(this->ObjectOrigin[0], this->ObjectOrigin[1], this->ObjectOrigin[2], this->ObjectOrigin[3]));
        mesh = lc::views::srTriMesh(input);
    } catch (const std::exception& e) {
        vtkErrorMacro(<< e.what());
        return 0;
    }
    const long n = static_cast<long>(mesh.triangles.size());
    if (n == 0) return 1;  // nothing to draw

    const lc::sr::ObserverCamera& cam = this->Camera;
    const lc::Vec4 observer(this->ObserverTime, cam.position.x(), cam.position.y(), cam.position.z());
    std::vector<lc::sr::ApparentFootprint> footprints;
    try {
        footprints = apparentFootprints(mesh, frame, observer, cam);
    } catch (const std::exception& e) {
        vtkErrorMacro(<< "footprint: " << e.what());
        return 0;
    }
    this->UpdateProgress(0.5);

    // Quad q of triangle i, in triangle order.
    std::vector<long> quadOf(static_cast<std::size_t>(n), -1);
    long nq = 0;
    for (long i = 0; i < n; ++i) {
        const lc::sr::PixelRect& r = footprints[i].rect;
        if (r.empty()) continue;
        quadOf[i] = nq++;
        this->FootprintPixels += double(r.x1 - r.x0 + 1) * double(r.y1 - r.y0 + 1);
        this->FullScreenQuads += footprints[i].fullScreen;
    }
    this->Quads = static_cast<std::size_t>(nq);

    writeQuads(mesh, footprints, quadOf, nq, output);
    this->UpdateProgress(1.0);
    return 1;
}

void vtkLightconeSrFootprintQuads::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Beta: (" << this->Beta[0] << ", " << this->Beta[1] << ", " << this->Beta[2] << ")\n"
       << indent << "ObjectOrigin: (" << this->ObjectOrigin[0] << ", " << this->ObjectOrigin[1] << ", "
       << this->ObjectOrigin[2] << ", " << this->ObjectOrigin[3] << ")\n"
       << indent << "ObserverTime: " << this->ObserverTime << "\n"
       << indent << "Camera: " << this->Camera.width << " x " << this->Camera.height << "\n"
       << indent << "Quads: " << this->Quads << " (full screen " << this->FullScreenQuads << ")\n"
       << indent << "FootprintPixels: " << this->FootprintPixels << "\n";
}
