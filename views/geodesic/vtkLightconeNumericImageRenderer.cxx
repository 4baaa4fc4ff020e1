// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeNumericImageRenderer.h"

#include "offscreen_parts.hpp"
#include "read_back.hpp"
#include "vtkLightconeGeodesicTracerMapper.h"

#include <vtkActor.h>
#include <vtkObjectFactory.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <stdexcept>

vtkStandardNewMacro(vtkLightconeNumericImageRenderer);

vtkLightconeNumericImageRenderer::vtkLightconeNumericImageRenderer()
    : Mapper(vtkSmartPointer<vtkLightconeGeodesicTracerMapper>::New()) {}
vtkLightconeNumericImageRenderer::~vtkLightconeNumericImageRenderer() = default;

void vtkLightconeNumericImageRenderer::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent
       << "Metric: " << (this->Mapper->HasScene() ? this->Mapper->GetScene().spacetime->name() : std::string("(none)"))
       << "\n"
       << indent << "TracerGlsl: " << this->Mapper->GetGeneratedGlslSize() << " characters (generated)\n"
       << indent << "Tolerance: " << this->Tolerance << "\n"
       << indent << "MaxSteps: " << this->MaxSteps << "\n"
       << indent << "HorizonEpsilon: " << this->HorizonEpsilon << "\n"
       << indent << "ConstraintTolerance: " << this->ConstraintTolerance << "\n"
       << indent << "StepPerRadius: " << this->StepPerRadius << "\n"
       << indent << "FarFieldRadiusFactor: " << this->FarFieldRadiusFactor << "\n"
       << indent << "FarFieldStepPerRadius: " << this->FarFieldStepPerRadius << "\n"
       << indent << "TextureSize: " << this->TextureSize << "\n";
}

void vtkLightconeNumericImageRenderer::SetScene(const lc::Scene& scene) {
    this->Mapper->SetScene(scene);  // validates: throws before anything changes here
    this->Invalidate();
    this->Modified();
}

void vtkLightconeNumericImageRenderer::Build() {
    if (!this->Mapper->HasScene()) throw std::logic_error("vtkLightconeNumericImageRenderer: no scene");
    const lc::Scene& scene = this->Mapper->GetScene();
    const lc::Camera& cam = scene.camera;
    // The quad comes from a vtkPlaneSource (clipSpaceQuadActor); the sky is the actor's texture.
    this->Actor = lc::views::clipSpaceQuadActor(this->Mapper);
    this->Actor->SetTexture(scene.spacetime->hasOtherEnd()
                                ? lc::views::bakeSkies(scene.sky, scene.otherSky, scene.background, this->TextureSize)
                                : lc::views::bakeTexture(scene.sky, scene.background, this->TextureSize));
    this->CreateWindow(cam.width, cam.height);
    this->Renderer->AddActor(this->Actor);
    this->MarkBuilt();
    this->UpdateUniforms(0);
}

void vtkLightconeNumericImageRenderer::SetCameraOrientation(const lc::Vec3& forward, const lc::Vec3& up) {
    this->Mapper->SetCameraOrientation(forward, up);  // validates
}

void vtkLightconeNumericImageRenderer::SetCamera(const lc::Camera& camera) {
    this->Mapper->SetCamera(camera);  // validates
}

void vtkLightconeNumericImageRenderer::UpdateUniforms(int mode) {
    vtkLightconeGeodesicTracerMapper::Controls c;
    c.tolerance = this->Tolerance;
    c.maxSteps = this->MaxSteps;
    c.horizonEpsilon = this->HorizonEpsilon;
    c.constraintTolerance = this->ConstraintTolerance;
    c.stepPerRadius = this->StepPerRadius;
    c.farFieldRadiusFactor = this->FarFieldRadiusFactor;
    c.farFieldStepPerRadius = this->FarFieldStepPerRadius;
    this->Mapper->SetControls(c);
    this->Mapper->SetMode(static_cast<vtkLightconeGeodesicTracerMapper::Mode>(mode));
}

void vtkLightconeNumericImageRenderer::Render() {
    this->BuildIfNeeded();
    this->UpdateUniforms(0);
    this->Window->Render();
}

std::vector<unsigned char> vtkLightconeNumericImageRenderer::ReadPixels(int mode) {
    this->BuildIfNeeded();
    this->UpdateUniforms(mode);
    std::vector<unsigned char> rgb =
        this->DrawAndReadBack(this->Mapper->GetScene().camera.width, this->Mapper->GetScene().camera.height);
    if (mode != 0) this->UpdateUniforms(0);
    return rgb;
}

std::vector<float> vtkLightconeNumericImageRenderer::RenderColour() {
    return lc::views::toUnitFloats(this->ReadPixels(0));
}

std::vector<int> vtkLightconeNumericImageRenderer::RenderIds() {
    const std::vector<unsigned char> rgb = this->ReadPixels(1);
    std::vector<int> ids(rgb.size() / 3);
    for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<int>(rgb[3 * k]);
    return ids;
}

std::vector<int> vtkLightconeNumericImageRenderer::RenderStepCounts() {
    const std::vector<unsigned char> rgb = this->ReadPixels(1);
    std::vector<int> steps(rgb.size() / 3);
    for (std::size_t k = 0; k < steps.size(); ++k) steps[k] = 8 * static_cast<int>(rgb[3 * k + 1]);
    return steps;
}

std::vector<float> vtkLightconeNumericImageRenderer::RenderEscapeDirections() {
    const std::vector<unsigned char> rgb = this->ReadPixels(2);
    std::vector<float> out(rgb.size());
    for (std::size_t k = 0; k < rgb.size(); ++k) out[k] = 2.0f * rgb[k] / 255.0f - 1.0f;
    return out;
}
