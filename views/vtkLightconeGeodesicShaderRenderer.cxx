#include "vtkLightconeGeodesicShaderRenderer.h"

#include "lightconeMetricGlsl.h"
#include "lightconeOffscreen.h"
#include "lightconeReadBack.h"
#include "lightcone_glsl_camera_direction.h"
#include "lightcone_glsl_geodesic_trace.h"
#include "lightcone_glsl_geodesic_pixel.h"
#include "lightconeCoreGlsl.h"

#include "core/spacetime/frame.hpp"

#include <vtkActor.h>
#include <vtkObjectFactory.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShaderProperty.h>
#include <vtkTexture.h>
#include <vtkUniforms.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkLightconeGeodesicShaderRenderer);

namespace {

// The fragment shader's declarations: the generated metric, flow and step, then the hand-written
// GLSL files (each mirrors the core function its first line names), after VTK's own declarations
// and the custom uniforms.
std::string fragmentDeclarations(const std::string& tracerGlsl) {
    return std::string("//VTK::ValuePass::Dec\n") + tracerGlsl + lightcone_glsl_geodesic_trace +
           lc::views::cameraDirectionsGlsl() + lightcone_glsl_camera_direction + lc::views::skyUvGlsl();
}

void set4(vtkUniforms* u, const char* name, const lc::Vec4& v) {
    const float f[4] = {static_cast<float>(v(0)), static_cast<float>(v(1)), static_cast<float>(v(2)),
                        static_cast<float>(v(3))};
    u->SetUniform4f(name, f);
}
void set3(vtkUniforms* u, const char* name, const lc::Vec3& v) {
    const float f[3] = {static_cast<float>(v(0)), static_cast<float>(v(1)), static_cast<float>(v(2))};
    u->SetUniform3f(name, f);
}

}  // namespace

vtkLightconeGeodesicShaderRenderer::vtkLightconeGeodesicShaderRenderer() = default;
vtkLightconeGeodesicShaderRenderer::~vtkLightconeGeodesicShaderRenderer() = default;

void vtkLightconeGeodesicShaderRenderer::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Metric: " << (this->HasScene ? this->Scene.spacetime->name() : std::string("(none)")) << "\n"
       << indent << "TracerGlsl: " << this->TracerGlsl.size() << " characters (generated)\n"
       << indent << "Tolerance: " << this->Tolerance << "\n"
       << indent << "MaxSteps: " << this->MaxSteps << "\n"
       << indent << "HorizonEpsilon: " << this->HorizonEpsilon << "\n"
       << indent << "ConstraintTolerance: " << this->ConstraintTolerance << "\n"
       << indent << "StepPerRadius: " << this->StepPerRadius << "\n"
       << indent << "FarFieldRadiusFactor: " << this->FarFieldRadiusFactor << "\n"
       << indent << "FarFieldStepPerRadius: " << this->FarFieldStepPerRadius << "\n"
       << indent << "TextureSize: " << this->TextureSize << "\n";
}

void vtkLightconeGeodesicShaderRenderer::SetScene(const lc::Scene& scene) {
    const lc::Spacetime* st = scene.spacetime.get();
    if (!st) throw std::invalid_argument("the GPU geodesic renderer: the scene has no spacetime");
    this->TracerGlsl = lc::views::tracerShaderFunctions(*st);
    scene.camera.validate();
    // Throws if the observer cannot be static / has a bad velocity here.
    (void)lc::LocalFrame::withVelocity(*st, scene.observer, scene.observerVelocity);
    this->Scene = scene;
    this->HasScene = true;
    this->Invalidate();
    this->Modified();
}

void vtkLightconeGeodesicShaderRenderer::Build() {
    if (!this->HasScene) throw std::logic_error("vtkLightconeGeodesicShaderRenderer: no scene");
    const lc::Camera& cam = this->Scene.camera;

    this->Actor = lc::views::clipSpaceQuadActor();
    this->Actor->SetTexture(lc::views::bakeTexture(this->Scene.sky, this->Scene.background, this->TextureSize));
    vtkShaderProperty* sp = this->Actor->GetShaderProperty();
    sp->AddFragmentShaderReplacement("//VTK::ValuePass::Dec", true, fragmentDeclarations(this->TracerGlsl), false);
    sp->AddFragmentShaderReplacement("//VTK::TCoord::Impl", true, lightcone_glsl_geodesic_pixel, false);

    this->CreateWindow(cam.width, cam.height);
    this->Renderer->AddActor(this->Actor);

    this->MarkBuilt();
    this->UpdateUniforms(0);
}

void vtkLightconeGeodesicShaderRenderer::SetCameraOrientation(const lc::Vec3& forward, const lc::Vec3& up) {
    this->Scene.camera.forward = forward;
    this->Scene.camera.up = up;
    this->Scene.camera.validate();
    if (!this->NeedsBuild()) this->UpdateUniforms(0);
}

