// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeSrImageRenderer.h"

#include "offscreen_parts.hpp"
#include "read_back.hpp"
#include "sr_mesh.hpp"
#include "vtkLightconeSrApparentTriangles.h"
#include "vtkLightconeSrFootprintQuads.h"
#include "vtkLightconeSrPolygonMapper.h"
#include "vtkLightconeSrRayTracingMapper.h"
#include "vtkLightconePhotoObjectFilter.h"

#include "core/render/special_relativity.hpp"
#include "core/sr/photo_object.hpp"

#include <vtkActor.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

vtkStandardNewMacro(vtkLightconeSrImageRenderer);

namespace {

// What the pipelines would otherwise refuse mid-build, or read out of bounds: named by object.
void checkObject(const lc::sr::SrObject& o, std::size_t index) {
    const std::string who = "vtkLightconeSrImageRenderer: object " + std::to_string(index) + ": ";
    const lc::sr::TriMesh& m = o.mesh;
    if (!m.normals.empty() && m.normals.size() != m.positions.size())
        throw std::invalid_argument(who + "needs one normal per vertex or none");
    for (const lc::Vec3& p : m.positions)
        if (!p.allFinite()) throw std::invalid_argument(who + "a mesh vertex is not finite");
    for (const lc::Vec3& n : m.normals)
        if (!n.allFinite()) throw std::invalid_argument(who + "a normal is not finite");
    for (const auto& t : m.triangles)
        for (int v : t)
            if (v < 0 || static_cast<std::size_t>(v) >= m.positions.size())
                throw std::invalid_argument(who + "a triangle refers to vertex " + std::to_string(v) + " of " +
                                            std::to_string(m.positions.size()));
    if (!o.frame.origin().allFinite()) throw std::invalid_argument(who + "the frame's origin is not finite");
    try {
        o.material.validate();
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(who + e.what());
    }
}

vtkSmartPointer<vtkActor> techniqueActor(vtkLightconeSrMapper* mapper) {
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    actor->GetProperty()->BackfaceCullingOff();
    return actor;
}

}  // namespace

vtkLightconeSrImageRenderer::vtkLightconeSrImageRenderer() = default;
vtkLightconeSrImageRenderer::~vtkLightconeSrImageRenderer() { this->Planck.release(this->Window); }

void vtkLightconeSrImageRenderer::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Mode: " << (this->Mode == LocalRayTracing ? "LocalRayTracing" : "PolygonDistortion") << "\n"
       << indent << "ToneMap: " << this->ToneMap << "\n"
       << indent << "Shading: " << this->Shading << "\n"
       << indent << "Doppler: " << this->Doppler << "\n"
       << indent << "ReflectedLight: " << this->ReflectedLight << "\n"
       << indent << "PerVertexDoppler: " << this->PerVertexDoppler << "\n"
       << indent << "Objects: " << this->Scene.objects.size() << "\n"
       << indent << "Triangles: " << this->Triangles << "\n"
       << indent << "Quads: " << this->Quads << " (full screen " << this->FullScreenQuads << ")\n"
       << indent << "BuildSeconds: " << this->BuildSeconds << "\n";
}

namespace {
// Polygon distortion rasterises straight edges, which only a pinhole keeps straight.
void requireDrawable(const lc::sr::ObserverCamera& camera, int mode) {
    if (mode == vtkLightconeSrImageRenderer::PolygonDistortion && camera.projection != lc::Camera::Projection::Pinhole)
        throw std::invalid_argument(
            "vtkLightconeSrImageRenderer: polygon distortion on the GPU needs a pinhole camera (a panorama bends the "
            "straight edges the rasteriser draws); use local ray tracing, or the CPU's polygon distortion");
}
}  // namespace

void vtkLightconeSrImageRenderer::SetScene(const lc::sr::SrScene& scene, const lc::sr::ObserverCamera& camera) {
    camera.validate();
    requireDrawable(camera, this->Mode);
    // The id pass encodes object + 1 and triangle + 1 in 8-bit channels.
    for (const auto& o : scene.objects)
        if (o.mesh.triangles.size() > 65534)
            throw std::invalid_argument("vtkLightconeSrImageRenderer: at most 65534 triangles per object");
    if (scene.objects.size() > 254) throw std::invalid_argument("vtkLightconeSrImageRenderer: at most 254 objects");
    for (std::size_t i = 0; i < scene.objects.size(); ++i) checkObject(scene.objects[i], i);
    if (!std::isfinite(scene.observerTime) || !scene.lightPosition.allFinite() ||
        !(std::isfinite(scene.lightTemperatureK) && scene.lightTemperatureK >= 0))
        throw std::invalid_argument(
            "vtkLightconeSrImageRenderer: observer time, light position and temperature must be finite "
            "(temperature >= 0)");
    this->Scene = scene;
    this->Camera = camera;
    this->HasScene = true;
    this->SceneTime.Modified();
    this->GeometryTime.Modified();
    this->Modified();
}

