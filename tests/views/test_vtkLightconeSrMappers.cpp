// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeSrRayTracingMapper and vtkLightconeSrPolygonMapper (base vtkLightconeSrMapper): the
// special-relativity techniques as mappers. Invalid settings (a camera without pixels, an object
// index the 8-bit id pass cannot hold, a negative material value, a non-finite time or light, a
// depth scale <= 0) are refused and leave the accepted value; what changes per frame (camera,
// object, time, light, options, id pass) must not modify a mapper, since a modified mapper rebuilds
// its shader program. Drawn through a plain VTK pipeline (mesh -> algorithm -> mapper -> actor),
// each mapper's id pass shows the object index it was given on exactly the pixels where the CPU
// reference lc::sr::SrRenderer shows the object in the same technique (double precision per pixel),
// up to pixels on its outline.
#include "vtkLightconeSrApparentTriangles.h"
#include "vtkLightconeSrFootprintQuads.h"
#include "vtkLightconeSrPolygonMapper.h"
#include "vtkLightconeSrRayTracingMapper.h"
#include "vtkLightconePhotoObjectFilter.h"

#include "offscreen_parts.hpp"
#include "planck_texture.hpp"
#include "read_back.hpp"
#include "sr_mesh.hpp"

#include "core/sr/mesh.hpp"
#include "core/sr/renderer.hpp"

#include "tests/common/sr_camera.hpp"

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include <limits>
#include <sstream>

namespace {

using lc::test::srCamera;

using lc::Vec3;

const lc::sr::MovingFrame kMapperFrame(Vec3(0.6, 0.0, 0.2), Vec3(-1.0, 0.3, -4.0));

}  // namespace

