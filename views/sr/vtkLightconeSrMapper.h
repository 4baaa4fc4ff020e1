// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeSrMapper_h
#define vtkLightconeSrMapper_h
// The base of the special-relativity techniques' mappers (seed 003; vtkLightconeSrRayTracingMapper,
// vtkLightconeSrPolygonMapper): one object of an lc::sr::SrScene, drawn as the observer at rest in S
// sees it. What both shaders share is here and set as uniforms on the program at each draw
// (glsl/sr_uniforms): the camera, the object (its moving frame, material, emitter temperature and
// index in the scene), the observer's time, the light, the options of lc::sr::SrRenderOptions, the
// Planck lookup (glsl/planck_lookup), the id pass and the depth scale that orders every triangle of
// every object in one depth buffer. None of these setters calls Modified(): a change redraws
// without rebuilding the shader or the buffers. A subclass supplies its vertex and fragment code.
#include "core/colour/blackbody.hpp"
#include "core/sr/lorentz.hpp"
#include "core/sr/observer_camera.hpp"
#include "core/sr/renderer.hpp"

#include <vtkOpenGLPolyDataMapper.h>

#include <string>

namespace lc::views {
class PlanckTexture;
}

class vtkLightconeSrMapper : public vtkOpenGLPolyDataMapper {
public:
    vtkAbstractTypeMacro(vtkLightconeSrMapper, vtkOpenGLPolyDataMapper)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // The scene's camera (lc::Camera: pinhole or panorama, both fields of view) at the observer.
    // Throws std::invalid_argument for a camera that ObserverCamera::validate refuses; a projection
    // the technique cannot draw (CheckProjection) is an error when drawing, and nothing is drawn.
    void SetCamera(const lc::sr::ObserverCamera& camera);
    const lc::sr::ObserverCamera& GetCamera() const { return this->Camera; }
    // The object: its index in the scene (0..253: the id pass writes index + 1 in 8 bits), its
    // frame and its material. Throws std::invalid_argument for an index out of range or a
    // material with a non-finite or negative value.
    void SetObject(int index, const lc::sr::MovingFrame& frame, const lc::sr::SrMaterial& material);
    int GetObjectIndex() const { return this->ObjectIndex; }
    // The observer's time; the observer is at the camera's position then. Finite (else throws).
    void SetObserverTime(double t);
    double GetObserverTime() const { return this->ObserverTime; }
    // The point light at rest in S and its temperature (reflected light). Finite (else throws).
    void SetLight(const lc::Vec3& position, double temperatureK);
    void SetToneMap(lc::colour::ToneMap map) { this->ToneMap = map; }
    void SetShading(bool on) { this->Shading = on; }
    void SetDoppler(bool on) { this->Doppler = on; }
    void SetReflectedLight(bool on) { this->ReflectedLight = on; }
    // The id pass: object and triangle index in the colour channels instead of the shading.
    void SetDrawIds(bool ids) { this->DrawIds = ids; }
    bool GetDrawIds() const { return this->DrawIds; }
    // Depth written: s / (s + scale) for the apparent distance s (> 0; the same for every mapper
    // of one image, so that one depth buffer orders all of them).
    void SetDepthScale(double scale);
    // The Planck lookup texture (owned by the caller, shared by all mappers); required to draw.
    void SetPlanckTexture(lc::views::PlanckTexture* planck) { this->Planck = planck; }

protected:
    vtkLightconeSrMapper();
    ~vtkLightconeSrMapper() override = default;

    // The technique's GLSL: declarations (attributes, outputs, functions) and body of the vertex
    // shader, declarations (inputs, functions) and body of the fragment shader; they replace VTK's
    // //VTK::PositionVC::Dec and ::Impl and //VTK::TCoord::Impl after the shared uniforms and
    // fragment functions, which this class adds.
    virtual std::string VertexDeclarations() const = 0;
    virtual std::string VertexImplementation() const = 0;
    virtual std::string FragmentDeclarations() const = 0;
    virtual std::string FragmentImplementation() const = 0;

    void ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
    void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
    // Without a Planck texture, or with a projection CheckProjection refuses: an error, nothing drawn.
    void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
    void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
    // Throws std::invalid_argument for a projection the technique cannot draw (default: none).
    virtual void CheckProjection(const lc::Camera&) const {}
    // Maps the input's point array `name` to the vertex attribute of the same name.
    void MapAttribute(const char* name);

private:
    vtkLightconeSrMapper(const vtkLightconeSrMapper&) = delete;
    void operator=(const vtkLightconeSrMapper&) = delete;

    lc::sr::ObserverCamera Camera;
    int ObjectIndex = 0;
    lc::sr::MovingFrame Frame;
    lc::sr::SrMaterial Material;
    double ObserverTime = 0;
    lc::Vec3 LightPosition = lc::Vec3(0.0, 10.0, 10.0);
    double LightTemperature = 6000;
    lc::colour::ToneMap ToneMap = lc::colour::ToneMap::ColourOnly;
    bool Shading = true;
    bool Doppler = true;
    bool ReflectedLight = false;
    bool DrawIds = false;
    double DepthScale = 1;
    lc::views::PlanckTexture* Planck = nullptr;
};

#endif