void vtkLightconeGeodesicShaderRenderer::UpdateUniforms(int mode) {
    const lc::Scene& scene = this->Scene;
    const lc::Camera& cam = scene.camera;
    const lc::Spacetime& st = *scene.spacetime;
    const lc::LocalFrame frame = lc::LocalFrame::withVelocity(st, scene.observer, scene.observerVelocity);
    const lc::Mat4 g0 = st.metric(scene.observer);
    const lc::Vec3 f = cam.forward.normalized();
    const lc::Vec3 r = f.cross(cam.up).normalized();
    const lc::Vec3 u = r.cross(f);
    const double deg = lc::kPi / 180;
    const lc::TraceOptions& trace = scene.settings.trace;

    vtkUniforms* fs = this->Actor->GetShaderProperty()->GetFragmentCustomUniforms();
    fs->SetUniformi("lcMode", mode);
    fs->SetUniformf("lcBoundaryStop", static_cast<float>(this->HorizonEpsilon));
    fs->SetUniformi("lcEscapes", st.asymptoticallyFlat() ? 1 : 0);
    // The shader keeps its own far-field rule (below): escape at 1000 unless the scene says.
    fs->SetUniformf("lcEscapeRadius", static_cast<float>(trace.escapeRadius > 0 ? trace.escapeRadius : 1e3));
    fs->SetUniformf("lcMaxAffine", static_cast<float>(std::min(trace.maxAffine, 1e30)));
    set3(fs, "lcBackground", scene.background);
    // A step may not exceed StepPerRadius x the distance from the origin (asymptotically flat
    // metrics only).
    fs->SetUniformf("lcStepPerRadius", static_cast<float>(st.asymptoticallyFlat() ? this->StepPerRadius : 1e30));
    const double observerRadius = std::max(1.0, scene.observer.tail<3>().norm());
    fs->SetUniformf("lcFarRadius", static_cast<float>(this->FarFieldRadiusFactor * observerRadius));
    fs->SetUniformf("lcFarStepPerRadius",
                    static_cast<float>(
                        st.asymptoticallyFlat() ? std::max(this->FarFieldStepPerRadius, this->StepPerRadius) : 1e30));
    fs->SetUniformf("lcInitialStep", static_cast<float>(trace.initialStep > 0 ? trace.initialStep : 1e-2));
    fs->SetUniformf("lcTolerance", static_cast<float>(this->Tolerance));
    fs->SetUniformi("lcMaxSteps", this->MaxSteps);
    fs->SetUniformf("lcConstraintTolerance", static_cast<float>(this->ConstraintTolerance));
    set4(fs, "lcObserver", scene.observer);
    set4(fs, "lcE0", frame.e[0]);
    set4(fs, "lcE1", frame.e[1]);
    set4(fs, "lcE2", frame.e[2]);
    set4(fs, "lcE3", frame.e[3]);
    set4(fs, "lcG0r0", g0.row(0).transpose());
    set4(fs, "lcG0r1", g0.row(1).transpose());
    set4(fs, "lcG0r2", g0.row(2).transpose());
    set4(fs, "lcG0r3", g0.row(3).transpose());
    set3(fs, "lcForward", f);
    set3(fs, "lcRight", r);
    set3(fs, "lcUp", u);
    const int projection = cam.projection == lc::Camera::Projection::Pinhole ? 0 : 1;
    fs->SetUniformi("lcProjection", projection);
    fs->SetUniformf("lcTanHalfX", static_cast<float>(std::tan(0.5 * cam.fovXDeg * deg)));
    fs->SetUniformf("lcTanHalfY", static_cast<float>(projection == 0 ? std::tan(0.5 * cam.fovYDeg * deg) : 1.0));
    fs->SetUniformf("lcHalfX", static_cast<float>(0.5 * cam.fovXDeg * deg));
    fs->SetUniformf("lcHalfY", static_cast<float>(0.5 * cam.fovYDeg * deg));
    fs->SetUniformf("lcWidth", static_cast<float>(cam.width));
    fs->SetUniformf("lcHeight", static_cast<float>(cam.height));
}

void vtkLightconeGeodesicShaderRenderer::Render() {
    this->BuildIfNeeded();
    this->UpdateUniforms(0);
    this->Window->Render();
}

std::vector<unsigned char> vtkLightconeGeodesicShaderRenderer::ReadPixels(int mode) {
    this->BuildIfNeeded();
    this->UpdateUniforms(mode);
    std::vector<unsigned char> rgb = this->DrawAndReadBack(this->Scene.camera.width, this->Scene.camera.height);
    if (mode != 0) this->UpdateUniforms(0);
    return rgb;
}

std::vector<float> vtkLightconeGeodesicShaderRenderer::RenderColour() {
    return lc::views::toUnitFloats(this->ReadPixels(0));
}

std::vector<int> vtkLightconeGeodesicShaderRenderer::RenderIds() {
    const std::vector<unsigned char> rgb = this->ReadPixels(1);
    std::vector<int> ids(rgb.size() / 3);
    for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<int>(rgb[3 * k]);
    return ids;
}

std::vector<int> vtkLightconeGeodesicShaderRenderer::RenderStepCounts() {
    const std::vector<unsigned char> rgb = this->ReadPixels(1);
    std::vector<int> steps(rgb.size() / 3);
    for (std::size_t k = 0; k < steps.size(); ++k) steps[k] = 8 * static_cast<int>(rgb[3 * k + 1]);
    return steps;
}

std::vector<float> vtkLightconeGeodesicShaderRenderer::RenderEscapeDirections() {
    const std::vector<unsigned char> rgb = this->ReadPixels(2);
    std::vector<float> out(rgb.size());
    for (std::size_t k = 0; k < rgb.size(); ++k) out[k] = 2.0f * rgb[k] / 255.0f - 1.0f;
    return out;
}
