// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeGodelImageMapper.h"

#include "camera_uniforms.hpp"
#include "core_formula_glsl.hpp"
#include "planck_texture.hpp"
#include "lightcone_glsl_godel_fragment.h"
#include "lightcone_glsl_godel_fragment_dec.h"
#include "lightcone_glsl_godel_fragment_night.h"
#include "lightcone_glsl_camera_uniforms.h"
#include "lightcone_glsl_godel_projection.h"
#include "lightcone_glsl_godel_vertex.h"
#include "lightcone_glsl_godel_vertex_dec.h"
#include "lightcone_glsl_planck_uniforms.h"

#include <vtkDataObject.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLHelper.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>

#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkLightconeGodelImageMapper);

vtkLightconeGodelImageMapper::vtkLightconeGodelImageMapper() {
    this->ScalarVisibilityOff();
    // The points are unit directions: VTK's shift/scale of the coordinates would change vertexMC.
    this->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
    this->MapDataArrayToVertexAttribute("lcAux", "lcAux", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    this->MapDataArrayToVertexAttribute("lcLight", "lcLight", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    this->MapDataArrayToVertexAttribute("lcTemperature", "lcTemperature", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

void vtkLightconeGodelImageMapper::SetCamera(const lc::Camera& camera) {
    camera.validate();
    this->Camera = camera;
}

void vtkLightconeGodelImageMapper::SetNightSide(bool night) {
    if (night == this->NightSide) return;
    this->NightSide = night;
    this->Modified();  // another fragment shader
}

void vtkLightconeGodelImageMapper::ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren,
                                                       vtkActor* act) {
    std::string vs = shaders[vtkShader::Vertex]->GetSource();
    vtkShaderProgram::Substitute(vs, "//VTK::PositionVC::Dec",
                                 std::string(lightcone_glsl_godel_vertex_dec) + lightcone_glsl_camera_uniforms +
                                     lc::views::cameraProjectionGlsl() + lightcone_glsl_godel_projection,
                                 false);
    vtkShaderProgram::Substitute(vs, "//VTK::PositionVC::Impl", lightcone_glsl_godel_vertex, false);
    shaders[vtkShader::Vertex]->SetSource(vs);
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    vtkShaderProgram::Substitute(fs, "//VTK::PositionVC::Dec",
                                 std::string(lightcone_glsl_godel_fragment_dec) + lightcone_glsl_planck_uniforms +
                                     lc::views::planckLookupGlsl() + lc::views::srgbDecodeGlsl() +
                                     lc::views::dayNightGlsl(),
                                 false);
    vtkShaderProgram::Substitute(fs, "//VTK::TCoord::Impl",
                                 this->NightSide ? lightcone_glsl_godel_fragment_night : lightcone_glsl_godel_fragment,
                                 false);
    shaders[vtkShader::Fragment]->SetSource(fs);
    this->Superclass::ReplaceShaderValues(shaders, ren, act);
}

void vtkLightconeGodelImageMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) {
    this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
    vtkShaderProgram* p = cellBO.Program;
    if (!p) return;
    lc::views::setCameraUniforms(p, this->Camera);
    p->SetUniformf("lcMaxLambda", float(this->MaximumLambda));
    p->SetUniformi("lcWrap", this->PanoramaTwin ? 1 : 0);
    p->SetUniformi("lcMode", this->DrawObjectIds ? 1 : 0);
    p->SetUniformf("lcObjectId", float(this->ObjectId + 1) / 255.0f);
    this->Planck->bind(ren->GetRenderWindow(), p, "lcPlanck");
    this->Planck->setUniforms(p, lc::colour::ToneMap::ColourOnly);
}

void vtkLightconeGodelImageMapper::RenderPiece(vtkRenderer* ren, vtkActor* act) {
    if (!this->Planck) {
        vtkErrorMacro(<< "no Planck texture (SetPlanckTexture): nothing drawn");
        return;
    }
    this->Superclass::RenderPiece(ren, act);
}

void vtkLightconeGodelImageMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act) {
    if (this->Planck) this->Planck->deactivate();
    this->Superclass::RenderPieceFinish(ren, act);
}

void vtkLightconeGodelImageMapper::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent
       << "Projection: " << (this->Camera.projection == lc::Camera::Projection::Pinhole ? "pinhole" : "panorama")
       << "\n"
       << indent << "MaximumLambda: " << this->MaximumLambda << "\n"
       << indent << "PanoramaTwin: " << this->PanoramaTwin << "\n"
       << indent << "DrawObjectIds: " << this->DrawObjectIds << "\n"
       << indent << "ObjectId: " << this->ObjectId << "\n"
       << indent << "NightSide: " << this->NightSide << "\n";
}
