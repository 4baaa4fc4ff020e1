// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeSrApparentTriangles: the special-relativity photo-object (vtkLightconePhotoObjectFilter)
// as the polygon-distortion mapper's triangles. Against core: every triangle owns its three
// vertices at lc::sr::apparentPosition minus the eye, carries the whole apparent triangle, the rest
// normals and its index, and each vertex's Doppler factor is lc::sr::restRayDoppler along the
// direction the observer sees it in (the filter computes it with lc::sr::dopplerFactor). Invalid
// input (a foreign block, a mesh without normals, a cell that is not a triangle) is an error with
// an empty output; an empty photo-object is an empty output.
#include "vtkLightconeSrApparentTriangles.h"

#include "sr_mesh.hpp"
#include "vtkLightconePhotoObjectFilter.h"

#include "core/sr/doppler.hpp"
#include "core/sr/mesh.hpp"
#include "core/sr/photo_object.hpp"
#include "tests/common/vtk_event_counter.hpp"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <sstream>

namespace {

using lc::Vec3;

int errorsOf(vtkAlgorithm* algorithm, std::string* text = nullptr) {
    lc::test::EventCounter errors;
    errors.watch(algorithm);
    algorithm->Update();
    if (text) *text = errors.text;
    return errors.count;
}

}  // namespace

TEST(SrApparentTriangles, VerticesAreApparentPositionsSeenFromTheEyeWithTheirDoppler) {
    const lc::sr::TriMesh sphere = lc::sr::makeUvSphere(1.0, 12, 6);
    const Vec3 beta(0.8, 0.1, 0.0);
    const lc::Vec4 origin(1.0, -2.0, 0.5, -6.0), observer(2.0, 0.3, -0.2, 1.0);
    vtkNew<vtkLightconePhotoObjectFilter> photo;
    photo->SetModeToSpecialRelativity();
    photo->SetInputData(lc::views::srMeshPolyData(sphere));
    photo->SetBeta(beta.x(), beta.y(), beta.z());
    photo->SetObjectOrigin(origin(0), origin(1), origin(2), origin(3));
    photo->SetObserver(observer(0), observer(1), observer(2), observer(3));
    vtkNew<vtkLightconeSrApparentTriangles> triangles;
    triangles->SetInputConnection(photo->GetOutputPort());
    triangles->SetEye(observer(1), observer(2), observer(3));
    EXPECT_EQ(errorsOf(triangles), 0);
    vtkPolyData* out = triangles->GetOutput();
    const vtkIdType nt = static_cast<vtkIdType>(sphere.triangles.size());
    ASSERT_EQ(out->GetNumberOfPolys(), nt);
    ASSERT_EQ(out->GetNumberOfPoints(), 3 * nt);
    vtkPointData* pd = out->GetPointData();
    vtkDataArray* a[3] = {pd->GetArray("lcA0"), pd->GetArray("lcA1"), pd->GetArray("lcA2")};
    vtkDataArray* n[3] = {pd->GetArray("lcN0"), pd->GetArray("lcN1"), pd->GetArray("lcN2")};
    vtkDataArray* index = pd->GetArray("lcTriangle");
    vtkDataArray* vd = pd->GetArray("lcVD");
    ASSERT_TRUE(a[0] && a[1] && a[2] && n[0] && n[1] && n[2] && index && vd);

    const lc::sr::MovingFrame frame = lc::sr::MovingFrame::throughEvent(beta, origin);
    const Vec3 eye = observer.tail<3>();
    for (vtkIdType t = 0; t < nt; ++t) {
        const auto& idx = sphere.triangles[static_cast<std::size_t>(t)];
        Vec3 expected[3];
        for (int k = 0; k < 3; ++k)
            expected[k] = lc::sr::apparentPosition(frame, sphere.positions[std::size_t(idx[k])], observer) - eye;
        for (int k = 0; k < 3; ++k) {
            const vtkIdType v = 3 * t + k;
            double x[3];
            out->GetPoint(v, x);
            const double tol = 1e-6 * (1 + expected[k].norm());
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(x[c], expected[k](c), tol) << "triangle " << t << " vertex " << k;
                for (int m = 0; m < 3; ++m) {
                    EXPECT_NEAR(a[m]->GetComponent(v, c), expected[m](c), 1e-6 * (1 + expected[m].norm()));
                    EXPECT_NEAR(n[m]->GetComponent(v, c), sphere.normals[std::size_t(idx[m])](c), 1e-6);
                }
            }
            EXPECT_EQ(index->GetComponent(v, 0), t);
            const double D = lc::sr::restRayDoppler<double>(beta, expected[k].normalized());
            EXPECT_NEAR(vd->GetComponent(v, 0), D, 1e-6 * D);
        }
    }
    std::ostringstream print;
    triangles->Print(print);
    EXPECT_NE(print.str().find("Eye: (0.3, -0.2, 1)"), std::string::npos) << print.str();
}

