// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeGodelLayerTriangles: a photo-object layer as the Goedel mapper's triangles. Against
// the photo-object filter's own block: every triangle owns its three vertices, at the block's
// unit directions and depths; the centroid is the normalised mean direction; u stays continuous
// across the texture seam; a black-body emitter's temperature is lc::shiftedTemperature of the
// block's frequency ratio. Invalid input (a block the photo-object lacks, a block without the
// layer's arrays) is an error with an empty output, no crash; an empty layer is an empty output.
#include "vtkLightconeGodelImageMapper.h"
#include "vtkLightconeGodelLayerTriangles.h"
#include "vtkLightconePhotoObjectFilter.h"

#include "core/godel/photo_object.hpp"
#include "core/render/photo_scene.hpp"
#include "core/render/post_render.hpp"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <Eigen/Geometry>
#include <sstream>

namespace {

// A small sphere in front of an observer at the origin (a = 1), with spherical texture coordinates.
vtkSmartPointer<vtkPolyData> sphereMesh() {
    const lc::godel::Mesh mesh = lc::godel::uvSphere(0.2, 8, 16);
    const std::vector<lc::Vec2> uv = lc::sphericalUvs(mesh);
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> points;
    for (const auto& v : mesh.vertices) points->InsertNextPoint(v.data());
    vtkNew<vtkCellArray> cells;
    for (const auto& t : mesh.triangles) {
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        cells->InsertNextCell(3, ids);
    }
    vtkNew<vtkFloatArray> tc;
    tc->SetNumberOfComponents(2);
    for (const auto& p : uv) tc->InsertNextTuple2(p(0), p(1));
    poly->SetPoints(points);
    poly->SetPolys(cells);
    poly->GetPointData()->SetTCoords(tc);
    return poly;
}

bool quietly(vtkAlgorithm* algorithm) {
    const int previous = vtkObject::GetGlobalWarningDisplay();
    vtkObject::GlobalWarningDisplayOff();
    const int ok = algorithm->GetExecutive()->Update();
    vtkObject::SetGlobalWarningDisplay(previous);
    return ok != 0;
}

}  // namespace

