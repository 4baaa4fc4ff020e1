// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeGodelImageMapper_h
#define vtkLightconeGodelImageMapper_h
// Draws one photo-object layer of a Goedel scene (seed 001 section 6) as the observer sees it: the
// input (vtkLightconeGodelLayerTriangles: unit image directions, centroid and depth, texture
// coordinates, light, observed temperature) is projected by the vertex shader as lc::Camera::project
// does (glsl/godel_projection on the generated lcPinholeHomogeneous / lcPanoramaScreen), with the
// depth lambda / lambdaMax in the depth buffer so that one buffer orders every image of every
// object; the fragment shader shows the actor's texture, or the Planck colour of D T for a
// black-body emitter, times the light (with a night texture: lcDayNight), or the flat object id in
// the coverage pass. Camera, mode and id are uniforms set on the program at draw time: changing
// them redraws without rebuilding the shader or the buffers.
#include "core/scene/camera.hpp"

#include <vtkOpenGLPolyDataMapper.h>

namespace lc::views {
class PlanckTexture;
}

class vtkLightconeGodelImageMapper : public vtkOpenGLPolyDataMapper {
public:
    static vtkLightconeGodelImageMapper* New();
    vtkTypeMacro(vtkLightconeGodelImageMapper, vtkOpenGLPolyDataMapper)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // The camera with forward and up as frame components (lc::frameCamera), as the layers'
    // directions are, and the depth that maps to the far plane. Uniforms only: no Modified(), so
    // no shader rebuild.
    void SetCamera(const lc::Camera& camera);
    void SetMaximumLambda(double lambda) { this->MaximumLambda = lambda; }
    double GetMaximumLambda() const { return this->MaximumLambda; }
    // Panorama: draw the copy shifted by a full turn (the part of a triangle over the +-180 degree edge).
    void SetPanoramaTwin(bool twin) { this->PanoramaTwin = twin; }
    bool GetPanoramaTwin() const { return this->PanoramaTwin; }
    // The coverage pass: the flat colour (ObjectId + 1) / 255 in red instead of the shading.
    void SetDrawObjectIds(bool ids) { this->DrawObjectIds = ids; }
    bool GetDrawObjectIds() const { return this->DrawObjectIds; }
    void SetObjectId(int id) { this->ObjectId = id; }
    int GetObjectId() const { return this->ObjectId; }
    // The Planck lookup texture (owned by the caller, shared by all layers); required.
    void SetPlanckTexture(lc::views::PlanckTexture* planck) { this->Planck = planck; }
    // Whether the actor carries a night texture "lcNight" blended by lcDayNight (changes the shader).
    void SetNightSide(bool night);
    bool GetNightSide() const { return this->NightSide; }

protected:
    vtkLightconeGodelImageMapper();
    ~vtkLightconeGodelImageMapper() override = default;

    void ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
    void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
    // Without a Planck texture: an error, nothing drawn.
    void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
    void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;

private:
    vtkLightconeGodelImageMapper(const vtkLightconeGodelImageMapper&) = delete;
    void operator=(const vtkLightconeGodelImageMapper&) = delete;

    lc::Camera Camera;
    double MaximumLambda = 1;
    bool PanoramaTwin = false;
    bool DrawObjectIds = false;
    int ObjectId = 0;
    bool NightSide = false;
    lc::views::PlanckTexture* Planck = nullptr;
};

#endif
