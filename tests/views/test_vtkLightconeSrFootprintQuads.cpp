// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeSrFootprintQuads: the fragments local ray tracing runs. Against an independent
// oracle: lc::sr::SrRenderer in BruteForce mode tests every pixel against every triangle (no
// footprint), so every pixel it shows a triangle at must lie inside that triangle's quad (the
// footprint is conservative); each quad carries its rest triangle. Invalid input (no normals, a
// polygon that is not a triangle, |beta| >= 1, a non-finite time, a bad camera) is one error with
// an empty output, reported again on the next update; zero normals (unused points, degenerate
// faces) are drawn; an empty mesh is an empty output; an unchanged camera re-executes nothing.
#include "vtkLightconeSrFootprintQuads.h"

#include "offscreen_parts.hpp"
#include "sr_mesh.hpp"

#include "core/sr/mesh.hpp"
#include "core/sr/renderer.hpp"
#include "tests/common/vtk_event_counter.hpp"

#include "tests/common/sr_camera.hpp"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

using lc::test::srCamera;

using lc::Vec3;

// Seed 003's cube of edge 4 at 0.95 c (data/sr_cube.json): at t = 0 its centre is at (9.5, 0, -10).
const lc::sr::MovingFrame kFrame(Vec3(0.95, 0, 0), Vec3(9.5, 0, -10));

void setFrame(vtkLightconeSrFootprintQuads* quads, const lc::sr::MovingFrame& frame) {
    quads->SetBeta(frame.beta().x(), frame.beta().y(), frame.beta().z());
    quads->SetObjectOrigin(0, frame.origin().x(), frame.origin().y(), frame.origin().z());
}

// The independent oracle: every pixel against every triangle of the mesh in kFrame, no footprint.
lc::sr::SrImage bruteForceImage(const lc::sr::TriMesh& mesh, const lc::sr::ObserverCamera& cam) {
    lc::sr::SrScene scene;
    scene.objects.push_back({mesh, kFrame, {}});
    lc::sr::SrRenderOptions brute;
    brute.mode = lc::sr::SrRenderMode::BruteForce;
    return lc::sr::SrRenderer().render(scene, cam, brute);
}

}  // namespace

TEST(SrFootprintQuads, EveryPixelBruteForceShowsLiesInItsTrianglesQuad) {
    const int W = 160, H = 90;
    const lc::sr::TriMesh cube = lc::sr::makeCube(4.0, 3);
    const lc::sr::SrImage cpu = bruteForceImage(cube, srCamera(W, H, 75));

    vtkNew<vtkLightconeSrFootprintQuads> quads;
    quads->SetInputData(lc::views::srMeshPolyData(cube));
    setFrame(quads, kFrame);
    quads->SetCamera(srCamera(W, H, 75));
    quads->Update();
    vtkPolyData* out = quads->GetOutput();
    const vtkIdType nq = static_cast<vtkIdType>(quads->GetNumberOfQuads());
    ASSERT_GT(nq, 0);
    ASSERT_EQ(out->GetNumberOfPoints(), 4 * nq);
    ASSERT_EQ(out->GetNumberOfPolys(), 2 * nq);
    vtkDataArray* p0 = out->GetPointData()->GetArray("lcP0");
    vtkDataArray* p1 = out->GetPointData()->GetArray("lcP1");
    vtkDataArray* n2 = out->GetPointData()->GetArray("lcN2");
    ASSERT_TRUE(p0 && p1 && n2 && out->GetPointData()->GetArray("lcP2") && out->GetPointData()->GetArray("lcN0"));

    // Each quad's pixel rectangle, by triangle; its corners carry the rest triangle.
    struct Rect {
        double x0, y0, x1, y1;
    };
    std::map<int, Rect> rectOf;
    double area = 0;
    for (vtkIdType q = 0; q < nq; ++q) {
        Rect r{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), -1, -1};
        const int t = static_cast<int>(p0->GetComponent(4 * q, 3));
        for (int k = 0; k < 4; ++k) {
            double x[3];
            out->GetPoint(4 * q + k, x);
            r.x0 = std::min(r.x0, x[0]), r.x1 = std::max(r.x1, x[0]);
            r.y0 = std::min(r.y0, x[1]), r.y1 = std::max(r.y1, x[1]);
            EXPECT_EQ(p0->GetComponent(4 * q + k, 3), t);  // the same triangle on every corner
        }
        ASSERT_FALSE(rectOf.count(t)) << "two quads for triangle " << t;
        rectOf[t] = r;
        area += (r.x1 - r.x0) * (r.y1 - r.y0);
        const auto& idx = cube.triangles[static_cast<std::size_t>(t)];
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(p0->GetComponent(4 * q, c), cube.positions[std::size_t(idx[0])](c), 1e-6);
            EXPECT_NEAR(p1->GetComponent(4 * q, c), cube.positions[std::size_t(idx[1])](c), 1e-6);
            EXPECT_NEAR(n2->GetComponent(4 * q, c), cube.normals[std::size_t(idx[2])](c), 1e-6);
        }
    }
    EXPECT_NEAR(quads->GetFootprintPixels(), area, 1e-6 * area);

    std::size_t shown = 0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const int t = cpu.triangle[static_cast<std::size_t>(j) * W + i];
            if (t < 0) continue;
            ++shown;
            ASSERT_TRUE(rectOf.count(t)) << "pixel " << i << ", " << j << " shows triangle " << t
                                         << ", which has no quad";
            const Rect& r = rectOf[t];
            EXPECT_TRUE(i + 0.5 > r.x0 && i + 0.5 < r.x1 && j + 0.5 > r.y0 && j + 0.5 < r.y1)
                << "pixel " << i << ", " << j << " outside the quad of triangle " << t;
        }
    EXPECT_GT(shown, 500u);
    // Conservative, but not the whole screen for every triangle: far less than one image per quad.
    EXPECT_LT(quads->GetFootprintPixels(), 0.25 * double(nq) * W * H);

    std::ostringstream print;
    quads->Print(print);
    EXPECT_NE(print.str().find("Quads: " + std::to_string(nq)), std::string::npos) << print.str();
}

