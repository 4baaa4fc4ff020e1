// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconeGeodesicTracerMapper: the tracer's technique as a mapper. Invalid scenes (no
// spacetime, a bad camera, a superluminal observer) are refused with a clear error and leave the
// accepted scene as it was; what changes per frame (camera orientation, mode, controls) must not
// modify the mapper, since a modified mapper rebuilds its shader program (0.1 s on llvmpipe); a
// draw through a standard quad source gives the undistorted sky of flat spacetime: the pixel at
// the image centre looks along the camera's forward direction (lc::skyUv of it, the CPU's lookup).
#include "vtkLightconeGeodesicTracerMapper.h"

#include "offscreen_parts.hpp"
#include "read_back.hpp"

#include "core/accretion/thin_disk.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"
#include "core/scene/sky.hpp"

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkTexture.h>

#include <sstream>

namespace {

lc::Scene flatScene() {
    lc::Scene scene;
    scene.spacetime = std::make_shared<lc::Minkowski>();
    scene.camera.width = 32;
    scene.camera.height = 16;
    scene.sky = std::make_shared<lc::CheckerTexture>(8, 4, lc::Vec3(1, 1, 1), lc::Vec3(0, 0, 1));
    scene.settings.progress = false;
    return scene;
}

}  // namespace

TEST(GeodesicTracerMapper, RefusesInvalidScenesAndKeepsTheAcceptedOne) {
    vtkNew<vtkLightconeGeodesicTracerMapper> mapper;
    EXPECT_FALSE(mapper->HasScene());
    lc::Scene none = flatScene();
    none.spacetime.reset();
    EXPECT_THROW(mapper->SetScene(none), std::invalid_argument);
    mapper->SetScene(flatScene());
    lc::Scene badCamera = flatScene();
    badCamera.camera.width = 0;
    EXPECT_THROW(mapper->SetScene(badCamera), std::invalid_argument);
    lc::Scene fast = flatScene();
    fast.observerVelocity = lc::Vec4(1, 1.5, 0, 0);  // |v| > c
    EXPECT_ANY_THROW(mapper->SetScene(fast));
    lc::Scene texturedDisk = flatScene();  // a disk showing a texture: the CPU's only
    texturedDisk.spacetime = std::make_shared<lc::KerrNewman>(1.0, 0.5, 0.0);
    texturedDisk.observer = lc::Vec4(0, 30, 0, 5);
    lc::DiskObject disk;
    disk.name = "rings";
    disk.model = std::make_shared<lc::ThinDiskModel>(texturedDisk.spacetime, 0, 10, true);
    disk.emission = lc::DiskObject::Emission::Texture;
    texturedDisk.disks.push_back(disk);
    try {
        mapper->SetScene(texturedDisk);
        ADD_FAILURE() << "a textured disk must be refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'rings' shows a texture"), std::string::npos) << e.what();
    }
    EXPECT_EQ(mapper->GetScene().camera.width, 32);
    EXPECT_EQ(mapper->GetScene().spacetime->name(), "minkowski");
    EXPECT_THROW(mapper->SetCameraOrientation(lc::Vec3(0, 0, 1), lc::Vec3(0, 0, 2)), std::invalid_argument);
    std::ostringstream print;
    mapper->Print(print);
    EXPECT_NE(print.str().find("Metric: minkowski"), std::string::npos) << print.str();
}

TEST(GeodesicTracerMapper, PerFrameChangesAreUniformsAndTheCentrePixelSeesForward) {
    vtkNew<vtkLightconeGeodesicTracerMapper> mapper;
    mapper->SetScene(flatScene());
    const vtkMTimeType built = mapper->GetMTime();
    mapper->SetCameraOrientation(lc::Vec3(0.37, 1, 0.21), lc::Vec3(0, 0, 1));
    mapper->SetMode(vtkLightconeGeodesicTracerMapper::ClassAndSteps);
    vtkLightconeGeodesicTracerMapper::Controls controls;
    controls.tolerance = 1e-4;
    mapper->SetControls(controls);
    EXPECT_EQ(mapper->GetMTime(), built) << "a per-frame change would rebuild the shader";

    mapper->SetMode(vtkLightconeGeodesicTracerMapper::Colour);
    vtkSmartPointer<vtkActor> actor = lc::views::clipSpaceQuadActor(mapper);
    const lc::Scene& scene = mapper->GetScene();
    actor->SetTexture(lc::views::bakeTexture(scene.sky, scene.background, 64));
    vtkSmartPointer<vtkRenderWindow> window = lc::views::offscreenWindow(32, 16);
    window->GetRenderers()->GetFirstRenderer()->AddActor(actor);
    window->Render();
    const std::vector<unsigned char> rgb = lc::views::readBackRgb(window, 32, 16, "the tracer mapper test");
    // The centre pixel's ray: about forward (0.37, 1, 0.21), seen by a static observer in flat spacetime.
    const lc::Vec3 d = scene.camera.direction(16, 8);
    const lc::Vec2 uv = lc::skyUv<double>(d);
    const lc::Vec3 expected = scene.sky->sample(uv(0), uv(1));
    const std::size_t centre = 3 * (8 * 32 + 16);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[centre + std::size_t(c)] / 255.0, expected(c), 2.0 / 255) << c;
}
