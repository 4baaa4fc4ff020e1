#include "vtkLightconeSpecialRelativityRenderer.h"

#include "lightconeCoreGlsl.h"
#include "lightconeSrGlsl.h"

#include "lightcone_glsl_sr_flat_hit.h"
#include "lightcone_glsl_sr_output.h"
#include "lightcone_glsl_sr_polygon_fragment.h"
#include "lightcone_glsl_sr_polygon_fragment_dec.h"
#include "lightcone_glsl_sr_polygon_vertex.h"
#include "lightcone_glsl_sr_polygon_vertex_dec.h"
#include "lightcone_glsl_sr_ray_fragment.h"
#include "lightcone_glsl_sr_ray_fragment_dec.h"
#include "lightcone_glsl_sr_ray_vertex.h"
#include "lightcone_glsl_sr_ray_vertex_dec.h"
#include "lightcone_glsl_sr_rest_ray_hit.h"
#include "lightcone_glsl_sr_shade.h"
#include "lightcone_glsl_sr_view_direction.h"

#include "lightconeOffscreen.h"
#include "lightconeReadBack.h"

#include "core/numerics/parallel.hpp"
#include "core/render/special_relativity.hpp"
#include "core/sr/local_ray_tracing.hpp"
#include "core/sr/mesh.hpp"
#include "core/sr/photo_object.hpp"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkShaderProperty.h>
#include <vtkTextureObject.h>
#include <vtkUniforms.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkLightconeSpecialRelativityRenderer);

