// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeGodelImageRenderer.h"

#include "core/render/godel_lighting.hpp"

#include "offscreen_parts.hpp"
#include "read_back.hpp"
#include "vtkLightconeGodelImageMapper.h"
#include "vtkLightconeGodelLayerTriangles.h"
#include "vtkLightconeMeshLoader.h"
#include "vtkLightconePhotoObjectFilter.h"

#include "core/godel/isometry.hpp"
#include "core/metrics/godel.hpp"
#include "core/numerics/parallel.hpp"
#include "core/render/photo_scene.hpp"
#include "core/render/post_render.hpp"
#include "core/scene/frame_camera.hpp"
#include "core/scene/godel_placement.hpp"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkLightconeGodelImageRenderer);

namespace {

// An object's mesh in its own frame as the photo-object filter's input: its texture coordinates
// (spherical, as the CPU renderers) and, when lit, the light at each vertex travel with the points.
vtkSmartPointer<vtkPolyData> objectMesh(const lc::godel::Mesh& mesh, const std::vector<lc::Vec3>* light) {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    lc::MeshObject object;
    object.positions = mesh.vertices;
    object.triangles = mesh.triangles;
    lc::io::meshToPolyData(object, poly);
    const std::vector<lc::Vec2> uv = lc::sphericalUvs(mesh);
    const vtkIdType n = static_cast<vtkIdType>(mesh.vertices.size());
    auto tcoords = lc::views::floatArray("TCoords", 2, n);
    for (vtkIdType i = 0; i < n; ++i) tcoords->SetTuple2(i, uv[std::size_t(i)](0), uv[std::size_t(i)](1));
    poly->GetPointData()->SetTCoords(tcoords);
    if (light) {
        auto lit = lc::views::floatArray("lcLight", 3, n);
        for (vtkIdType i = 0; i < n; ++i) lit->SetTuple(i, (*light)[std::size_t(i)].data());
        poly->GetPointData()->AddArray(lit);
    }
    return poly;
}

// The largest depth over the layers' points (every block's "depth").
double maximumDepth(vtkMultiBlockDataSet* photo) {
    double m = 0;
    for (unsigned int b = 0; b < photo->GetNumberOfBlocks(); ++b)
        if (auto* pd = vtkPolyData::SafeDownCast(photo->GetBlock(b)))
            if (vtkDataArray* depth = pd->GetPointData()->GetArray("depth"))
                if (depth->GetNumberOfTuples() > 0) m = std::max(m, depth->GetRange(0)[1]);
    return m;
}

}  // namespace

vtkLightconeGodelImageRenderer::vtkLightconeGodelImageRenderer() = default;
vtkLightconeGodelImageRenderer::~vtkLightconeGodelImageRenderer() = default;

void vtkLightconeGodelImageRenderer::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Latitudes: " << this->Latitudes << "\n"
       << indent << "Longitudes: " << this->Longitudes << "\n"
       << indent << "Windings: " << this->Windings << "\n"
       << indent << "TextureSize: " << this->TextureSize << "\n"
       << indent << "Lighting: " << this->Lighting << "\n"
       << indent << "Layers: " << this->Layers.size() << "\n"
       << indent << "Triangles: " << this->Triangles << "\n"
       << indent << "MaxLambda: " << this->MaxLambda << "\n";
}

void vtkLightconeGodelImageRenderer::SetScene(const lc::Scene& scene) {
    if (!scene.spacetime || !scene.spacetime->godelRadius())
        throw std::invalid_argument("the GPU Goedel renderer needs a scene with the 'godel' metric");
    if (scene.observerVelocity.tail<3>().norm() > 0)
        throw std::invalid_argument("the GPU Goedel renderer takes a static observer");
    scene.camera.validate();
    (void)lc::frameCamera(scene);
    this->Scene = scene;
    // Lighting tests occlusion in each sphere's own chart: scenes built in code may lack it.
    const double a = scene.spacetime->godelRadius().value();
    for (auto& s : this->Scene.spheres)
        if (!s.placement) s.placement = std::make_shared<lc::GodelPlacement>(a, s.centre);
    this->Windings = scene.settings.windings;
    this->PhotoScene.reset();
    this->HasScene = true;
    this->Invalidate();
    this->Modified();
}

void vtkLightconeGodelImageRenderer::SetPhotoScene(std::shared_ptr<const std::vector<lc::PhotoSceneObject>> photos) {
    this->PhotoScene = std::move(photos);
    this->Modified();
}

