// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeGeodesicTracerMapper.h"

#include "core_formula_glsl.hpp"
#include "metric_glsl.hpp"
#include "planck_texture.hpp"
#include "star_light_texture.hpp"
#include "lightcone_glsl_star_light.h"
#include "lightcone_glsl_blackbody_light.h"
#include "lightcone_glsl_disk_colour.h"
#include "lightcone_glsl_geodesic_disk.h"
#include "lightcone_glsl_planck_uniforms.h"
#include "camera_uniforms.hpp"
#include "lightcone_glsl_camera_direction.h"
#include "lightcone_glsl_camera_uniforms.h"
#include "lightcone_glsl_geodesic_pixel.h"
#include "lightcone_glsl_geodesic_trace.h"
#include "lightcone_glsl_geodesic_uniforms.h"

#include "core/accretion/thin_disk.hpp"
#include "core/render/post_render.hpp"
#include "core/scene/frame_camera.hpp"

#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkOpenGLHelper.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkLightconeGeodesicTracerMapper);

namespace {

void set4(vtkShaderProgram* p, const char* name, const lc::Vec4& v) {
    const float f[4] = {float(v(0)), float(v(1)), float(v(2)), float(v(3))};
    p->SetUniform4f(name, f);
}
void set3(vtkShaderProgram* p, const char* name, const lc::Vec3& v) {
    const float f[3] = {float(v(0)), float(v(1)), float(v(2))};
    p->SetUniform3f(name, f);
}

// Nodes of the disk's orbit table: linear interpolation between them keeps Omega, u^t and the flux
// within 1e-5 of the CPU's (float storage is 6e-8).
constexpr int kDiskTableNodes = 512;

}  // namespace

vtkLightconeGeodesicTracerMapper::vtkLightconeGeodesicTracerMapper() { this->ScalarVisibilityOff(); }
vtkLightconeGeodesicTracerMapper::~vtkLightconeGeodesicTracerMapper() = default;

void vtkLightconeGeodesicTracerMapper::SetScene(const lc::Scene& scene) {
    const lc::Spacetime* st = scene.spacetime.get();
    if (!st) throw std::invalid_argument("the GPU geodesic tracer: the scene has no spacetime");
    std::string glsl = lc::views::tracerShaderFunctions(*st);  // throws for a metric not written as code
    scene.camera.validate();
    // Throws if the observer cannot be static / has a bad velocity here, or the camera's chart
    // directions are parallel in its rest space.
    (void)lc::frameCamera(scene);
    std::vector<float> table;
    // A black-body sky's g is 1 / |p_t| of the camera ray (unit observed frequency), which holds
    // at infinity only where p_t is conserved: stationary metrics.
    const bool starSky = scene.sky && scene.sky->lightMap();
    if ((scene.skyTemperature || starSky) && !st->declaredStationary())
        throw std::invalid_argument("the GPU geodesic tracer draws a black-body sky for stationary metrics; " +
                                    st->name() + " is not declared stationary (render it without --gpu)");
    if (!starSky)
        this->StarLight.reset();
    else if (!this->StarLight || this->StarLight->sky() != scene.sky)
        this->StarLight = std::make_unique<lc::views::StarLightTexture>(scene.sky);
    if ((scene.skyTemperature || starSky) && !this->Planck)
        this->Planck =
            std::make_unique<lc::views::PlanckTexture>(lc::kShadeMinTemperature, lc::kShadeMaxTemperature, 4096);
    if (!scene.disks.empty()) {
        const lc::DiskObject& d = scene.disks.front();
        if (d.emission == lc::DiskObject::Emission::Texture)
            throw std::invalid_argument("the GPU geodesic tracer draws a disk as a black body or by its flux; '" +
                                        d.name + "' shows a texture (render it without --gpu)");
        const lc::ThinDiskModel& m = *d.model;
        const double step = std::log(m.outerRadius() / m.innerRadius()) / (kDiskTableNodes - 1);
        for (int k = 0; k < kDiskTableNodes; ++k) {
            const double r = m.innerRadius() * std::exp(step * k);
            const lc::CircularOrbit o = m.orbit(r);
            for (double v : {o.omega, o.ut, m.flux(r) / m.maxFlux()}) table.push_back(static_cast<float>(v));
        }
        if (!this->Planck)
            this->Planck =
                std::make_unique<lc::views::PlanckTexture>(lc::kShadeMinTemperature, lc::kShadeMaxTemperature, 4096);
    }
    this->DiskTable = std::move(table);
    this->Scene = scene;
    this->TracerGlsl = std::move(glsl);
    this->SceneSet = true;
    this->Modified();  // another metric: another shader
}

