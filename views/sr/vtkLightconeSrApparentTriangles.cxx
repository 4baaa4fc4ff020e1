// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeSrApparentTriangles.h"

#include "offscreen_parts.hpp"

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

#include <Eigen/Core>

vtkStandardNewMacro(vtkLightconeSrApparentTriangles);

vtkLightconeSrApparentTriangles::vtkLightconeSrApparentTriangles() { this->SetNumberOfInputPorts(1); }

int vtkLightconeSrApparentTriangles::FillInputPortInformation(int, vtkInformation* info) {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
    return 1;
}

int vtkLightconeSrApparentTriangles::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                                 vtkInformationVector* outputVector) {
    vtkMultiBlockDataSet* input = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    if (!input || !output) return 0;
    if (input->GetNumberOfBlocks() == 0) return 1;  // the photo-object of an empty mesh
    vtkPolyData* apparent = vtkPolyData::SafeDownCast(input->GetBlock(0));
    if (!apparent) {
        vtkErrorMacro(<< "block 0 is not a vtkPolyData (expected the special-relativity photo-object's \"apparent\")");
        return 0;
    }
    const vtkIdType nt = apparent->GetNumberOfPolys();
    if (nt == 0) return 1;
    vtkPointData* pd = apparent->GetPointData();
    vtkDataArray* doppler = pd->GetArray("doppler");
    vtkDataArray* normals = pd->GetNormals() ? pd->GetNormals() : pd->GetArray("Normals");
    if (!doppler || !normals || normals->GetNumberOfComponents() != 3) {
        vtkErrorMacro(<< "the apparent mesh lacks \"doppler\" or the rest normals (give the input mesh point normals)");
        return 0;
    }
    const Eigen::Vector3d eye(this->Eye[0], this->Eye[1], this->Eye[2]);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(3 * nt);
    auto a0 = lc::views::floatArray("lcA0", 3, 3 * nt), a1 = lc::views::floatArray("lcA1", 3, 3 * nt),
         a2 = lc::views::floatArray("lcA2", 3, 3 * nt);
    auto n0 = lc::views::floatArray("lcN0", 3, 3 * nt), n1 = lc::views::floatArray("lcN1", 3, 3 * nt),
         n2 = lc::views::floatArray("lcN2", 3, 3 * nt);
    auto triangle = lc::views::floatArray("lcTriangle", 1, 3 * nt), vd = lc::views::floatArray("lcVD", 1, 3 * nt);
    vtkNew<vtkCellArray> cells;
    cells->AllocateExact(nt, 3 * nt);
    vtkNew<vtkIdList> ids;
    vtkIdType t = 0;
    vtkCellArray* polys = apparent->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(ids); ++t) {
        if (ids->GetNumberOfIds() != 3) {
            vtkErrorMacro(<< "cell " << t << " of the apparent mesh is not a triangle");
            output->Initialize();
            return 0;
        }
        Eigen::Vector3d a[3], n[3];
        for (int k = 0; k < 3; ++k) {
            double p[3];
            apparent->GetPoint(ids->GetId(k), p);
            a[k] = Eigen::Vector3d(p[0], p[1], p[2]) - eye;
            normals->GetTuple(ids->GetId(k), p);
            n[k] = Eigen::Vector3d(p[0], p[1], p[2]);
        }
        const vtkIdType out[3] = {3 * t, 3 * t + 1, 3 * t + 2};
        for (int k = 0; k < 3; ++k) {
            const vtkIdType v = out[k];
            lc::views::putVec3(a0, v, a[0]);
            lc::views::putVec3(a1, v, a[1]);
            lc::views::putVec3(a2, v, a[2]);
            lc::views::putVec3(n0, v, n[0]);
            lc::views::putVec3(n1, v, n[1]);
            lc::views::putVec3(n2, v, n[2]);
            points->SetPoint(v, a[k].data());
            triangle->SetValue(v, static_cast<float>(t));
            vd->SetValue(v, static_cast<float>(doppler->GetComponent(ids->GetId(k), 0)));
        }
        cells->InsertNextCell(3, out);
    }
    output->SetPoints(points);
    output->SetPolys(cells);
    for (vtkFloatArray* arr : {a0.Get(), a1.Get(), a2.Get(), n0.Get(), n1.Get(), n2.Get(), triangle.Get(), vd.Get()})
        output->GetPointData()->AddArray(arr);
    return 1;
}

void vtkLightconeSrApparentTriangles::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Eye: (" << this->Eye[0] << ", " << this->Eye[1] << ", " << this->Eye[2] << ")\n";
}
