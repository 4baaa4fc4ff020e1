// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeNumericImageRenderer_h
#define vtkLightconeNumericImageRenderer_h
// A GPU (fragment-shader) Hamiltonian ray tracer for any metric written as code (seed 002),
// drawn through VTK's OpenGL pipeline: the GPU twin of lc::renderNumeric + lc::shadePixels for
// scenes without objects (sky, boundary and background only).
//
// One full-screen quad (two triangles given directly in clip space) carries a fragment-shader
// replacement that, per pixel:
//   - builds the viewing direction exactly as lc::Camera::direction (glsl/camera_direction);
//   - maps it to the covariant past-directed null momentum p = g(x0) (-e0 + n^i e_i) with the
//     observer's orthonormal frame e_mu and g(x0) computed on the CPU in double precision
//     (lc::LocalFrame::withVelocity, passed as uniforms);
//   - integrates Hamilton's equations (lcFlow, GENERATED from lc::hamiltonEquations) with g and
//     its exact derivatives from lcMetric, GENERATED from the metric's C++ code g<S>()
//     (core/codegen: the expression recorded, differentiated symbolically, common
//     subexpressions computed once), using an adaptive Dormand-Prince 5(4) stepper in single
//     precision (lcDopri5Step, GENERATED from Boost.Odeint's runge_kutta_dopri5::do_step) under
//     odeint's step control (error norm and step decrease GENERATED from odeint's
//     default_error_checker and default_step_adjuster, the increase from lc::increasedStep;
//     glsl/geodesic_trace is the loop and its stops)
//     whose step is also capped, for asymptotically flat metrics, by
//     StepPerRadius x max(distance from the origin, 1), as lc::traceGeodesic caps it by
//     scene.settings.trace.stepPerRadius (and by more in the far field, see below);
//   - fails a ray whose null condition drifts: lc::constraintDrift (generated
//     lcConstraintDrift, the CPU's measure: |H| relative to |p| |v| or the launch scale) above
//     ConstraintTolerance;
//   - stops where the metric's boundary function (generated likewise; Kerr: r / r_+ - 1) falls
//     below HorizonEpsilon, on escape (asymptotically flat metrics: coordinate radius > escape
//     radius while moving outwards), on the affine limit (scene.settings.trace.maxAffine:
//     background, as the CPU's MaxAffine) or on the step budget (failed);
//   - colours the pixel with the sky texture (lcSkyUv, generated from lc::skyUv), black for the
//     boundary, the scene's background for the affine limit, magenta for a failed ray; a
//     two-ended metric's far side (its generated lcOtherEnd below HorizonEpsilon, checked first
//     as on the CPU) with the far side's sky (lc::Spacetime::otherEndDirection), both skies
//     baked side by side into the actor's texture (bakeSkies).
// Metrics: every metric in core/metrics (Spacetime::symbolic()); one not written as code throws.
//
// Precision: single-precision floats throughout the shader (llvmpipe and desktop GPUs alike);
// metric constants are folded in double and rounded once; the read-back is the 8-bit
// framebuffer, so colours are quantised to 1/255.
#include "core/scene/scene.hpp"

#include "vtkLightconeGeodesicTracerMapper.h"
#include "vtkLightconeOffscreenRenderer.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkActor;

class vtkLightconeNumericImageRenderer : public vtkLightconeOffscreenRenderer {
public:
    static vtkLightconeNumericImageRenderer* New();
    vtkTypeMacro(vtkLightconeNumericImageRenderer, vtkLightconeOffscreenRenderer)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // Pixel classes of RenderIds().
    // OtherEnd: a two-ended metric's far side (its sky; Spacetime::hasOtherEnd).
    enum PixelClass { Sky = 0, Horizon = 1, Failed = 2, Background = 3, Disk = 4, OtherEnd = 5 };

    // The scene's metric must be written as code (every metric in core/metrics; throws
    // otherwise); objects are not drawn (sky, horizon and background only). The camera's
    // width x height is the image size; the escape radius and the step cap per radius come from
    // scene.settings.trace.
    void SetScene(const lc::Scene& scene);