void vtkLightconeGodelImageRenderer::Build() {
    if (!this->HasScene) throw std::logic_error("vtkLightconeGodelImageRenderer: no scene");
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<vtkSmartPointer<vtkLightconePhotoObjectFilter>> photos = this->BuildPhotoObjects();
    this->VertexSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    this->CreateWindow(this->Scene.camera.width, this->Scene.camera.height);
    this->Layers.clear();
    this->Triangles = 0;
    for (std::size_t o = 0; o < photos.size(); ++o) this->AddObjectLayers(o, photos[o]);
    this->MarkBuilt();
    this->UpdateUniforms(false);
}

std::vector<vtkSmartPointer<vtkLightconePhotoObjectFilter>> vtkLightconeGodelImageRenderer::BuildPhotoObjects() {
    const lc::Scene& scene = this->Scene;
    const double a = scene.spacetime->godelRadius().value();
    lc::PhotoSceneOptions po;
    po.maxWinding = this->Windings;
    po.latitudes = this->Latitudes;
    po.longitudes = this->Longitudes;
    po.threads = scene.settings.threads;
    // Every object (spheres at rest or moving, meshes) through vtkLightconePhotoObjectFilter, the
    // builder the CPU per-vertex renderer also uses (lc::buildPhotoObject), in the camera frame.
    const std::vector<lc::PhotoSource> sources = lc::photoSources(scene, po);
    if (this->PhotoScene && this->PhotoScene->size() != sources.size())
        throw std::invalid_argument("vtkLightconeGodelImageRenderer: the photo scene has " +
                                    std::to_string(this->PhotoScene->size()) + " objects, the scene " +
                                    std::to_string(sources.size()));
    const bool lit = this->IsLit();
    // Without a photo scene (whose worker lit the vertices) the light is computed here, once per scene.
    std::unique_ptr<lc::GodelLighting> lighting;
    if (lit && !this->PhotoScene)
        lighting = std::make_unique<lc::GodelLighting>(a, scene, std::min(1, scene.settings.windings));
    std::vector<vtkSmartPointer<vtkLightconePhotoObjectFilter>> photos;
    double maxLambda = 0;
    for (std::size_t o = 0; o < sources.size(); ++o) {
        const lc::PhotoSource& src = sources[o];
        // Lit spheres at rest: ambient plus the light arriving along the light's null rays, per
        // vertex; computed with a given photo scene (off the caller's thread), else here.
        std::vector<lc::Vec3> light;
        if (lit) light = this->PhotoScene ? (*this->PhotoScene)[o].light : lc::vertexLight(a, scene, *lighting, src, o);
        auto photo = vtkSmartPointer<vtkLightconePhotoObjectFilter>::New();
        photo->SetInputData(objectMesh(src.mesh, light.empty() ? nullptr : &light));
        photo->SetModeToGodel();
        photo->SetGodelA(a);
        photo->SetObserver(scene.observer(0), scene.observer(1), scene.observer(2), scene.observer(3));
        photo->SetCentreEvent(src.centre(0), src.centre(1), src.centre(2), src.centre(3));
        photo->SetMotion(src.motion);
        photo->SetMaxWinding(this->Windings);
        photo->CameraFrameOn();
        if (this->PhotoScene)
            photo->SetPhotoObject(
                std::shared_ptr<const lc::PhotoSceneObject>(this->PhotoScene, &(*this->PhotoScene)[o]));
        // The filter reports a failure as a VTK error event: its text becomes the exception's.
        lc::views::updateOrThrow({photo}, "object '" + src.name + "'");
        maxLambda = std::max(maxLambda, maximumDepth(photo->GetOutput()));
        photos.push_back(photo);
    }
    // A margin so the farthest image is not clipped by the far plane.
    this->MaxLambda = maxLambda > 0 ? 1.01 * maxLambda : 1.0;
    return photos;
}

