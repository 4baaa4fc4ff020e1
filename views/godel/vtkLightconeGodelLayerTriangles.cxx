// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeGodelLayerTriangles.h"

#include "offscreen_parts.hpp"

#include "core/render/post_render.hpp"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <Eigen/Core>

vtkStandardNewMacro(vtkLightconeGodelLayerTriangles);

vtkLightconeGodelLayerTriangles::vtkLightconeGodelLayerTriangles() { this->SetNumberOfInputPorts(1); }

namespace {

// A triangle's corners on the unit sphere of directions, their centroid direction, and texture
// coordinates with u kept continuous across the texture's seam (it repeats), as the CPU raster.
struct TriangleCorners {
    Eigen::Vector3d d[3], centroid = Eigen::Vector3d::Zero();
    double u[3], v[3];

    TriangleCorners(vtkIdList* ids, vtkDataArray* direction, vtkDataArray* uv) {
        for (int k = 0; k < 3; ++k) {
            const vtkIdType p = ids->GetId(k);
            d[k] = Eigen::Vector3d(direction->GetComponent(p, 0), direction->GetComponent(p, 1),
                                   direction->GetComponent(p, 2))
                       .normalized();
            centroid += d[k];
            u[k] = uv->GetComponent(p, 0);
            v[k] = uv->GetComponent(p, 1);
        }
        centroid = centroid.norm() > 1e-12 ? centroid.normalized() : d[0];
        const double umax = std::max({u[0], u[1], u[2]});
        for (double& uk : u)
            if (umax - uk > 0.5) uk += 1;
    }
};

}  // namespace

int vtkLightconeGodelLayerTriangles::FillInputPortInformation(int, vtkInformation* info) {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
    return 1;
}

int vtkLightconeGodelLayerTriangles::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                                 vtkInformationVector* outputVector) {
    vtkMultiBlockDataSet* input = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    if (!input || !output) return 0;
    if (this->Block >= static_cast<int>(input->GetNumberOfBlocks())) {
        vtkErrorMacro(<< "block " << this->Block << " requested, the photo-object has " << input->GetNumberOfBlocks()
                      << " (2 per winding)");
        return 0;
    }
    vtkPolyData* layer = vtkPolyData::SafeDownCast(input->GetBlock(static_cast<unsigned int>(this->Block)));
    if (!layer) {
        vtkErrorMacro(<< "block " << this->Block << " is not a vtkPolyData");
        return 0;
    }
    if (layer->GetNumberOfPolys() == 0) return 1;  // no triangle of this object has this image
    vtkPointData* pd = layer->GetPointData();
    vtkDataArray* direction = pd->GetArray("direction");
    vtkDataArray* depth = pd->GetArray("depth");
    vtkDataArray* ratio = pd->GetArray("frequency_ratio");
    vtkDataArray* uv = pd->GetTCoords();
    vtkDataArray* light = pd->GetArray("lcLight");
    if (!direction || !depth || !ratio || !uv) {
        vtkErrorMacro(<< "block " << this->Block
                      << " lacks the point data of a photo-object layer (direction, depth, frequency_ratio, TCoords)");
        return 0;
    }
    const vtkIdType nt = layer->GetNumberOfPolys();
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(3 * nt);
    auto tcoords = lc::views::floatArray("TCoords", 2, 3 * nt);
    auto aux = lc::views::floatArray("lcAux", 4, 3 * nt);
    auto lightOut = lc::views::floatArray("lcLight", 3, 3 * nt);
    auto temperature = lc::views::floatArray("lcTemperature", 1, 3 * nt);
    vtkNew<vtkCellArray> cells;
    cells->AllocateExact(nt, 3 * nt);
    vtkNew<vtkIdList> ids;
    vtkIdType t = 0;
    vtkCellArray* polys = layer->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(ids); ++t) {
        if (ids->GetNumberOfIds() != 3) {
            vtkErrorMacro(<< "block " << this->Block << ": cell " << t << " is not a triangle");
            output->Initialize();
            return 0;
        }
        const TriangleCorners c(ids, direction, uv);
        const vtkIdType out[3] = {3 * t, 3 * t + 1, 3 * t + 2};
        for (int k = 0; k < 3; ++k) {
            const vtkIdType p = ids->GetId(k);
            points->SetPoint(out[k], c.d[k].data());
            tcoords->SetTuple2(out[k], c.u[k], c.v[k]);
            aux->SetTuple4(out[k], c.centroid(0), c.centroid(1), c.centroid(2), depth->GetComponent(p, 0));
            if (light)
                lightOut->SetTuple3(out[k], light->GetComponent(p, 0), light->GetComponent(p, 1),
                                    light->GetComponent(p, 2));
            else
                lightOut->SetTuple3(out[k], 1, 1, 1);
            // D T of a black-body emitter, clamped as lc::shadePixels (0: the texture).
            temperature->SetValue(out[k], this->Temperature > 0 ? static_cast<float>(lc::shiftedTemperature(
                                                                      ratio->GetComponent(p, 0), this->Temperature))
                                                                : 0.0f);
        }
        cells->InsertNextCell(3, out);
    }
    output->SetPoints(points);
    output->SetPolys(cells);
    output->GetPointData()->SetTCoords(tcoords);
    output->GetPointData()->AddArray(aux);
    output->GetPointData()->AddArray(lightOut);
    output->GetPointData()->AddArray(temperature);
    return 1;
}

void vtkLightconeGodelLayerTriangles::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Block: " << this->Block << "\n" << indent << "Temperature: " << this->Temperature << "\n";
}