// The camera turned away from the cube (a look-around in the workbench): the brute-force renderer
// shows none of it, and no quad is drawn; before, every triangle behind the camera took a quad of
// the whole screen (1200 of them for data/sr_cube.json, 32 s a frame on llvmpipe). Turned by 60
// degrees the cube is partly in view: the quads still cover every pixel that shows it.
TEST(SrFootprintQuads, NoQuadForTrianglesOutOfView) {
    const int W = 160, H = 90;
    const lc::sr::TriMesh cube = lc::sr::makeCube(4.0, 3);
    vtkNew<vtkLightconeSrFootprintQuads> quads;
    quads->SetInputData(lc::views::srMeshPolyData(cube));
    setFrame(quads, kFrame);
    for (const double turnDeg : {180.0, 90.0, 60.0}) {
        SCOPED_TRACE(turnDeg);
        lc::sr::ObserverCamera cam = srCamera(W, H, 75);
        const double t = turnDeg * lc::kPi / 180;
        cam.forward = Vec3(-std::sin(t), 0, -std::cos(t));  // about y, away from the cube at +x
        const lc::sr::SrImage cpu = bruteForceImage(cube, cam);
        const std::size_t shown = static_cast<std::size_t>(
            std::count_if(cpu.triangle.begin(), cpu.triangle.end(), [](int tri) { return tri >= 0; }));
        quads->SetCamera(cam);
        quads->Update();
        EXPECT_EQ(quads->GetNumberOfFullScreenQuads(), 0u);
        if (turnDeg > 60) {
            EXPECT_EQ(shown, 0u);
            EXPECT_EQ(quads->GetNumberOfQuads(), 0u);
            EXPECT_EQ(quads->GetOutput()->GetNumberOfPoints(), 0);
        } else {
            EXPECT_GT(shown, 100u);
            EXPECT_GT(quads->GetNumberOfQuads(), 0u);
            EXPECT_LT(quads->GetNumberOfQuads(), cube.triangles.size());
        }
    }
}