void vtkLightconeGodelImageRenderer::AddObjectLayers(std::size_t o, vtkLightconePhotoObjectFilter* photo) {
    const lc::Scene& scene = this->Scene;
    const bool panorama = scene.camera.projection == lc::Camera::Projection::Panorama;
    const double temperature = lc::objectTemperature(scene, o);
    // A black-body emitter is drawn white and coloured per vertex with Planck(D T).
    const lc::TexturePtr surface = temperature > 0 ? std::make_shared<lc::SolidTexture>(lc::Vec3::Ones())
                                                   : lc::shownTexture(scene, lc::PostRender{}, o);
    vtkSmartPointer<vtkTexture> texture = lc::views::bakeTexture(surface, lc::Vec3(0.8, 0.8, 0.8), this->TextureSize);
    // Night side: only lit spheres (elsewhere every surface counts as fully lit).
    const lc::TexturePtr nightSource = this->IsLit() && temperature <= 0 ? lc::objectNightTexture(scene, o) : nullptr;
    vtkSmartPointer<vtkTexture> night =
        nightSource ? lc::views::bakeTexture(nightSource, lc::Vec3::Zero(), this->TextureSize) : nullptr;
    // One layer per image block of the photo-object (its images by winding and branch).
    const int blocks = static_cast<int>(photo->GetOutput()->GetNumberOfBlocks());
    for (int b = 0; b < blocks; ++b) {
        auto triangles = vtkSmartPointer<vtkLightconeGodelLayerTriangles>::New();
        triangles->SetInputConnection(photo->GetOutputPort());
        triangles->SetBlock(b);
        triangles->SetTemperature(std::max(0.0, temperature));
        triangles->Update();
        const vtkIdType nt = triangles->GetOutput()->GetNumberOfPolys();
        if (nt == 0) continue;
        this->Triangles += static_cast<std::size_t>(nt);
        Layer entry;
        entry.object = static_cast<int>(o);
        for (int copy = 0; copy < (panorama ? 2 : 1); ++copy) {
            vtkNew<vtkLightconeGodelImageMapper> mapper;
            mapper->SetInputConnection(triangles->GetOutputPort());
            mapper->SetPlanckTexture(&this->Planck);
            mapper->SetNightSide(night != nullptr);
            mapper->SetPanoramaTwin(copy == 1);
            mapper->SetObjectId(entry.object);
            auto actor = vtkSmartPointer<vtkActor>::New();
            actor->SetMapper(mapper);
            actor->SetTexture(texture);
            if (night) actor->GetProperty()->SetTexture("lcNight", night);
            actor->GetProperty()->LightingOff();
            this->Renderer->AddActor(actor);
            (copy == 0 ? entry.mapper : entry.twinMapper) = mapper.Get();
        }
        this->Layers.push_back(entry);
    }
}

void vtkLightconeGodelImageRenderer::SetCameraOrientation(const lc::Vec3& forward, const lc::Vec3& up) {
    lc::Scene scene = this->Scene;
    scene.camera.forward = forward;
    scene.camera.up = up;
    scene.camera.lookAt.reset();  // an explicit orientation turns away from look_at
    scene.camera.validate();
    (void)lc::frameCamera(scene);
    this->Scene.camera = scene.camera;
    if (!this->NeedsBuild()) this->UpdateUniforms(false);
}

void vtkLightconeGodelImageRenderer::UpdateUniforms(bool objectIds) {
    for (const Layer& layer : this->Layers)
        for (vtkLightconeGodelImageMapper* mapper : {layer.mapper, layer.twinMapper}) {
            if (!mapper) continue;
            mapper->SetCamera(lc::frameCamera(this->Scene));  // the layers' directions are frame components
            mapper->SetMaximumLambda(this->MaxLambda);
            mapper->SetDrawObjectIds(objectIds);
        }
    const lc::Vec3& bg = this->Scene.background;
    if (objectIds)
        this->Renderer->SetBackground(0, 0, 0);
    else
        this->Renderer->SetBackground(bg(0), bg(1), bg(2));
}

void vtkLightconeGodelImageRenderer::Render() {
    this->BuildIfNeeded();
    this->Window->Render();
}

std::vector<unsigned char> vtkLightconeGodelImageRenderer::ReadPixels() {
    return this->DrawAndReadBack(this->Scene.camera.width, this->Scene.camera.height);
}

std::vector<float> vtkLightconeGodelImageRenderer::RenderColour() {
    this->BuildIfNeeded();
    this->UpdateUniforms(false);
    return lc::views::toUnitFloats(this->ReadPixels());
}

std::vector<int> vtkLightconeGodelImageRenderer::RenderObjectIds() {
    this->BuildIfNeeded();
    this->UpdateUniforms(true);
    const std::vector<unsigned char> rgb = this->ReadPixels();
    this->UpdateUniforms(false);
    std::vector<int> ids(rgb.size() / 3);
    for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<int>(rgb[3 * k]) - 1;
    return ids;
}