namespace {

// Shaders (views/glsl). The custom uniforms (lc*, set through vtkUniforms) are declared by VTK
// itself; only the Planck sampler, bound in the UpdateShaderEvent callback, is declared in
// planck_lookup. The fragment functions shared by both techniques: the pixel's view direction
// and the colour of core/sr/renderer.cpp.
std::string sharedFragmentFunctions() {
    return lc::views::planckLookupGlsl() + lc::views::srViewDirectionGlsl() + lightcone_glsl_sr_view_direction +
           lc::views::aberrationGlsl() + lc::views::srShadingGlsl() + lightcone_glsl_sr_shade +
           lightcone_glsl_sr_output;
}

void put(vtkFloatArray* a, vtkIdType i, const lc::Vec3& v) {
    float* p = a->GetPointer(3 * i);
    p[0] = static_cast<float>(v.x()), p[1] = static_cast<float>(v.y()), p[2] = static_cast<float>(v.z());
}
void put(vtkFloatArray* a, vtkIdType i, const lc::Vec3& v, double w) {
    float* p = a->GetPointer(4 * i);
    p[0] = static_cast<float>(v.x()), p[1] = static_cast<float>(v.y()), p[2] = static_cast<float>(v.z());
    p[3] = static_cast<float>(w);
}

vtkSmartPointer<vtkActor> makeActor(const char* vsDec, const char* vsImpl, const std::string& fsDec, const char* fsImpl,
                                    const std::vector<const char*>& attributes, vtkCallbackCommand* callback) {
    vtkNew<vtkOpenGLPolyDataMapper> mapper;
    mapper->ScalarVisibilityOff();
    // vertexMC are pixel coordinates / camera-relative positions: no VBO shift and scale.
    mapper->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
    for (const char* a : attributes)
        mapper->MapDataArrayToVertexAttribute(a, a, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    mapper->AddObserver(vtkCommand::UpdateShaderEvent, callback);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    actor->GetProperty()->BackfaceCullingOff();
    vtkShaderProperty* sp = actor->GetShaderProperty();
    sp->AddVertexShaderReplacement("//VTK::PositionVC::Dec", true, vsDec, false);
    sp->AddVertexShaderReplacement("//VTK::PositionVC::Impl", true, vsImpl, false);
    sp->AddFragmentShaderReplacement("//VTK::PositionVC::Dec", true, fsDec, false);
    sp->AddFragmentShaderReplacement("//VTK::TCoord::Impl", true, fsImpl, false);
    sp->AddFragmentShaderReplacement("//VTK::Depth::Impl", true, "", false);
    return actor;
}

}  // namespace

vtkLightconeSpecialRelativityRenderer::vtkLightconeSpecialRelativityRenderer() {
    // The parameters of lc::sr::SrRenderer's default table, so both look up the same texels.
}
vtkLightconeSpecialRelativityRenderer::~vtkLightconeSpecialRelativityRenderer() { this->Planck.release(this->Window); }

void vtkLightconeSpecialRelativityRenderer::PrintSelf(ostream& os, vtkIndent indent) {
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

void vtkLightconeSpecialRelativityRenderer::SetScene(const lc::sr::SrScene& scene,
                                                     const lc::sr::PinholeCamera& camera) {
    if (camera.width < 1 || camera.height < 1)
        throw std::invalid_argument("vtkLightconeSpecialRelativityRenderer: bad image size");
    for (const auto& o : scene.objects)
        if (o.mesh.triangles.size() > 65534)
            throw std::invalid_argument("vtkLightconeSpecialRelativityRenderer: at most 65534 triangles per object");
    if (scene.objects.size() > 254)
        throw std::invalid_argument("vtkLightconeSpecialRelativityRenderer: at most 254 objects");
    this->Scene = scene;
    this->Camera = camera;
    this->HasScene = true;
    this->GeometryTime.Modified();
    this->Modified();
}

void vtkLightconeSpecialRelativityRenderer::SetCamera(const lc::sr::PinholeCamera& camera) {
    this->Camera = camera;
    this->GeometryTime.Modified();
    this->Modified();
}

void vtkLightconeSpecialRelativityRenderer::SetObserverTime(double t) {
    this->Scene.observerTime = t;
    this->GeometryTime.Modified();
    this->Modified();
}

void vtkLightconeSpecialRelativityRenderer::SetScene(const lc::Scene& scene) {
    const lc::SrSceneAndCamera in = lc::toSpecialRelativity(scene);  // the CPU renderer's conversion
    this->SetBackground(scene.background(0), scene.background(1), scene.background(2));
    this->SetScene(in.scene, in.camera);
}

void vtkLightconeSpecialRelativityRenderer::SetOptions(const lc::sr::SrRenderOptions& o) {
    this->SetMode(o.mode == lc::sr::SrRenderMode::PolygonDistortion ? PolygonDistortion : LocalRayTracing);
    this->SetToneMap(o.toneMap == lc::colour::ToneMap::ColourOnly ? 0 : 1);
    this->SetShading(o.shading);
    this->SetDoppler(o.doppler);
    this->SetReflectedLight(o.colourSource == lc::sr::SrColourSource::ReflectedLight);
    this->SetBackground(o.background(0), o.background(1), o.background(2));
}

void vtkLightconeSpecialRelativityRenderer::Build() {
    if (!this->HasScene) throw std::logic_error("vtkLightconeSpecialRelativityRenderer: no scene");
    const auto t0 = std::chrono::steady_clock::now();
    const lc::sr::SrScene& scene = this->Scene;
    const lc::sr::PinholeCamera& cam = this->Camera;
    const lc::Vec4 observer(scene.observerTime, cam.position.x(), cam.position.y(), cam.position.z());
    const int nObj = static_cast<int>(scene.objects.size());

    // Every triangle of every object, flattened.
    struct Item {
        int object, triangle;
    };
    std::vector<Item> items;
    for (int o = 0; o < nObj; ++o)
        for (int t = 0; t < static_cast<int>(scene.objects[o].mesh.triangles.size()); ++t) items.push_back({o, t});
    const long nItems = static_cast<long>(items.size());
    this->Triangles = items.size();

    // Depth scale: the apparent distance of the objects' first vertices (any positive value
    // keeps the order; this one keeps the 24-bit resolution where the objects are).
    double scale = 0;
    for (const auto& o : scene.objects)
        if (!o.mesh.positions.empty())
            scale = std::max(
                scale, (lc::sr::apparentPosition(o.frame, o.mesh.positions.front(), observer) - cam.position).norm());
    this->DepthScale = scale > 0 ? scale : 1.0;

    // ---- Local ray tracing: one quad per triangle over its conservative footprint.
    std::vector<lc::sr::PixelRect> rects(static_cast<std::size_t>(nItems));
    std::vector<char> full(static_cast<std::size_t>(nItems), 0);
    std::vector<lc::sr::RestTriangle> tris(static_cast<std::size_t>(nItems));
    lc::FirstError errors;
#pragma omp parallel for schedule(dynamic, 64)
    for (long i = 0; i < nItems; ++i)
        errors.run([&] {
            const auto& obj = scene.objects[static_cast<std::size_t>(items[i].object)];
            tris[i] = lc::sr::RestTriangle::fromMesh(obj.mesh, items[i].triangle);
            const lc::sr::ApparentFootprint fp = lc::sr::apparentFootprint(tris[i], obj.frame, observer, cam);
            rects[i] = fp.rect;
            full[i] = fp.fullScreen;
        });
    errors.rethrow();
    std::vector<lc::Vec4> obsRest(nObj);
    for (int o = 0; o < nObj; ++o) obsRest[o] = scene.objects[o].frame.eventToRest(observer);
    std::vector<long> quadOf(static_cast<std::size_t>(nItems), -1);
    long nq = 0;
    double pixels = 0;
    this->FullScreenQuads = 0;
    for (long i = 0; i < nItems; ++i)
        if (!rects[i].empty()) {
            quadOf[i] = nq++;
            pixels += double(rects[i].x1 - rects[i].x0 + 1) * (rects[i].y1 - rects[i].y0 + 1);
            this->FullScreenQuads += full[i] != 0;
        }
    this->Quads = static_cast<std::size_t>(nq);
    this->MeanQuadPixels = nq ? pixels / nq : 0;
    {
        vtkNew<vtkPoints> points;
        points->SetDataTypeToFloat();
        points->SetNumberOfPoints(4 * nq);
        auto p0 = lc::views::floatArray("lcP0", 4, 4 * nq), p1 = lc::views::floatArray("lcP1", 4, 4 * nq),
             p2 = lc::views::floatArray("lcP2", 4, 4 * nq);
        auto n0 = lc::views::floatArray("lcN0", 3, 4 * nq), n1 = lc::views::floatArray("lcN1", 3, 4 * nq),
             n2 = lc::views::floatArray("lcN2", 3, 4 * nq);
        auto beta = lc::views::floatArray("lcBeta", 4, 4 * nq), obs = lc::views::floatArray("lcObs", 4, 4 * nq),
             mat = lc::views::floatArray("lcMat", 4, 4 * nq);
        auto* pts = static_cast<float*>(points->GetVoidPointer(0));
#pragma omp parallel for schedule(static)
        for (long i = 0; i < nItems; ++i) {
            const long q = quadOf[i];
            if (q < 0) continue;
            const auto& obj = scene.objects[static_cast<std::size_t>(items[i].object)];
            const lc::sr::RestTriangle& tri = tris[i];
            const lc::sr::PixelRect& r = rects[i];
            const float xs[4] = {float(r.x0), float(r.x1 + 1), float(r.x1 + 1), float(r.x0)};
            const float ys[4] = {float(r.y0), float(r.y0), float(r.y1 + 1), float(r.y1 + 1)};
            const lc::Vec4& ob = obsRest[static_cast<std::size_t>(items[i].object)];
            const lc::sr::SrMaterial& m = obj.material;
            for (int k = 0; k < 4; ++k) {
                const vtkIdType v = 4 * q + k;
                pts[3 * v] = xs[k], pts[3 * v + 1] = ys[k], pts[3 * v + 2] = 0.0f;
                put(p0, v, tri.p[0], items[i].triangle);
                put(p1, v, tri.p[1], items[i].object);
                put(p2, v, tri.p[2], m.temperatureK);
                put(n0, v, tri.n[0]);
                put(n1, v, tri.n[1]);
                put(n2, v, tri.n[2]);
                put(beta, v, obj.frame.beta(), 0.0);
                float* o4 = obs->GetPointer(4 * v);  // (t', x', y', z')
                o4[0] = float(ob[0]), o4[1] = float(ob[1]), o4[2] = float(ob[2]), o4[3] = float(ob[3]);
                float* mm = mat->GetPointer(4 * v);
                mm[0] = float(m.ambient), mm[1] = float(m.diffuse), mm[2] = float(m.specular),
                mm[3] = float(m.shininess);
            }
        }
        vtkNew<vtkCellArray> cells;
        cells->AllocateExact(2 * nq, 6 * nq);
        for (vtkIdType q = 0; q < nq; ++q) {
            const vtkIdType a[3] = {4 * q, 4 * q + 1, 4 * q + 2}, b[3] = {4 * q, 4 * q + 2, 4 * q + 3};
            cells->InsertNextCell(3, a);
            cells->InsertNextCell(3, b);
        }
        vtkNew<vtkPolyData> poly;
        poly->SetPoints(points);
        poly->SetPolys(cells);
        for (vtkFloatArray* a :
             {p0.Get(), p1.Get(), p2.Get(), n0.Get(), n1.Get(), n2.Get(), beta.Get(), obs.Get(), mat.Get()})
            poly->GetPointData()->AddArray(a);
        if (!this->RayActor) {
            this->ShaderCallback = vtkSmartPointer<vtkCallbackCommand>::New();
            this->ShaderCallback->SetCallback(&vtkLightconeSpecialRelativityRenderer::OnUpdateShader);
            this->ShaderCallback->SetClientData(this);
            this->RayActor = makeActor(
                lightcone_glsl_sr_ray_vertex_dec, lightcone_glsl_sr_ray_vertex,
                lightcone_glsl_sr_ray_fragment_dec + sharedFragmentFunctions() + lc::views::restRayGlsl() +
                    lc::views::srTriangleHitsGlsl() + lightcone_glsl_sr_rest_ray_hit,
                lightcone_glsl_sr_ray_fragment,
                {"lcP0", "lcP1", "lcP2", "lcN0", "lcN1", "lcN2", "lcBeta", "lcObs", "lcMat"}, this->ShaderCallback);
        }
        vtkOpenGLPolyDataMapper::SafeDownCast(this->RayActor->GetMapper())->SetInputData(poly);
    }

    // ---- Polygon distortion: flat triangles through the apparent vertices (own vertices).
    {
        const vtkIdType nt = static_cast<vtkIdType>(nItems);
        std::vector<std::vector<lc::Vec3>> app(nObj);
        for (int o = 0; o < nObj; ++o)
            app[o] = lc::sr::apparentPositions(scene.objects[o].frame, scene.objects[o].mesh.positions, observer);
        vtkNew<vtkPoints> points;
        points->SetDataTypeToFloat();
        points->SetNumberOfPoints(3 * nt);
        auto a0 = lc::views::floatArray("lcA0", 3, 3 * nt), a1 = lc::views::floatArray("lcA1", 3, 3 * nt),
             a2 = lc::views::floatArray("lcA2", 3, 3 * nt);
        auto n0 = lc::views::floatArray("lcN0", 3, 3 * nt), n1 = lc::views::floatArray("lcN1", 3, 3 * nt),
             n2 = lc::views::floatArray("lcN2", 3, 3 * nt);
        auto beta = lc::views::floatArray("lcBeta", 4, 3 * nt), mat = lc::views::floatArray("lcMat", 4, 3 * nt);
        auto ids = lc::views::floatArray("lcIds", 2, 3 * nt), vd = lc::views::floatArray("lcVD", 1, 3 * nt);
        auto* pts = static_cast<float*>(points->GetVoidPointer(0));
#pragma omp parallel for schedule(static)
        for (long i = 0; i < nItems; ++i) {
            const int o = items[i].object;
            const auto& obj = scene.objects[static_cast<std::size_t>(o)];
            const auto& idx = obj.mesh.triangles[static_cast<std::size_t>(items[i].triangle)];
            const lc::sr::RestTriangle& tri = tris[i];
            lc::Vec3 a[3];
            for (int k = 0; k < 3; ++k) a[k] = app[o][static_cast<std::size_t>(idx[k])] - cam.position;
            const lc::sr::SrMaterial& m = obj.material;
            for (int k = 0; k < 3; ++k) {
                const vtkIdType v = 3 * i + k;
                pts[3 * v] = float(a[k].x()), pts[3 * v + 1] = float(a[k].y()), pts[3 * v + 2] = float(a[k].z());
                put(a0, v, a[0]);
                put(a1, v, a[1]);
                put(a2, v, a[2]);
                put(n0, v, tri.n[0]);
                put(n1, v, tri.n[1]);
                put(n2, v, tri.n[2]);
                put(beta, v, obj.frame.beta(), m.temperatureK);
                float* mm = mat->GetPointer(4 * v);
                mm[0] = float(m.ambient), mm[1] = float(m.diffuse), mm[2] = float(m.specular),
                mm[3] = float(m.shininess);
                float* id = ids->GetPointer(2 * v);
                id[0] = float(o), id[1] = float(items[i].triangle);
                // Doppler factor of the light from the apparent vertex, seen along its direction.
                *vd->GetPointer(v) = float(lc::sr::restRayDoppler<double>(obj.frame.beta(), a[k].normalized()));
            }
        }
        vtkNew<vtkCellArray> cells;
        cells->AllocateExact(nt, 3 * nt);
        for (vtkIdType t = 0; t < nt; ++t) {
            const vtkIdType c[3] = {3 * t, 3 * t + 1, 3 * t + 2};
            cells->InsertNextCell(3, c);
        }
        vtkNew<vtkPolyData> poly;
        poly->SetPoints(points);
        poly->SetPolys(cells);
        for (vtkFloatArray* arr :
             {a0.Get(), a1.Get(), a2.Get(), n0.Get(), n1.Get(), n2.Get(), beta.Get(), mat.Get(), ids.Get(), vd.Get()})
            poly->GetPointData()->AddArray(arr);
        if (!this->PolygonActor)
            this->PolygonActor =
                makeActor(lightcone_glsl_sr_polygon_vertex_dec, lightcone_glsl_sr_polygon_vertex,
                          lightcone_glsl_sr_polygon_fragment_dec + sharedFragmentFunctions() +
                              lc::views::srTriangleHitsGlsl() + lightcone_glsl_sr_flat_hit + lc::views::restRayGlsl(),
                          lightcone_glsl_sr_polygon_fragment,
                          {"lcA0", "lcA1", "lcA2", "lcN0", "lcN1", "lcN2", "lcBeta", "lcMat", "lcIds", "lcVD"},
                          this->ShaderCallback);
        vtkOpenGLPolyDataMapper::SafeDownCast(this->PolygonActor->GetMapper())->SetInputData(poly);
    }

    if (!this->Window) {
        this->CreateWindow(cam.width, cam.height);
        this->Renderer->AddActor(this->RayActor);
        this->Renderer->AddActor(this->PolygonActor);
    }
    this->Window->SetSize(cam.width, cam.height);
    this->BuildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    this->MarkBuilt();
}

void vtkLightconeSpecialRelativityRenderer::OnUpdateShader(vtkObject*, unsigned long, void* clientData,
                                                           void* callData) {
    static_cast<vtkLightconeSpecialRelativityRenderer*>(clientData)
        ->BindPlanck(static_cast<vtkShaderProgram*>(callData));
}

// The Planck table as a float RGB texture (samples x 2 rows: ColourOnly, ReferenceLog),
// linear filtering, clamped: texture() then interpolates like BlackbodyTable::lookup.
void vtkLightconeSpecialRelativityRenderer::BindPlanck(vtkShaderProgram* program) {
    this->Planck.bind(this->Window, program);
}

void vtkLightconeSpecialRelativityRenderer::UpdateUniforms(bool ids) {
    const lc::sr::PinholeCamera::Basis b = this->Camera.basis();
    const float fwd[3] = {float(b.forward.x()), float(b.forward.y()), float(b.forward.z())};
    const float right[3] = {float(b.right.x()), float(b.right.y()), float(b.right.z())};
    const float up[3] = {float(b.up.x()), float(b.up.y()), float(b.up.z())};
    const lc::Vec3 lr = this->Scene.lightPosition - this->Camera.position;
    const float lightRel[3] = {float(lr.x()), float(lr.y()), float(lr.z())};
    for (vtkActor* actor : {this->RayActor.Get(), this->PolygonActor.Get()}) {
        const bool poly = actor == this->PolygonActor.Get();
        vtkUniforms* vs = actor->GetShaderProperty()->GetVertexCustomUniforms();
        if (poly) {
            vs->SetUniform3f("lcFwd", fwd);
            vs->SetUniform3f("lcRight", right);
            vs->SetUniform3f("lcUpV", up);
            vs->SetUniformf("lcFocal", float(b.focalPx));
            vs->SetUniformf("lcCx", float(b.cx));
            vs->SetUniformf("lcCy", float(b.cy));
        } else {
            vs->SetUniformf("lcW", float(this->Camera.width));
            vs->SetUniformf("lcH", float(this->Camera.height));
        }
        vtkUniforms* fs = actor->GetShaderProperty()->GetFragmentCustomUniforms();
        fs->SetUniform3f("lcFwdF", fwd);
        fs->SetUniform3f("lcRightF", right);
        fs->SetUniform3f("lcUpF", up);
        fs->SetUniformf("lcFocal", float(b.focalPx));
        fs->SetUniformf("lcCx", float(b.cx));
        fs->SetUniformf("lcCy", float(b.cy));
        fs->SetUniformf("lcH", float(this->Camera.height));
        fs->SetUniform3f("lcLightRel", lightRel);
        fs->SetUniformf("lcDepthScale", float(this->DepthScale));
        fs->SetUniformi("lcIdPass", ids ? 1 : 0);
        this->Planck.setUniforms(
            fs, this->ToneMap == 0 ? lc::colour::ToneMap::ColourOnly : lc::colour::ToneMap::ReferenceLog);
        fs->SetUniformi("lcShading", this->Shading ? 1 : 0);
        fs->SetUniformi("lcDoppler", this->Doppler ? 1 : 0);
        fs->SetUniformi("lcReflected", this->ReflectedLight ? 1 : 0);
        fs->SetUniformf("lcLightT", float(this->Scene.lightTemperatureK));
        if (poly) fs->SetUniformi("lcVertexDoppler", this->PerVertexDoppler ? 1 : 0);
    }
    this->RayActor->SetVisibility(this->Mode == LocalRayTracing);
    this->PolygonActor->SetVisibility(this->Mode == PolygonDistortion);
    if (ids)
        this->Renderer->SetBackground(0, 0, 0);
    else
        this->Renderer->SetBackground(this->Background);
}

void vtkLightconeSpecialRelativityRenderer::Render() {
    this->BuildIfNeeded();
    this->UpdateUniforms(false);
    this->Window->Render();
}

std::vector<unsigned char> vtkLightconeSpecialRelativityRenderer::ReadPixels() {
    return this->DrawAndReadBack(this->Camera.width, this->Camera.height);
}

std::vector<float> vtkLightconeSpecialRelativityRenderer::RenderColour() {
    this->BuildIfNeeded();
    this->UpdateUniforms(false);
    return lc::views::toUnitFloats(this->ReadPixels());
}

vtkLightconeSpecialRelativityRenderer::Ids vtkLightconeSpecialRelativityRenderer::RenderIds() {
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
