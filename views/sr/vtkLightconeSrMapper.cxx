// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeSrMapper.h"

#include "camera_uniforms.hpp"
#include "core_formula_glsl.hpp"
#include "planck_texture.hpp"
#include "sr_glsl.hpp"
#include "lightcone_glsl_camera_direction.h"
#include "lightcone_glsl_camera_uniforms.h"
#include "lightcone_glsl_planck_uniforms.h"
#include "lightcone_glsl_sr_output.h"
#include "lightcone_glsl_sr_pixel_clip.h"
#include "lightcone_glsl_sr_shade.h"
#include "lightcone_glsl_sr_uniforms.h"

#include <vtkDataObject.h>
#include <vtkOpenGLHelper.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace {

void setVec3(vtkShaderProgram* p, const char* name, const lc::Vec3& v) {
    const float f[3] = {float(v.x()), float(v.y()), float(v.z())};
    p->SetUniform3f(name, f);
}

void requireFinite(double v, const char* what) {
    if (!std::isfinite(v)) throw std::invalid_argument(std::string("SR mapper: ") + what + " must be finite");
}

}  // namespace

vtkLightconeSrMapper::vtkLightconeSrMapper() {
    this->ScalarVisibilityOff();
    // The points are pixel coordinates or eye-relative positions: VTK's shift/scale would change vertexMC.
    this->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
}

void vtkLightconeSrMapper::MapAttribute(const char* name) {
    this->MapDataArrayToVertexAttribute(name, name, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

void vtkLightconeSrMapper::SetCamera(const lc::sr::ObserverCamera& camera) {
    camera.validate();
    this->Camera = camera;
}

void vtkLightconeSrMapper::SetObject(int index, const lc::sr::MovingFrame& frame, const lc::sr::SrMaterial& material) {
    if (index < 0 || index > 253)
        throw std::invalid_argument("SR mapper: object index " + std::to_string(index) + " outside 0..253");
    try {
        material.validate();
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("SR mapper: ") + e.what());
    }
    this->ObjectIndex = index;
    this->Frame = frame;
    this->Material = material;
}

void vtkLightconeSrMapper::SetObserverTime(double t) {
    requireFinite(t, "observer time");
    this->ObserverTime = t;
}

void vtkLightconeSrMapper::SetLight(const lc::Vec3& position, double temperatureK) {
    for (int k = 0; k < 3; ++k) requireFinite(position(k), "light position");
    requireFinite(temperatureK, "light temperature");
    this->LightPosition = position;
    this->LightTemperature = temperatureK;
}

void vtkLightconeSrMapper::SetDepthScale(double scale) {
    if (!(std::isfinite(scale) && scale > 0))
        throw std::invalid_argument("SR mapper: depth scale must be finite and > 0");
    this->DepthScale = scale;
}

void vtkLightconeSrMapper::ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren,
                                               vtkActor* act) {
    // VTK's tag stays first: VTK substitutes its own declarations there afterwards.
    const std::string tag = "//VTK::PositionVC::Dec\n";
    std::string vs = shaders[vtkShader::Vertex]->GetSource();
    vtkShaderProgram::Substitute(vs, "//VTK::PositionVC::Dec",
                                 tag + lightcone_glsl_camera_uniforms + lightcone_glsl_sr_uniforms +
                                     lightcone_glsl_sr_pixel_clip + this->VertexDeclarations(),
                                 false);
    vtkShaderProgram::Substitute(vs, "//VTK::PositionVC::Impl", this->VertexImplementation(), false);
    shaders[vtkShader::Vertex]->SetSource(vs);

    // Shared by both techniques: the pixel's view direction, the rest-frame ray, the colour of
    // core/sr/renderer.cpp and the outputs; then the technique's inputs and hit.
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    vtkShaderProgram::Substitute(fs, "//VTK::PositionVC::Dec",
                                 tag + lightcone_glsl_camera_uniforms + lightcone_glsl_sr_uniforms +
                                     lightcone_glsl_planck_uniforms + lc::views::planckLookupGlsl() +
                                     lc::views::cameraDirectionsGlsl() + lightcone_glsl_camera_direction +
                                     lc::views::restRayGlsl() + lc::views::srShadingGlsl() + lightcone_glsl_sr_shade +
                                     lightcone_glsl_sr_output + this->FragmentDeclarations(),
                                 false);
    vtkShaderProgram::Substitute(fs, "//VTK::TCoord::Impl", this->FragmentImplementation(), false);
    // gl_FragDepth is written by lcOutput.
    vtkShaderProgram::Substitute(fs, "//VTK::Depth::Impl", "", false);
    shaders[vtkShader::Fragment]->SetSource(fs);
    this->Superclass::ReplaceShaderValues(shaders, ren, act);
}

void vtkLightconeSrMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) {
    this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
    vtkShaderProgram* p = cellBO.Program;
    if (!p) return;
    lc::views::setCameraUniforms(p, this->Camera);
    const lc::Vec4 observer(this->ObserverTime, this->Camera.position.x(), this->Camera.position.y(),
                            this->Camera.position.z());
    const lc::Vec4 obsRest = this->Frame.eventToRest(observer);
    const float obs[4] = {float(obsRest(0)), float(obsRest(1)), float(obsRest(2)), float(obsRest(3))};
    p->SetUniform4f("lcObserverRest", obs);
    setVec3(p, "lcBeta", this->Frame.beta());
    const lc::sr::SrMaterial& m = this->Material;
    const float mat[4] = {float(m.ambient), float(m.diffuse), float(m.specular), float(m.shininess)};
    p->SetUniform4f("lcMaterial", mat);
    p->SetUniformf("lcTemperature", float(m.temperatureK));
    p->SetUniformf("lcObjectId", float(this->ObjectIndex));
    setVec3(p, "lcLightRel", this->LightPosition - this->Camera.position);
    p->SetUniformf("lcLightT", float(this->LightTemperature));
    p->SetUniformi("lcShading", this->Shading ? 1 : 0);
    p->SetUniformi("lcDoppler", this->Doppler ? 1 : 0);
    p->SetUniformi("lcReflected", this->ReflectedLight ? 1 : 0);
    p->SetUniformi("lcIdPass", this->DrawIds ? 1 : 0);
    p->SetUniformf("lcDepthScale", float(this->DepthScale));
    this->Planck->bind(ren->GetRenderWindow(), p, "lcPlanck");
    this->Planck->setUniforms(p, this->ToneMap);
}

void vtkLightconeSrMapper::RenderPiece(vtkRenderer* ren, vtkActor* act) {
    if (!this->Planck) {
        vtkErrorMacro(<< "no Planck texture (SetPlanckTexture): nothing drawn");
        return;
    }
    try {
        this->CheckProjection(this->Camera);
    } catch (const std::invalid_argument& e) {
        vtkErrorMacro(<< e.what() << ": nothing drawn");
        return;
    }
    this->Superclass::RenderPiece(ren, act);
}

void vtkLightconeSrMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act) {
    if (this->Planck) this->Planck->deactivate();
    this->Superclass::RenderPieceFinish(ren, act);
}

void vtkLightconeSrMapper::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    const lc::Vec3& beta = this->Frame.beta();
    os << indent
       << "Camera: " << (this->Camera.projection == lc::Camera::Projection::Pinhole ? "pinhole " : "panorama ")
       << this->Camera.width << " x " << this->Camera.height << ", fields " << this->Camera.fovXDeg << " x "
       << this->Camera.fovYDeg << " deg\n"
       << indent << "ObjectIndex: " << this->ObjectIndex << "\n"
       << indent << "Beta: (" << beta.x() << ", " << beta.y() << ", " << beta.z() << ")\n"
       << indent << "Temperature: " << this->Material.temperatureK << " K\n"
       << indent << "ObserverTime: " << this->ObserverTime << "\n"
       << indent << "ToneMap: " << (this->ToneMap == lc::colour::ToneMap::ColourOnly ? "colour only" : "reference log")
       << "\n"
       << indent << "Shading: " << this->Shading << "\n"
       << indent << "Doppler: " << this->Doppler << "\n"
       << indent << "ReflectedLight: " << this->ReflectedLight << "\n"
       << indent << "DrawIds: " << this->DrawIds << "\n"
       << indent << "DepthScale: " << this->DepthScale << "\n";
}
