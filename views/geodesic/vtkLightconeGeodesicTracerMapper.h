// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeGeodesicTracerMapper_h
#define vtkLightconeGeodesicTracerMapper_h
// The fragment-shader Hamiltonian tracer of vtkLightconeNumericImageRenderer as a mapper: drawn
// on a full-screen quad (its input, e.g. lc::views::clipSpaceQuadActor's vtkPlaneSource), each
// fragment traces the past null ray of its pixel through the scene's metric (the generated
// lcMetric, lcFlow, lcDopri5Step and step control of metric_glsl, glsl/geodesic_trace) and
// shows the sky (the actor's texture), the boundary, the background or a failed ray. The scene
// sets the shader (SetScene rebuilds it); the camera orientation, the mode and the controls are
// uniforms set on the program at draw time: changing them redraws without a rebuild. A scene with
// an accretion disk also draws it (glsl/geodesic_disk): black body or bolometric intensity.
#include "core/scene/scene.hpp"

#include <vtkOpenGLPolyDataMapper.h>

#include <memory>
#include <string>
#include <vector>

namespace lc::views {
class PlanckTexture;
class StarLightTexture;
}  // namespace lc::views

class vtkLightconeGeodesicTracerMapper : public vtkOpenGLPolyDataMapper {
public:
    static vtkLightconeGeodesicTracerMapper* New();
    vtkTypeMacro(vtkLightconeGeodesicTracerMapper, vtkOpenGLPolyDataMapper)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // What the renderer's settings ask (vtkLightconeNumericImageRenderer documents each).
    struct Controls {
        double tolerance = 1e-5;
        int maxSteps = 3000;
        double horizonEpsilon = 1e-3;
        double constraintTolerance = 1e-2;
        double stepPerRadius = 0.3;
        double farFieldRadiusFactor = 2.0;
        double farFieldStepPerRadius = 1.0;
    };
    enum Mode { Colour = 0, ClassAndSteps = 1, EscapeDirection = 2 };

    // Throws std::invalid_argument for a scene without a spacetime, a metric not written as code,
    // a bad camera or an observer that cannot have its velocity there.
    void SetScene(const lc::Scene& scene);
    bool HasScene() const { return this->SceneSet; }
    const lc::Scene& GetScene() const { return this->Scene; }
    void SetCameraOrientation(const lc::Vec3& forward, const lc::Vec3& up);
    // The whole camera (orientation, fields of view, projection, look_at) as uniforms, no shader
    // rebuild; its width and height must stay (throws std::invalid_argument otherwise).
    void SetCamera(const lc::Camera& camera);
    void SetControls(const Controls& controls) { this->TracerControls = controls; }
    void SetMode(Mode mode) { this->DrawMode = mode; }
    // Characters of generated GLSL (metric, flow, stepper, step control).
    std::size_t GetGeneratedGlslSize() const { return this->TracerGlsl.size(); }

protected:
    vtkLightconeGeodesicTracerMapper();
    ~vtkLightconeGeodesicTracerMapper() override;

    void ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
    void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

private:
    vtkLightconeGeodesicTracerMapper(const vtkLightconeGeodesicTracerMapper&) = delete;
    void operator=(const vtkLightconeGeodesicTracerMapper&) = delete;

    // The scene's accretion disk (glsl/geodesic_disk): its orbits' table and the black-body colours.
    void SetDiskUniforms(vtkShaderProgram* program, vtkRenderer* ren);
    void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
    void ReleaseGraphicsResources(vtkWindow* window) override;

    lc::Scene Scene;
    bool SceneSet = false;
    std::vector<float> DiskTable;  // (Omega, u^t, F / F_max) per node, evenly spaced in log r
    std::unique_ptr<lc::views::PlanckTexture> Planck;
    std::unique_ptr<lc::views::StarLightTexture> StarLight;  // a star sky's (b, b T) map
    std::string TracerGlsl;
    Controls TracerControls;
    Mode DrawMode = Colour;
};

#endif