TEST(SrApparentTriangles, RefusesForeignBlocksMissingNormalsAndNonTriangles) {
    const lc::sr::TriMesh cube = lc::sr::makeCube(2.0, 1);
    std::string text;
    {  // the rest mesh without normals: the photo-object carries none
        vtkSmartPointer<vtkPolyData> mesh = lc::views::srMeshPolyData(cube);
        mesh->GetPointData()->SetNormals(nullptr);
        vtkNew<vtkLightconePhotoObjectFilter> photo;
        photo->SetModeToSpecialRelativity();
        photo->SetInputData(mesh);
        vtkNew<vtkLightconeSrApparentTriangles> triangles;
        triangles->SetInputConnection(photo->GetOutputPort());
        EXPECT_EQ(errorsOf(triangles, &text), 1);
        EXPECT_NE(text.find("rest normals"), std::string::npos) << text;
        EXPECT_EQ(triangles->GetOutput()->GetNumberOfPoints(), 0);
    }
    {  // a block that is not a vtkPolyData
        vtkNew<vtkMultiBlockDataSet> foreign, inner;
        foreign->SetNumberOfBlocks(1);
        foreign->SetBlock(0, inner);
        vtkNew<vtkLightconeSrApparentTriangles> triangles;
        triangles->SetInputData(foreign);
        EXPECT_EQ(errorsOf(triangles, &text), 1);
        EXPECT_NE(text.find("not a vtkPolyData"), std::string::npos) << text;
    }
    {  // a quadrilateral among the cells
        vtkSmartPointer<vtkPolyData> mesh = lc::views::srMeshPolyData(cube);
        vtkNew<vtkDoubleArray> doppler;
        doppler->SetName("doppler");
        doppler->SetNumberOfTuples(mesh->GetNumberOfPoints());
        doppler->Fill(1.0);
        mesh->GetPointData()->AddArray(doppler);
        vtkNew<vtkCellArray> quad;
        const vtkIdType ids[4] = {0, 1, 2, 3};
        quad->InsertNextCell(4, ids);
        mesh->SetPolys(quad);
        vtkNew<vtkMultiBlockDataSet> blocks;
        blocks->SetNumberOfBlocks(1);
        blocks->SetBlock(0, mesh);
        vtkNew<vtkLightconeSrApparentTriangles> triangles;
        triangles->SetInputData(blocks);
        EXPECT_EQ(errorsOf(triangles, &text), 1);
        EXPECT_NE(text.find("is not a triangle"), std::string::npos) << text;
        EXPECT_EQ(triangles->GetOutput()->GetNumberOfPoints(), 0);
    }
    {  // an empty mesh: the photo-object is empty, so is the output
        vtkNew<vtkPolyData> empty;
        vtkNew<vtkLightconePhotoObjectFilter> photo;
        photo->SetModeToSpecialRelativity();
        photo->SetInputData(empty);
        vtkNew<vtkLightconeSrApparentTriangles> triangles;
        triangles->SetInputConnection(photo->GetOutputPort());
        const int previous = vtkObject::GetGlobalWarningDisplay();
        vtkObject::GlobalWarningDisplayOff();  // the filter warns about the empty mesh
        EXPECT_EQ(errorsOf(triangles), 0);
        vtkObject::SetGlobalWarningDisplay(previous);
        EXPECT_EQ(triangles->GetOutput()->GetNumberOfPoints(), 0);
    }
}