void vtkLightconeSrImageRenderer::SetCamera(const lc::sr::ObserverCamera& camera) {
    camera.validate();
    requireDrawable(camera, this->Mode);
    this->Camera = camera;
    this->GeometryTime.Modified();
    this->Modified();
}

void vtkLightconeSrImageRenderer::SetObserverTime(double t) {
    if (!std::isfinite(t)) throw std::invalid_argument("vtkLightconeSrImageRenderer: observer time must be finite");
    this->Scene.observerTime = t;
    this->GeometryTime.Modified();
    this->Modified();
}

void vtkLightconeSrImageRenderer::SetScene(const lc::Scene& scene) {
    const lc::SrSceneAndCamera in = lc::toSpecialRelativity(scene);  // the CPU renderer's conversion
    this->SetBackground(scene.background(0), scene.background(1), scene.background(2));
    this->SetScene(in.scene, in.camera);
}

void vtkLightconeSrImageRenderer::SetOptions(const lc::sr::SrRenderOptions& o) {
    this->SetMode(o.mode == lc::sr::SrRenderMode::PolygonDistortion ? PolygonDistortion : LocalRayTracing);
    this->SetToneMap(o.toneMap == lc::colour::ToneMap::ColourOnly ? 0 : 1);
    this->SetShading(o.shading);
    this->SetDoppler(o.doppler);
    this->SetReflectedLight(o.colourSource == lc::sr::SrColourSource::ReflectedLight);
    this->SetBackground(o.background(0), o.background(1), o.background(2));
}

void vtkLightconeSrImageRenderer::SetMode(int mode) {
    mode = std::clamp(mode, int(LocalRayTracing), int(PolygonDistortion));
    if (mode == this->Mode) return;
    if (this->HasScene) requireDrawable(this->Camera, mode);
    this->Mode = mode;
    this->GeometryTime.Modified();  // the other technique's pipelines run
    this->Modified();
}

void vtkLightconeSrImageRenderer::MakePipelines() {
    if (this->Renderer)
        for (const ObjectPipelines& p : this->Pipelines) {
            this->Renderer->RemoveActor(p.rayActor);
            this->Renderer->RemoveActor(p.polygonActor);
        }
    this->Pipelines.clear();
    this->ActorsAdded = false;
    this->Triangles = 0;
    for (const lc::sr::SrObject& object : this->Scene.objects) {
        ObjectPipelines p;
        p.mesh = lc::views::srMeshPolyData(object.mesh);
        p.quads = vtkSmartPointer<vtkLightconeSrFootprintQuads>::New();
        p.quads->SetInputData(p.mesh);
        p.rayMapper = vtkSmartPointer<vtkLightconeSrRayTracingMapper>::New();
        p.rayMapper->SetInputConnection(p.quads->GetOutputPort());
        p.rayActor = techniqueActor(p.rayMapper);
        p.photoObject = vtkSmartPointer<vtkLightconePhotoObjectFilter>::New();
        p.photoObject->SetModeToSpecialRelativity();
        p.photoObject->SetInputData(p.mesh);
        p.apparent = vtkSmartPointer<vtkLightconeSrApparentTriangles>::New();
        p.apparent->SetInputConnection(p.photoObject->GetOutputPort());
        p.polygonMapper = vtkSmartPointer<vtkLightconeSrPolygonMapper>::New();
        p.polygonMapper->SetInputConnection(p.apparent->GetOutputPort());
        p.polygonActor = techniqueActor(p.polygonMapper);
        for (vtkLightconeSrMapper* m : {static_cast<vtkLightconeSrMapper*>(p.rayMapper.Get()),
                                        static_cast<vtkLightconeSrMapper*>(p.polygonMapper.Get())})
            m->SetPlanckTexture(&this->Planck);
        this->Triangles += object.mesh.triangles.size();
        this->Pipelines.push_back(p);
    }
    this->PipelinesTime.Modified();
}

void vtkLightconeSrImageRenderer::SetPipelineParameters() {
    const lc::sr::SrScene& scene = this->Scene;
    const lc::sr::ObserverCamera& cam = this->Camera;
    const lc::Vec4 observer(scene.observerTime, cam.position.x(), cam.position.y(), cam.position.z());
    // Depth scale: the apparent distance of the objects' first vertices (any positive value keeps
    // the order; this one keeps the 24-bit resolution where the objects are).
    double scale = 0;
    for (const auto& o : scene.objects)
        if (!o.mesh.positions.empty())
            scale = std::max(
                scale, (lc::sr::apparentPosition(o.frame, o.mesh.positions.front(), observer) - cam.position).norm());
    this->DepthScale = scale > 0 ? scale : 1.0;
    for (std::size_t i = 0; i < this->Pipelines.size(); ++i) {
        const ObjectPipelines& p = this->Pipelines[i];
        const lc::sr::MovingFrame& frame = scene.objects[i].frame;
        const double origin[4] = {0.0, frame.origin().x(), frame.origin().y(), frame.origin().z()};
        p.quads->SetBeta(frame.beta().x(), frame.beta().y(), frame.beta().z());
        p.quads->SetObjectOrigin(origin);
        p.quads->SetObserverTime(scene.observerTime);
        p.quads->SetCamera(cam);
        p.photoObject->SetBeta(frame.beta().x(), frame.beta().y(), frame.beta().z());
        p.photoObject->SetObjectOrigin(origin);
        p.photoObject->SetObserver(observer(0), observer(1), observer(2), observer(3));
        p.apparent->SetEye(cam.position.x(), cam.position.y(), cam.position.z());
        for (vtkLightconeSrMapper* m : {static_cast<vtkLightconeSrMapper*>(p.rayMapper.Get()),
                                        static_cast<vtkLightconeSrMapper*>(p.polygonMapper.Get())}) {
            m->SetCamera(cam);
            m->SetObject(static_cast<int>(i), frame, scene.objects[i].material);
            m->SetObserverTime(scene.observerTime);
            m->SetLight(scene.lightPosition, scene.lightTemperatureK);
            m->SetDepthScale(this->DepthScale);
        }
    }
}

