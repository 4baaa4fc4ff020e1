#include "vtkLightconeGodelImageRenderer.h"

#include "lightconeCoreGlsl.h"
#include "lightconeOffscreen.h"
#include "lightconeReadBack.h"
#include "lightcone_glsl_godel_fragment.h"
#include "lightcone_glsl_godel_fragment_dec.h"
#include "lightcone_glsl_godel_fragment_night.h"
#include "lightcone_glsl_godel_projection.h"
#include "lightcone_glsl_godel_vertex.h"
#include "lightcone_glsl_godel_vertex_dec.h"
#include "lightcone_glsl_planck_lookup.h"

#include "core/colour/blackbody.hpp"
#include "core/godel/isometry.hpp"
#include "core/render/photo_scene.hpp"
#include "core/render/godel_lighting.hpp"
#include "core/scene/godel_placement.hpp"
#include "core/metrics/godel.hpp"
#include "core/numerics/parallel.hpp"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkShaderProgram.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShaderProperty.h>
#include <vtkTexture.h>
#include <vtkUniforms.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkLightconeGodelImageRenderer);

namespace {

// The shaders (views/glsl): the vertex shader projects image directions as lc::Camera::project;
// the fragment shader colours as lc::shadePixels (Planck lookup, sRGB decode, day/night).
std::string vertexDeclarations() {
    return std::string(lightcone_glsl_godel_vertex_dec) + lightcone_glsl_godel_projection;
}
std::string fragmentDeclarations() {
    return std::string(lightcone_glsl_godel_fragment_dec) + lightcone_glsl_planck_lookup + lc::views::srgbDecodeGlsl() +
           lc::views::dayNightGlsl();
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
    if (!dynamic_cast<const lc::GodelCartesian*>(scene.spacetime.get()))
        throw std::invalid_argument("the GPU Goedel renderer needs a scene with the 'godel' metric");
    if (scene.observerVelocity.tail<3>().norm() > 0)
        throw std::invalid_argument("the GPU Goedel renderer takes a static observer");
    scene.camera.validate();
    this->Scene = scene;
    // Lighting tests occlusion in each sphere's own chart: scenes built in code may lack it.
    const double a = dynamic_cast<const lc::GodelCartesian*>(scene.spacetime.get())->a();
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
    const lc::Scene& scene = this->Scene;
    const auto* chart = dynamic_cast<const lc::GodelCartesian*>(scene.spacetime.get());
    const double a = chart->a();

    // Photo-object layers of every object (spheres at rest, meshes, freely falling bodies),
    // directions already in the camera frame: the same data lc::renderGodelPerVertex draws.
    lc::PhotoSceneOptions po;
    po.maxWinding = this->Windings;
    po.latitudes = this->Latitudes;
    po.longitudes = this->Longitudes;
    po.threads = scene.settings.threads;
    const std::shared_ptr<const std::vector<lc::PhotoSceneObject>> built =
        this->PhotoScene ? this->PhotoScene
                         : std::make_shared<const std::vector<lc::PhotoSceneObject>>(lc::buildPhotoScene(scene, po));
    const std::vector<lc::PhotoSceneObject>& photos = *built;
    const bool lit = this->Lighting && !scene.lights.empty();
    std::unique_ptr<lc::GodelLighting> lighting;
    if (lit) lighting = std::make_unique<lc::GodelLighting>(a, scene, std::min(1, scene.settings.windings));

    // Per vertex and layer: the colour multiplier. Lit spheres at rest: ambient plus the light
    // arriving along the light's null rays; black-body emitters: the Planck colour at D T.
    struct ObjectData {
        std::vector<lc::Vec3> light;  // per mesh vertex (same in every layer)
        double temperature = 0;
        lc::TexturePtr texture;
    };
    std::vector<ObjectData> objects(photos.size());
    double maxLambda = 0;
    const std::size_t nSpheres = scene.spheres.size();
    for (std::size_t o = 0; o < photos.size(); ++o) {
        const lc::PhotoSceneObject& photo = photos[o];
        ObjectData& b = objects[o];
        const bool sphere = o < nSpheres;
        b.temperature = sphere ? scene.spheres[o].temperature : scene.meshes[o - nSpheres].temperature;
        b.texture = sphere ? scene.spheres[o].texture : scene.meshes[o - nSpheres].texture;
        b.light.assign(photo.mesh.vertices.size(), lc::Vec3::Ones());
        if (lit && sphere && !scene.spheres[o].motion.moving()) {
            const lc::godel::Isometry fromLocal = lc::godel::Isometry::movingOriginTo(a, scene.spheres[o].centre);
            const long n = static_cast<long>(photo.mesh.vertices.size());
            lc::FirstError errors;
#pragma omp parallel for schedule(dynamic, 64)
            for (long k = 0; k < n; ++k)
                errors.run([&] {
                    const lc::Vec3& v = photo.mesh.vertices[static_cast<std::size_t>(k)];
                    const lc::Vec4 x = fromLocal.apply(lc::Vec4(0, v(0), v(1), v(2)));
                    // A little ambient light so unlit sides stay visible (as lc::shadePixels).
                    b.light[static_cast<std::size_t>(k)] = lc::kAmbientLight * lc::Vec3::Ones() + lighting->at(x, o);
                });
            errors.rethrow();
        }
        for (const auto& layer : photo.layers)
            for (const auto& vi : layer.vertices)
                if (vi.valid) maxLambda = std::max(maxLambda, vi.lambda);
    }
    this->VertexSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // A margin so the farthest image is not clipped by the far plane.
    this->MaxLambda = maxLambda > 0 ? 1.01 * maxLambda : 1.0;

    this->CreateWindow(scene.camera.width, scene.camera.height);
    this->Layers.clear();
    this->Triangles = 0;

    const bool panorama = scene.camera.projection == lc::Camera::Projection::Panorama;
    // The shader declarations, and the callback that binds the Planck lookup texture to every program.
    const std::string vertexDec = vertexDeclarations(), fragmentDec = fragmentDeclarations();
    vtkNew<vtkCallbackCommand> planckBinder;
    planckBinder->SetClientData(this);
    planckBinder->SetCallback(&vtkLightconeGodelImageRenderer::OnUpdateShader);
    for (std::size_t o = 0; o < objects.size(); ++o) {
        const ObjectData& b = objects[o];
        const lc::PhotoSceneObject& photo = photos[o];
        // A black-body emitter is drawn white and coloured per vertex with Planck(D T), D the
        // vertex's frequency ratio (1 for objects at rest: no shift in Goedel, docs/PHYSICS.md 5).
        const lc::TexturePtr surface =
            b.temperature > 0 ? std::make_shared<lc::SolidTexture>(lc::Vec3::Ones()) : b.texture;
        vtkSmartPointer<vtkTexture> texture =
            lc::views::bakeTexture(surface, lc::Vec3(0.8, 0.8, 0.8), this->TextureSize);
        // Night side: only lit spheres (elsewhere every surface counts as fully lit).
        const lc::TexturePtr nightSource =
            lit && o < nSpheres && b.temperature <= 0 ? scene.spheres[o].nightTexture : nullptr;
        vtkSmartPointer<vtkTexture> night =
            nightSource ? lc::views::bakeTexture(nightSource, lc::Vec3::Zero(), this->TextureSize) : nullptr;
        const auto& uv = photo.uv;
        for (const lc::PhotoSceneLayer& layer : photo.layers) {
            if (layer.triangles.empty()) continue;
            const vtkIdType nt = static_cast<vtkIdType>(layer.triangles.size());
            vtkNew<vtkPoints> points;
            points->SetDataTypeToFloat();
            points->SetNumberOfPoints(3 * nt);
            auto tcoords = lc::views::floatArray("TCoords", 2, 3 * nt);
            auto aux = lc::views::floatArray("lcAux", 4, 3 * nt);
            auto light = lc::views::floatArray("lcLight", 3, 3 * nt);
            auto temperature = lc::views::floatArray("lcTemperature", 1, 3 * nt);
            vtkNew<vtkCellArray> cells;
            cells->AllocateExact(nt, 3 * nt);
            for (vtkIdType t = 0; t < nt; ++t) {
                const auto& tri = layer.triangles[static_cast<std::size_t>(t)];
                lc::Vec3 d[3];
                double u[3], v[3];
                lc::Vec3 centroid = lc::Vec3::Zero();
                for (int k = 0; k < 3; ++k) {
                    d[k] = layer.vertices[static_cast<std::size_t>(tri[k])].direction.normalized();
                    centroid += d[k];
                    u[k] = uv[static_cast<std::size_t>(tri[k])](0);
                    v[k] = uv[static_cast<std::size_t>(tri[k])](1);
                }
                centroid = centroid.norm() > 1e-12 ? centroid.normalized() : d[0];
                // Texture seam: keep u continuous across the triangle (the texture repeats).
                const double umax = std::max({u[0], u[1], u[2]});
                for (double& uk : u)
                    if (umax - uk > 0.5) uk += 1;
                const vtkIdType ids[3] = {3 * t, 3 * t + 1, 3 * t + 2};
                for (int k = 0; k < 3; ++k) {
                    const auto& vi = layer.vertices[static_cast<std::size_t>(tri[k])];
                    points->SetPoint(ids[k], d[k].data());
                    tcoords->SetTuple2(ids[k], u[k], v[k]);
                    aux->SetTuple4(ids[k], centroid(0), centroid(1), centroid(2), vi.lambda);
                    const std::size_t vk = static_cast<std::size_t>(tri[k]);
                    const lc::Vec3& l = b.light[vk];
                    light->SetTuple3(ids[k], l(0), l(1), l(2));
                    // D T of a black-body emitter, looked up per fragment (0: texture).
                    temperature->SetValue(ids[k], b.temperature > 0
                                                      ? static_cast<float>(std::clamp(
                                                            layer.frequencyRatio[vk] * b.temperature, 500.0, 1e5))
                                                      : 0.0f);
                }
                cells->InsertNextCell(3, ids);
            }
            this->Triangles += static_cast<std::size_t>(nt);
            vtkNew<vtkPolyData> poly;
            poly->SetPoints(points);
            poly->SetPolys(cells);
            poly->GetPointData()->SetTCoords(tcoords);
            poly->GetPointData()->AddArray(aux);
            poly->GetPointData()->AddArray(light);
            poly->GetPointData()->AddArray(temperature);

            Layer entry;
            entry.object = photo.sceneIndex;
            for (int copy = 0; copy < (panorama ? 2 : 1); ++copy) {
                vtkNew<vtkOpenGLPolyDataMapper> mapper;
                mapper->SetInputData(poly);
                mapper->ScalarVisibilityOff();
                // The directions are unit vectors: VTK's shift/scale would change vertexMC.
                mapper->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
                mapper->MapDataArrayToVertexAttribute("lcAux", "lcAux", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
                mapper->MapDataArrayToVertexAttribute("lcLight", "lcLight", vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                                      -1);
                mapper->MapDataArrayToVertexAttribute("lcTemperature", "lcTemperature",
                                                      vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
                mapper->AddObserver(vtkCommand::UpdateShaderEvent, planckBinder);
                auto actor = vtkSmartPointer<vtkActor>::New();
                actor->SetMapper(mapper);
                actor->SetTexture(texture);
                if (night) actor->GetProperty()->SetTexture("lcNight", night);
                actor->GetProperty()->LightingOff();
                vtkShaderProperty* sp = actor->GetShaderProperty();
                sp->AddVertexShaderReplacement("//VTK::PositionVC::Dec", true, vertexDec, false);
                sp->AddVertexShaderReplacement("//VTK::PositionVC::Impl", true, lightcone_glsl_godel_vertex, false);
                sp->AddFragmentShaderReplacement("//VTK::PositionVC::Dec", true, fragmentDec, false);
                sp->AddFragmentShaderReplacement(
                    "//VTK::TCoord::Impl", true,
                    night ? lightcone_glsl_godel_fragment_night : lightcone_glsl_godel_fragment, false);
                sp->GetVertexCustomUniforms()->SetUniformi("lcWrap", copy);
                this->Renderer->AddActor(actor);
                (copy == 0 ? entry.actor : entry.wrapActor) = actor;
            }
            this->Layers.push_back(entry);
        }
    }
    this->MarkBuilt();
    this->UpdateUniforms(false);
}

void vtkLightconeGodelImageRenderer::SetCameraOrientation(const lc::Vec3& forward, const lc::Vec3& up) {
    this->Scene.camera.forward = forward;
    this->Scene.camera.up = up;
    this->Scene.camera.validate();
    if (!this->NeedsBuild()) this->UpdateUniforms(false);
}

void vtkLightconeGodelImageRenderer::OnUpdateShader(vtkObject*, unsigned long, void* self, void* program) {
    auto* r = static_cast<vtkLightconeGodelImageRenderer*>(self);
    r->Planck.bind(r->Window, static_cast<vtkShaderProgram*>(program));
}

void vtkLightconeGodelImageRenderer::UpdateUniforms(bool objectIds) {
    const lc::Camera& cam = this->Scene.camera;
    const lc::Vec3 f = cam.forward.normalized();
    const lc::Vec3 r = f.cross(cam.up).normalized();
    const lc::Vec3 u = r.cross(f);
    const double deg = lc::kPi / 180;
    const int projection = cam.projection == lc::Camera::Projection::Pinhole ? 0 : 1;
    const float tanX = static_cast<float>(projection == 0 ? std::tan(0.5 * cam.fovXDeg * deg) : 1.0);
    const float tanY = static_cast<float>(projection == 0 ? std::tan(0.5 * cam.fovYDeg * deg) : 1.0);
    const double fv[3] = {f(0), f(1), f(2)}, rv[3] = {r(0), r(1), r(2)}, uv[3] = {u(0), u(1), u(2)};
    for (const Layer& layer : this->Layers)
        for (vtkActor* actor : {layer.actor.Get(), layer.wrapActor.Get()}) {
            if (!actor) continue;
            vtkUniforms* vs = actor->GetShaderProperty()->GetVertexCustomUniforms();
            vs->SetUniform3f("lcForward", fv);
            vs->SetUniform3f("lcRight", rv);
            vs->SetUniform3f("lcUp", uv);
            vs->SetUniformi("lcProjection", projection);
            vs->SetUniformf("lcTanHalfX", tanX);
            vs->SetUniformf("lcTanHalfY", tanY);
            vs->SetUniformf("lcHalfX", static_cast<float>(0.5 * cam.fovXDeg * deg));
            vs->SetUniformf("lcHalfY", static_cast<float>(0.5 * cam.fovYDeg * deg));
            vs->SetUniformf("lcMaxLambda", static_cast<float>(this->MaxLambda));
            vtkUniforms* fs = actor->GetShaderProperty()->GetFragmentCustomUniforms();
            fs->SetUniformi("lcMode", objectIds ? 1 : 0);
            this->Planck.setUniforms(fs, lc::colour::ToneMap::ColourOnly);
            fs->SetUniformf("lcObjectId", static_cast<float>(layer.object + 1) / 255.0f);
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