void vtkLightconeGeodesicTracerMapper::SetCameraOrientation(const lc::Vec3& forward, const lc::Vec3& up) {
    lc::Camera camera = this->Scene.camera;
    camera.forward = forward;
    camera.up = up;
    camera.lookAt.reset();  // an explicit orientation turns away from look_at
    camera.validate();
    (void)lc::frameCamera(camera, *this->Scene.spacetime, lc::observerFrame(this->Scene));
    this->Scene.camera = camera;
}

void vtkLightconeGeodesicTracerMapper::SetCamera(const lc::Camera& camera) {
    camera.validate();
    if (!this->SceneSet) throw std::logic_error("vtkLightconeGeodesicTracerMapper: no scene");
    if (camera.width != this->Scene.camera.width || camera.height != this->Scene.camera.height)
        throw std::invalid_argument("the GPU geodesic tracer: a new image size needs SetScene");
    (void)lc::frameCamera(camera, *this->Scene.spacetime, lc::observerFrame(this->Scene));
    this->Scene.camera = camera;
}

void vtkLightconeGeodesicTracerMapper::ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders,
                                                           vtkRenderer* ren, vtkActor* act) {
    if (!this->SceneSet) throw std::logic_error("vtkLightconeGeodesicTracerMapper: no scene");
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    // The generated metric, flow, step and step control, then the glue files that call them.
    // A disk: its uniforms, the generated formulas and the Planck lookup, compiled in by LC_DISK.
    // A black-body sky: the Planck lookup and its temperature, compiled in by LC_SKY_BLACKBODY.
    // A two-ended metric's far side (its generated lcOtherEnd): LC_OTHER_END.
    // A star sky: its map's texture and lookup (glsl/star_light), compiled in by LC_SKY_STARS.
    const bool disk = !this->Scene.disks.empty(), starSky = this->StarLight != nullptr,
               blackbodySky = this->Scene.skyTemperature.has_value() || starSky;
    const std::string planck = disk || blackbodySky ? lightcone_glsl_planck_uniforms + lc::views::planckLookupGlsl() +
                                                          lc::views::srgbDecodeGlsl() + lc::views::postRenderGlsl() +
                                                          lightcone_glsl_blackbody_light
                                                    : std::string();
    const std::string features =
        (disk ? "#define LC_DISK\n#define LC_DISK_TABLE " + std::to_string(kDiskTableNodes) + "\n" +
                    lc::views::diskRadiusGlsl(this->Scene.disks.front().model->radiusExpression()) +
                    lc::views::diskGlsl() + lightcone_glsl_geodesic_disk + planck + lightcone_glsl_disk_colour
              : planck) +
        (this->Scene.skyTemperature ? "#define LC_SKY_BLACKBODY\nuniform float lcSkyTemperature;\n" : "") +
        (starSky ? "#define LC_SKY_STARS\n" + lc::views::textureSampleGlsl() + lightcone_glsl_star_light : "") +
        (this->Scene.spacetime->hasOtherEnd() ? "#define LC_OTHER_END\n" + lc::views::otherEndDirectionGlsl() : "");
    const std::string declarations =
        std::string("//VTK::ValuePass::Dec\n") + lightcone_glsl_camera_uniforms + lightcone_glsl_geodesic_uniforms +
        this->TracerGlsl + features + lc::views::pastNullMomentumGlsl() + lightcone_glsl_geodesic_trace +
        lc::views::cameraDirectionsGlsl() + lightcone_glsl_camera_direction + lc::views::skyUvGlsl();
    vtkShaderProgram::Substitute(fs, "//VTK::ValuePass::Dec", declarations, false);
    vtkShaderProgram::Substitute(fs, "//VTK::TCoord::Impl", lightcone_glsl_geodesic_pixel, false);
    shaders[vtkShader::Fragment]->SetSource(fs);
    this->Superclass::ReplaceShaderValues(shaders, ren, act);
}

void vtkLightconeGeodesicTracerMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren,
                                                                 vtkActor* act) {
    this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
    vtkShaderProgram* p = cellBO.Program;
    if (!p) return;
    const lc::Scene& scene = this->Scene;
    const lc::Spacetime& st = *scene.spacetime;
    const Controls& c = this->TracerControls;
    const lc::LocalFrame frame = lc::observerFrame(scene);
    const lc::Camera cam = lc::frameCamera(scene.camera, st, frame);  // forward and up in the frame
    const lc::Mat4 g0 = st.metric(scene.observer);
    const lc::TraceOptions& trace = scene.settings.trace;
    const bool flat = st.asymptoticallyFlat();

    p->SetUniformi("lcMode", this->DrawMode);
    p->SetUniformf("lcBoundaryStop", float(c.horizonEpsilon));
    p->SetUniformi("lcEscapes", flat ? 1 : 0);
    // The shader keeps its own far-field rule (below): escape at 1000 unless the scene says.
    p->SetUniformf("lcEscapeRadius", float(trace.escapeRadius > 0 ? trace.escapeRadius : 1e3));
    p->SetUniformf("lcMaxAffine", float(std::min(trace.maxAffine, 1e30)));
    set3(p, "lcBackground", scene.background);
    // A step may not exceed stepPerRadius x the distance from the origin (asymptotically flat
    // metrics only), and farFieldStepPerRadius for outgoing rays in the far field.
    p->SetUniformf("lcStepPerRadius", float(flat ? c.stepPerRadius : 1e30));
    const double observerRadius = std::max(1.0, scene.observer.tail<3>().norm());
    p->SetUniformf("lcFarRadius", float(c.farFieldRadiusFactor * observerRadius));
    p->SetUniformf("lcFarStepPerRadius", float(flat ? std::max(c.farFieldStepPerRadius, c.stepPerRadius) : 1e30));
    p->SetUniformf("lcInitialStep", float(trace.initialStep > 0 ? trace.initialStep : 1e-2));
    p->SetUniformf("lcTolerance", float(c.tolerance));
    p->SetUniformi("lcMaxSteps", c.maxSteps);
    p->SetUniformf("lcConstraintTolerance", float(c.constraintTolerance));
    set4(p, "lcObserver", scene.observer);
    set4(p, "lcE0", frame.e[0]);
    set4(p, "lcE1", frame.e[1]);
    set4(p, "lcE2", frame.e[2]);
    set4(p, "lcE3", frame.e[3]);
    set4(p, "lcG0r0", g0.row(0).transpose());
    set4(p, "lcG0r1", g0.row(1).transpose());
    set4(p, "lcG0r2", g0.row(2).transpose());
    set4(p, "lcG0r3", g0.row(3).transpose());
    lc::views::setCameraUniforms(p, cam);
    if (!scene.disks.empty()) this->SetDiskUniforms(p, ren);
    if (scene.skyTemperature) p->SetUniformf("lcSkyTemperature", float(*scene.skyTemperature));
    if (this->StarLight) this->StarLight->bind(ren->GetRenderWindow(), p, "lcStarLight");
    if ((scene.skyTemperature || this->StarLight) && scene.disks.empty()) {  // else bound with the disk's uniforms
        this->Planck->bind(ren->GetRenderWindow(), p, "lcPlanck");
        this->Planck->setUniforms(p, lc::colour::ToneMap::ColourOnly);
    }
}

void vtkLightconeGeodesicTracerMapper::SetDiskUniforms(vtkShaderProgram* p, vtkRenderer* ren) {
    const lc::DiskObject& d = this->Scene.disks.front();
    const lc::ThinDiskModel& m = *d.model;
    p->SetUniformf("lcDiskInner", float(m.innerRadius()));
    p->SetUniformf("lcDiskOuter", float(m.outerRadius()));
    p->SetUniformf("lcDiskLogR0", float(std::log(m.innerRadius())));
    p->SetUniformf("lcDiskLogStep", float(std::log(m.outerRadius() / m.innerRadius()) / (kDiskTableNodes - 1)));
    p->SetUniformi("lcDiskEmission", d.emission == lc::DiskObject::Emission::Flux ? 1 : 0);
    p->SetUniformf("lcDiskTemperature", float(d.temperature));
    p->SetUniform3fv("lcDiskTable", kDiskTableNodes, this->DiskTable.data());
    this->Planck->bind(ren->GetRenderWindow(), p, "lcPlanck");
    this->Planck->setUniforms(p, lc::colour::ToneMap::ColourOnly);  // the tone map of lc::shadePixels
}

void vtkLightconeGeodesicTracerMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act) {
    if (this->Planck) this->Planck->deactivate();
    if (this->StarLight) this->StarLight->deactivate();
    this->Superclass::RenderPieceFinish(ren, act);
}

void vtkLightconeGeodesicTracerMapper::ReleaseGraphicsResources(vtkWindow* window) {
    if (this->Planck) this->Planck->release(vtkRenderWindow::SafeDownCast(window));
    if (this->StarLight) this->StarLight->release(vtkRenderWindow::SafeDownCast(window));
    this->Superclass::ReleaseGraphicsResources(window);
}

void vtkLightconeGeodesicTracerMapper::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    const Controls& c = this->TracerControls;
    os << indent << "Metric: " << (this->SceneSet ? this->Scene.spacetime->name() : std::string("(none)")) << "\n"
       << indent << "GeneratedGlsl: " << this->TracerGlsl.size() << " characters\n"
       << indent << "Mode: " << this->DrawMode << "\n"
       << indent << "Tolerance: " << c.tolerance << "\n"
       << indent << "MaxSteps: " << c.maxSteps << "\n"
       << indent << "StepPerRadius: " << c.stepPerRadius << "\n";
}