void vtkLightconeSrImageRenderer::Build() {
    if (!this->HasScene) throw std::logic_error("vtkLightconeSrImageRenderer: no scene");
    const auto t0 = std::chrono::steady_clock::now();
    if (this->SceneTime.GetMTime() > this->PipelinesTime.GetMTime()) this->MakePipelines();
    this->SetPipelineParameters();
    // Only the technique shown runs; an algorithm whose parameters did not change does not re-run.
    this->Quads = this->FullScreenQuads = 0;
    double pixels = 0;
    for (std::size_t i = 0; i < this->Pipelines.size(); ++i) {
        const ObjectPipelines& p = this->Pipelines[i];
        const std::string what = "vtkLightconeSrImageRenderer: object " + std::to_string(i);
        if (this->Mode == PolygonDistortion) {
            lc::views::updateOrThrow({p.photoObject, p.apparent}, what);
            continue;
        }
        lc::views::updateOrThrow({p.quads}, what);
        this->Quads += p.quads->GetNumberOfQuads();
        this->FullScreenQuads += p.quads->GetNumberOfFullScreenQuads();
        pixels += p.quads->GetFootprintPixels();
    }
    this->MeanQuadPixels = this->Quads ? pixels / double(this->Quads) : 0;
    if (!this->Window) this->CreateWindow(this->Camera.width, this->Camera.height);
    if (!this->ActorsAdded)
        for (const ObjectPipelines& p : this->Pipelines) {
            this->Renderer->AddActor(p.rayActor);
            this->Renderer->AddActor(p.polygonActor);
        }
    this->ActorsAdded = true;
    this->Window->SetSize(this->Camera.width, this->Camera.height);
    this->BuildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    this->MarkBuilt();
}

void vtkLightconeSrImageRenderer::UpdateUniforms(bool ids) {
    const auto map = this->ToneMap == 0 ? lc::colour::ToneMap::ColourOnly : lc::colour::ToneMap::ReferenceLog;
    for (const ObjectPipelines& p : this->Pipelines) {
        for (vtkLightconeSrMapper* m : {static_cast<vtkLightconeSrMapper*>(p.rayMapper.Get()),
                                        static_cast<vtkLightconeSrMapper*>(p.polygonMapper.Get())}) {
            m->SetToneMap(map);
            m->SetShading(this->Shading);
            m->SetDoppler(this->Doppler);
            m->SetReflectedLight(this->ReflectedLight);
            m->SetDrawIds(ids);
        }
        p.polygonMapper->SetPerVertexDoppler(this->PerVertexDoppler);
        p.rayActor->SetVisibility(this->Mode == LocalRayTracing);
        p.polygonActor->SetVisibility(this->Mode == PolygonDistortion);
    }
    if (ids)
        this->Renderer->SetBackground(0, 0, 0);
    else
        this->Renderer->SetBackground(this->Background);
}

void vtkLightconeSrImageRenderer::Render() {
    this->BuildIfNeeded();
    this->UpdateUniforms(false);
    this->Window->Render();
}

std::vector<unsigned char> vtkLightconeSrImageRenderer::ReadPixels() {
    return this->DrawAndReadBack(this->Camera.width, this->Camera.height);
}

std::vector<float> vtkLightconeSrImageRenderer::RenderColour() {
    this->BuildIfNeeded();
    this->UpdateUniforms(false);
    return lc::views::toUnitFloats(this->ReadPixels());
}

vtkLightconeSrImageRenderer::Ids vtkLightconeSrImageRenderer::RenderIds() {
    this->BuildIfNeeded();
    this->UpdateUniforms(true);
    const std::vector<unsigned char> rgb = this->ReadPixels();
    this->UpdateUniforms(false);
    Ids out;
    const std::size_t n = rgb.size() / 3;
    out.object.resize(n);
    out.triangle.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        out.object[k] = static_cast<int>(rgb[3 * k]) - 1;
        out.triangle[k] =
            out.object[k] < 0 ? -1 : 256 * static_cast<int>(rgb[3 * k + 1]) + static_cast<int>(rgb[3 * k + 2]) - 1;
    }
    return out;
}