TEST(GodelLayerTriangles, TrianglesOwnTheirVerticesWithCentroidSeamAndTemperature) {
    vtkNew<vtkLightconePhotoObjectFilter> photo;
    photo->SetInputData(sphereMesh());
    photo->SetGodelA(1.0);
    photo->SetCentreEvent(0, 0.8, 0.2, 0.1);
    photo->SetMaxWinding(0);
    photo->CameraFrameOn();
    photo->Update();
    auto* block = vtkPolyData::SafeDownCast(photo->GetOutput()->GetBlock(0));
    ASSERT_TRUE(block);
    ASSERT_GT(block->GetNumberOfPolys(), 0);

    vtkNew<vtkLightconeGodelLayerTriangles> triangles;
    triangles->SetInputConnection(photo->GetOutputPort());
    triangles->SetBlock(0);
    triangles->SetTemperature(5000);
    triangles->Update();
    vtkPolyData* out = triangles->GetOutput();
    ASSERT_EQ(out->GetNumberOfPolys(), block->GetNumberOfPolys());
    ASSERT_EQ(out->GetNumberOfPoints(), 3 * block->GetNumberOfPolys());
    vtkDataArray* aux = out->GetPointData()->GetArray("lcAux");
    vtkDataArray* light = out->GetPointData()->GetArray("lcLight");
    vtkDataArray* temperature = out->GetPointData()->GetArray("lcTemperature");
    vtkDataArray* tc = out->GetPointData()->GetTCoords();
    ASSERT_TRUE(aux && light && temperature && tc);
    vtkDataArray* dir = block->GetPointData()->GetArray("direction");
    vtkDataArray* depth = block->GetPointData()->GetArray("depth");
    vtkDataArray* ratio = block->GetPointData()->GetArray("frequency_ratio");
    vtkNew<vtkIdList> ids;
    vtkIdType t = 0;
    int seamTriangles = 0;
    for (block->GetPolys()->InitTraversal(); block->GetPolys()->GetNextCell(ids); ++t) {
        lc::Vec3 mean = lc::Vec3::Zero();
        double u[3], uIn[3];
        for (int k = 0; k < 3; ++k) {
            const vtkIdType p = ids->GetId(k), q = 3 * t + k;
            const lc::Vec3 d(dir->GetComponent(p, 0), dir->GetComponent(p, 1), dir->GetComponent(p, 2));
            mean += d.normalized();
            double x[3];
            out->GetPoint(q, x);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(x[c], d.normalized()(c), 1e-6);
            EXPECT_NEAR(aux->GetComponent(q, 3), depth->GetComponent(p, 0), 1e-5 * depth->GetComponent(p, 0));
            EXPECT_NEAR(temperature->GetComponent(q, 0), lc::shiftedTemperature(ratio->GetComponent(p, 0), 5000.0),
                        1e-3);
            EXPECT_EQ(light->GetComponent(q, 0), 1.0);  // no light on the input: fully lit
            u[k] = tc->GetComponent(q, 0);
            // Seam: the block's u, or one more where it lies more than half a turn below the max.
            uIn[k] = block->GetPointData()->GetTCoords()->GetComponent(p, 0);
            EXPECT_TRUE(u[k] == float(uIn[k]) || u[k] == float(uIn[k] + 1)) << u[k] << " from " << uIn[k];
        }
        mean.normalize();
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(aux->GetComponent(3 * t + k, c), mean(c), 1e-6);
        // No vertex is left more than half a turn below the triangle's largest u.
        const double top = std::max({uIn[0], uIn[1], uIn[2]});
        for (double uk : u) EXPECT_GE(uk, top - 0.5 - 1e-6) << "triangle " << t;
        seamTriangles += std::max({u[0], u[1], u[2]}) > 1.0;
    }
    EXPECT_GT(seamTriangles, 0);  // the sphere's u = 0/1 seam is in the layer

    std::ostringstream print;
    triangles->Print(print);
    EXPECT_NE(print.str().find("Temperature: 5000"), std::string::npos);
    vtkNew<vtkLightconeGodelImageMapper> mapper;
    std::ostringstream printMapper;
    mapper->Print(printMapper);
    EXPECT_NE(printMapper.str().find("MaximumLambda"), std::string::npos);
}

TEST(GodelLayerTriangles, RefusesMissingBlocksAndArraysAndPassesEmptyLayers) {
    vtkNew<vtkLightconePhotoObjectFilter> photo;
    photo->SetInputData(sphereMesh());
    photo->SetGodelA(1.0);
    photo->SetMaxWinding(0);
    vtkNew<vtkLightconeGodelLayerTriangles> triangles;
    triangles->SetInputConnection(photo->GetOutputPort());
    triangles->SetBlock(7);  // windings 0 only: blocks 0 and 1
    EXPECT_FALSE(quietly(triangles));
    EXPECT_EQ(triangles->GetOutput()->GetNumberOfPoints(), 0);

    // A multiblock whose block is a plain mesh without the layer's point data.
    vtkNew<vtkMultiBlockDataSet> foreign;
    foreign->SetNumberOfBlocks(1);
    foreign->SetBlock(0, sphereMesh());
    vtkNew<vtkLightconeGodelLayerTriangles> bare;
    bare->SetInputData(foreign);
    EXPECT_FALSE(quietly(bare));
    EXPECT_EQ(bare->GetOutput()->GetNumberOfPoints(), 0);

    // An empty layer (no triangle has this image) is an empty output, not an error.
    vtkNew<vtkMultiBlockDataSet> empty;
    empty->SetNumberOfBlocks(1);
    vtkNew<vtkPolyData> nothing;
    empty->SetBlock(0, nothing);
    vtkNew<vtkLightconeGodelLayerTriangles> none;
    none->SetInputData(empty);
    EXPECT_TRUE(quietly(none));
    EXPECT_EQ(none->GetOutput()->GetNumberOfPoints(), 0);
}