    // Error tolerance of the single-precision Dormand-Prince stepper (absolute and relative).
    vtkSetClampMacro(Tolerance, double, 1e-7, 1e-1);
    vtkGetMacro(Tolerance, double);
    // Budget of trial steps (accepted and rejected) per ray; a ray that exceeds it fails.
    vtkSetClampMacro(MaxSteps, int, 1, 100000);
    vtkGetMacro(MaxSteps, int);
    // Boundary stop where the metric's boundary function < HorizonEpsilon (Kerr: r < r_+ (1 +
    // HorizonEpsilon)); 1e-6 (the CPU margin) is below float resolution, and the outgoing chart
    // lets rays cross the past horizon smoothly anyway.
    vtkSetClampMacro(HorizonEpsilon, double, 0.0, 0.5);
    vtkGetMacro(HorizonEpsilon, double);
    // A ray fails when lc::constraintDrift > ConstraintTolerance (the CPU stops at the same drift
    // above scene.settings.trace.constraintTolerance = 1e-3, in double precision; rays that graze
    // the photon region for hundreds of single-precision steps drift further).
    vtkSetClampMacro(ConstraintTolerance, double, 1e-6, 1.0);
    vtkGetMacro(ConstraintTolerance, double);
    // Step cap (asymptotically flat metrics): a step is at most StepPerRadius x the distance
    // from the origin, so that a long step from far away cannot jump over the strong field while
    // its error estimate, sampled far away, stays small (the CPU's scene.settings.trace.
    // stepPerRadius, 0.1 by default). At the shader's float tolerance 0.3 gives the same image
    // as 0.1 with a third of the steps (docs/PERFORMANCE.md, bench_gpu_geodesic).
    vtkSetClampMacro(StepPerRadius, double, 0.01, 10.0);
    vtkGetMacro(StepPerRadius, double);
    // Far-field steps: a ray moving outwards beyond FarFieldRadiusFactor x the observer's
    // distance from the origin (at least 1) may take steps up to FarFieldStepPerRadius x its
    // radius: a quarter of a black-hole ray's steps are otherwise spent climbing from the
    // observer to the escape radius through nearly flat space, where the error control alone is
    // enough. A value <= StepPerRadius keeps one cap everywhere.
    vtkSetClampMacro(FarFieldRadiusFactor, double, 1.0, 1e6);
    vtkGetMacro(FarFieldRadiusFactor, double);
    vtkSetClampMacro(FarFieldStepPerRadius, double, 0.0, 10.0);
    vtkGetMacro(FarFieldStepPerRadius, double);
    // Sky texture resolution (2n x n texels, nearest sampling for procedural skies).
    vtkSetClampMacro(TextureSize, int, 8, 8192);
    vtkGetMacro(TextureSize, int);

    // Builds the VTK pipeline (done by the Render* calls when needed).
    void Build() override;
    // Only the camera orientation changes: uniforms are updated.
    void SetCameraOrientation(const lc::Vec3& forward, const lc::Vec3& up);
    // The whole camera but its size (fields of view, projection too): uniforms only.
    void SetCamera(const lc::Camera& camera);

    // Draws offscreen into a window of the camera's size.
    void Render();
    // Linear RGB floats in [0, 1] (8-bit framebuffer), 3 per pixel, row 0 at the top.
    std::vector<float> RenderColour();
    // Per pixel: Sky (0), Horizon (1), Failed (2), Background (3) or Disk (4); row 0 at the top.
    std::vector<int> RenderIds();
    // Per pixel the escape direction (unit, coordinate components) of sky pixels, quantised to
    // 2/255 per component (error at most 1/255); (-1, -1, -1) elsewhere (see RenderIds()).
    std::vector<float> RenderEscapeDirections();
    // Per pixel the number of trial steps the ray took (read back in units of 8 steps).
    std::vector<int> RenderStepCounts();

protected:
    vtkLightconeNumericImageRenderer();
    ~vtkLightconeNumericImageRenderer() override;

private:
    vtkLightconeNumericImageRenderer(const vtkLightconeNumericImageRenderer&) = delete;
    void operator=(const vtkLightconeNumericImageRenderer&) = delete;

    void UpdateUniforms(int mode);
    std::vector<unsigned char> ReadPixels(int mode);

    static constexpr vtkLightconeGeodesicTracerMapper::Controls Defaults{};  // the mapper's defaults
    double Tolerance = Defaults.tolerance;
    int MaxSteps = Defaults.maxSteps;
    double HorizonEpsilon = Defaults.horizonEpsilon;
    double ConstraintTolerance = Defaults.constraintTolerance;
    double StepPerRadius = Defaults.stepPerRadius;
    double FarFieldRadiusFactor = Defaults.farFieldRadiusFactor;
    double FarFieldStepPerRadius = Defaults.farFieldStepPerRadius;
    int TextureSize = 1024;
    // The technique: the scene, the tracer's shader, its uniforms and the generated GLSL of the metric.
    vtkSmartPointer<vtkLightconeGeodesicTracerMapper> Mapper;
    vtkSmartPointer<vtkActor> Actor;
};

#endif