TEST(SrMappers, InvalidSettingsAreRefusedAndPerFrameChangesAreUniforms) {
    vtkNew<vtkLightconeSrRayTracingMapper> ray;
    vtkNew<vtkLightconeSrPolygonMapper> polygon;
    for (vtkLightconeSrMapper* m :
         {static_cast<vtkLightconeSrMapper*>(ray), static_cast<vtkLightconeSrMapper*>(polygon)}) {
        SCOPED_TRACE(m->GetClassName());
        m->SetCamera(srCamera(40, 30, 60));
        const vtkMTimeType built = m->GetMTime();
        EXPECT_THROW(m->SetCamera(srCamera(0, 30, 60)), std::invalid_argument);
        lc::sr::ObserverCamera parallel = srCamera(40, 30, 60);
        parallel.up = parallel.forward;
        EXPECT_THROW(m->SetCamera(parallel), std::invalid_argument);
        EXPECT_EQ(m->GetCamera().width, 40);
        EXPECT_THROW(m->SetObject(254, kMapperFrame, {}), std::invalid_argument);
        EXPECT_THROW(m->SetObject(-1, kMapperFrame, {}), std::invalid_argument);
        lc::sr::SrMaterial negative;
        negative.diffuse = -0.5;
        EXPECT_THROW(m->SetObject(0, kMapperFrame, negative), std::invalid_argument);
        lc::sr::SrMaterial infinite;
        infinite.temperatureK = std::numeric_limits<double>::infinity();
        EXPECT_THROW(m->SetObject(0, kMapperFrame, infinite), std::invalid_argument);
        EXPECT_THROW(m->SetObserverTime(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
        EXPECT_THROW(m->SetLight(Vec3(0, std::numeric_limits<double>::infinity(), 0), 6000), std::invalid_argument);
        EXPECT_THROW(m->SetDepthScale(0), std::invalid_argument);

        lc::sr::ObserverCamera turned = srCamera(40, 30, 60);
        turned.forward = Vec3(0.3, 0.1, -1);
        m->SetCamera(turned);
        m->SetObject(253, kMapperFrame, {});
        m->SetObserverTime(2.5);
        m->SetLight(Vec3(1, 2, 3), 4000);
        m->SetToneMap(lc::colour::ToneMap::ReferenceLog);
        m->SetShading(false);
        m->SetDoppler(false);
        m->SetReflectedLight(true);
        m->SetDrawIds(true);
        m->SetDepthScale(7);
        EXPECT_EQ(m->GetMTime(), built) << "a per-frame change would rebuild the shader";
        EXPECT_EQ(m->GetObjectIndex(), 253);
        std::ostringstream print;
        m->Print(print);
        EXPECT_NE(print.str().find("ObjectIndex: 253"), std::string::npos) << print.str();
    }
    polygon->SetPerVertexDoppler(true);
    EXPECT_TRUE(polygon->GetPerVertexDoppler());
}

TEST(SrMappers, IdPassShowsTheObjectWhereTheCpuRendererDoes) {
    const int W = 96, H = 54;
    const lc::sr::TriMesh cube = lc::sr::makeCube(2.0, 2);
    const lc::sr::ObserverCamera cam = srCamera(W, H, 60);
    lc::sr::SrScene scene;
    scene.objects.push_back({cube, kMapperFrame, {}});
    lc::sr::SrRenderOptions polygonDistortion;
    polygonDistortion.mode = lc::sr::SrRenderMode::PolygonDistortion;
    const lc::sr::SrImage cpuRay = lc::sr::SrRenderer().render(scene, cam, {});
    const lc::sr::SrImage cpuPolygon = lc::sr::SrRenderer().render(scene, cam, polygonDistortion);

    vtkSmartPointer<vtkPolyData> mesh = lc::views::srMeshPolyData(cube);
    const double origin[4] = {0, kMapperFrame.origin().x(), kMapperFrame.origin().y(), kMapperFrame.origin().z()};
    vtkNew<vtkLightconeSrFootprintQuads> quads;
    quads->SetInputData(mesh);
    quads->SetBeta(kMapperFrame.beta().x(), kMapperFrame.beta().y(), kMapperFrame.beta().z());
    quads->SetObjectOrigin(origin);
    quads->SetCamera(cam);
    vtkNew<vtkLightconeSrRayTracingMapper> ray;
    ray->SetInputConnection(quads->GetOutputPort());
    vtkNew<vtkLightconePhotoObjectFilter> photo;
    photo->SetModeToSpecialRelativity();
    photo->SetInputData(mesh);
    photo->SetBeta(kMapperFrame.beta().x(), kMapperFrame.beta().y(), kMapperFrame.beta().z());
    photo->SetObjectOrigin(origin);
    photo->SetObserver(0, 0, 0, 0);
    vtkNew<vtkLightconeSrApparentTriangles> apparent;
    apparent->SetInputConnection(photo->GetOutputPort());
    vtkNew<vtkLightconeSrPolygonMapper> polygon;
    polygon->SetInputConnection(apparent->GetOutputPort());

    lc::views::PlanckTexture planck;
    vtkSmartPointer<vtkRenderWindow> window = lc::views::offscreenWindow(W, H);
    vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer();
    for (vtkLightconeSrMapper* m :
         {static_cast<vtkLightconeSrMapper*>(ray), static_cast<vtkLightconeSrMapper*>(polygon)}) {
        SCOPED_TRACE(m->GetClassName());
        const lc::sr::SrImage& cpu = m == ray.Get() ? cpuRay : cpuPolygon;
        m->SetCamera(cam);
        m->SetObject(7, kMapperFrame, {});
        m->SetPlanckTexture(&planck);
        m->SetDrawIds(true);
        vtkNew<vtkActor> actor;
        actor->SetMapper(m);
        actor->GetProperty()->LightingOff();
        renderer->RemoveAllViewProps();
        renderer->AddActor(actor);
        window->Render();
        const std::vector<unsigned char> rgb = lc::views::readBackRgb(window, W, H, "the SR mapper test");
        std::size_t shown = 0, differing = 0, offOutline = 0;
        for (int j = 0; j < H; ++j)
            for (int i = 0; i < W; ++i) {
                const std::size_t k = static_cast<std::size_t>(j) * W + i;
                const bool gpu = rgb[3 * k] != 0, ref = cpu.object[k] >= 0;
                if (gpu) {
                    EXPECT_EQ(rgb[3 * k], 8) << "pixel " << i << ", " << j;  // object index 7, + 1
                }
                shown += ref;
                if (gpu == ref) continue;
                ++differing;
                bool outline = false;
                for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                    const int ni = i + di, nj = j + dj;
                    if (ni >= 0 && ni < W && nj >= 0 && nj < H && (cpu.object[std::size_t(nj) * W + ni] >= 0) != ref)
                        outline = true;
                }
                offOutline += !outline;
            }
        std::printf("%s: %zu object pixels on the CPU, %zu differ (%zu off its outline)\n", m->GetClassName(), shown,
                    differing, offOutline);
        EXPECT_GT(shown, 150u);
        EXPECT_EQ(offOutline, 0u);
        // Only pixel centres within float rounding of the outline may flip.
        EXPECT_LT(double(differing), 0.01 * double(shown));
    }
    renderer->RemoveAllViewProps();
    planck.release(window);
}