TEST(SrFootprintQuads, RefusesInvalidInputAndReexecutesOnlyOnChange) {
    const lc::sr::TriMesh cube = lc::sr::makeCube(4.0, 1);
    auto run = [](vtkLightconeSrFootprintQuads* quads) {
        lc::test::EventCounter errors;
        errors.watch(quads);
        quads->Update();
        return std::make_pair(errors.count, errors.text);
    };
    auto fresh = [&](vtkPolyData* mesh) {
        auto quads = vtkSmartPointer<vtkLightconeSrFootprintQuads>::New();
        quads->SetInputData(mesh);
        setFrame(quads, kFrame);
        quads->SetCamera(srCamera(64, 36, 75));
        return quads;
    };
    {  // no normals
        vtkSmartPointer<vtkPolyData> mesh = lc::views::srMeshPolyData(cube);
        mesh->GetPointData()->SetNormals(nullptr);
        auto quads = fresh(mesh);
        const auto [count, text] = run(quads);
        EXPECT_EQ(count, 1);
        EXPECT_NE(text.find("no point normals"), std::string::npos) << text;
        EXPECT_EQ(quads->GetOutput()->GetNumberOfPoints(), 0);
    }
    {  // a quadrilateral
        vtkSmartPointer<vtkPolyData> mesh = lc::views::srMeshPolyData(cube);
        vtkNew<vtkCellArray> quad;
        const vtkIdType ids[4] = {0, 1, 2, 3};
        quad->InsertNextCell(4, ids);
        mesh->SetPolys(quad);
        const auto [count, text] = run(fresh(mesh));
        EXPECT_EQ(count, 1);
        EXPECT_NE(text.find("not 3: triangulate"), std::string::npos) << text;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    {  // faster than light, a non-finite time, a camera without pixels
        auto quads = fresh(lc::views::srMeshPolyData(cube));
        quads->SetBeta(1.0, 0, 0);
        const auto [count, text] = run(quads);
        EXPECT_EQ(count, 1);
        EXPECT_NE(text.find("|beta| must be < 1"), std::string::npos) << text;
        quads->SetBeta(0.5, 0, 0);
        quads->SetObserverTime(nan);
        EXPECT_NE(run(quads).second.find("observer time"), std::string::npos);
        quads->SetObserverTime(0);
        lc::sr::ObserverCamera bad = srCamera(0, 36, 75);
        quads->SetCamera(bad);
        EXPECT_NE(run(quads).second.find("camera width"), std::string::npos);
        EXPECT_EQ(quads->GetOutput()->GetNumberOfPoints(), 0);
        quads->SetCamera(srCamera(64, 36, 75));
        EXPECT_EQ(run(quads).first, 0);
        EXPECT_GT(quads->GetOutput()->GetNumberOfPoints(), 0);
    }
    {  // vtkPolyDataNormals leaves zero normals on unused points and degenerate faces: drawn, not refused
        vtkSmartPointer<vtkPolyData> mesh = lc::views::srMeshPolyData(cube);
        const vtkIdType unused = mesh->GetPoints()->InsertNextPoint(1e30, std::nan(""), 0);
        mesh->GetPointData()->GetNormals()->InsertNextTuple3(0, 0, 0);
        mesh->GetPointData()->GetNormals()->SetTuple3(0, 0, 0, 0);  // used by a triangle
        EXPECT_GT(unused, 0);
        auto quads = fresh(mesh), reference = fresh(lc::views::srMeshPolyData(cube));
        EXPECT_EQ(run(quads).first, 0);
        reference->Update();
        EXPECT_GT(quads->GetNumberOfQuads(), 0u);
        EXPECT_EQ(quads->GetNumberOfQuads(), reference->GetNumberOfQuads());
    }
    {  // a failure reported as an exception, and again on the next update (VTK counts a failed run as done)
        vtkSmartPointer<vtkPolyData> mesh = lc::views::srMeshPolyData(cube);
        mesh->GetPointData()->SetNormals(nullptr);
        auto quads = fresh(mesh);
        for (int attempt = 0; attempt < 2; ++attempt) {
            try {
                lc::views::updateOrThrow({quads}, "object 3");
                ADD_FAILURE() << "no exception on attempt " << attempt;
            } catch (const std::runtime_error& e) {
                EXPECT_NE(std::string(e.what()).find("object 3: "), std::string::npos) << e.what();
                EXPECT_NE(std::string(e.what()).find("no point normals"), std::string::npos) << e.what();
            }
        }
    }
    {  // an empty mesh: no quads, no error
        vtkNew<vtkPolyData> empty;
        auto quads = fresh(empty);
        EXPECT_EQ(run(quads).first, 0);
        EXPECT_EQ(quads->GetOutput()->GetNumberOfPoints(), 0);
    }
    {  // the same camera again re-executes nothing; a new observer time does
        auto quads = fresh(lc::views::srMeshPolyData(cube));
        lc::test::EventCounter executions;
        executions.watch(quads, vtkCommand::EndEvent);
        quads->Update();
        quads->SetCamera(srCamera(64, 36, 75));
        quads->Update();
        EXPECT_EQ(executions.count, 1);
        quads->SetObserverTime(0.5);
        quads->Update();
        EXPECT_EQ(executions.count, 2);
    }
}
