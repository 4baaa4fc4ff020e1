#ifndef vtkLightconeSpecialRelativityRenderer_h
#define vtkLightconeSpecialRelativityRenderer_h
// Special relativity by local ray tracing on the GPU (seed 003, Mueller, Grottel, Weiskopf):
// the VTK/OpenGL twin of lc::sr::SrRenderer (core/sr/renderer.cpp).
//
// LocalRayTracing (seed 003 sect. 4): for every triangle of every object the CPU computes the
// conservative screen footprint of its apparent (curved) image, lc::sr::apparentFootprint,
// and emits one screen-space quad covering it. The quad's four vertices carry, as flat
// attributes, the triangle's rest-frame vertices and normals, the object's velocity beta,
// the observer event in the object's rest frame and the material. The fragment shader
// builds the pixel's viewing ray (the generator of the past light cone), boosts it into the
// rest frame (makeRestRay: direction and Doppler factor D), intersects the rest triangle
// exactly (Moller-Trumbore, the test of intersectRest), discards misses and writes
// gl_FragDepth from the apparent distance sigma D, so one depth buffer orders all triangles
// of all objects. Colour = clamp(f Planck(D T)) with f the Phong factor computed in the
// rest frame with the aberrated light and view directions, Planck from a float texture of
// lc::colour::BlackbodyTable (one row per tone map), exactly as SrRenderer.
//
// PolygonDistortion (seed 003 sect. 3.2, the comparison of its Table 1): the flat triangles
// through the apparent vertices (lc::sr::apparentPositions) are rasterised; the fragment
// takes the distance and barycentrics of the pixel's ray on the flat triangle (as
// SrRenderer's PolygonDistortion) and colours with the pixel's Doppler factor, or, with
// PerVertexDoppler on, with the Doppler factor of each apparent vertex interpolated across
// the triangle (the classic per-vertex polygon-distortion colouring).
//
// The formulas are the CPU's, generated (lightconeSrGlsl): the view direction
// (lc::sr::pinholeViewDirection), both triangle hits (lc::sr::triangleLineHit, with the GPU's float
// tolerances) and the shading (lc::sr::srShading); the glsl/sr_* files are glue around them.
//
// Geometry depends on the observer time and the camera, so SetScene / SetObserverTime /
// SetCamera rebuild it (Build(), timed by GetBuildSeconds()); options only change uniforms.
#include "core/colour/blackbody.hpp"
#include "core/scene/scene.hpp"
#include "core/sr/camera.hpp"
#include "core/sr/renderer.hpp"

#include "lightconePlanckTexture.h"
#include "vtkLightconeOffscreenRenderer.h"

#include <vtkSmartPointer.h>
#include <vtkTimeStamp.h>

#include <cstddef>
#include <memory>
#include <vector>

class vtkActor;
class vtkCallbackCommand;
class vtkRenderWindow;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

class vtkLightconeSpecialRelativityRenderer : public vtkLightconeOffscreenRenderer {
public:
    static vtkLightconeSpecialRelativityRenderer* New();
    vtkTypeMacro(vtkLightconeSpecialRelativityRenderer, vtkLightconeOffscreenRenderer)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    enum { LocalRayTracing = 0, PolygonDistortion = 1 };

    // Objects at rest in their moving frames, observer and light at rest in S. The camera's
    // width x height is the image size.
    void SetScene(const lc::sr::SrScene& scene, const lc::sr::PinholeCamera& camera);
    // A 'minkowski' lc::Scene, converted as lc::renderSpecialRelativity does (spheres as
    // 96 x 48 UV spheres, meshes as given, first light, background).
    void SetScene(const lc::Scene& scene);
    void SetCamera(const lc::sr::PinholeCamera& camera);
    void SetObserverTime(double t);
    const lc::sr::SrScene& GetSrScene() const { return this->Scene; }
    const lc::sr::PinholeCamera& GetCamera() const { return this->Camera; }

    vtkSetClampMacro(Mode, int, LocalRayTracing, PolygonDistortion);
    vtkGetMacro(Mode, int);
    void SetModeToLocalRayTracing() { this->SetMode(LocalRayTracing); }
    void SetModeToPolygonDistortion() { this->SetMode(PolygonDistortion); }
    // 0: lc::colour::ToneMap::ColourOnly, 1: ToneMap::ReferenceLog.
    vtkSetClampMacro(ToneMap, int, 0, 1);
    vtkGetMacro(ToneMap, int);
    vtkSetMacro(Shading, bool);
    vtkGetMacro(Shading, bool);
    vtkSetMacro(Doppler, bool);
    vtkGetMacro(Doppler, bool);
    // Colour source SrColourSource::ReflectedLight instead of Emitter.
    vtkSetMacro(ReflectedLight, bool);
    vtkGetMacro(ReflectedLight, bool);
    // Polygon distortion only: Doppler factor per apparent vertex, interpolated.
    vtkSetMacro(PerVertexDoppler, bool);
    vtkGetMacro(PerVertexDoppler, bool);
    vtkSetVector3Macro(Background, double);
    vtkGetVector3Macro(Background, double);
    // Mode, tone map, Doppler, shading, colour source and background from SrRenderOptions
    // (BruteForce is drawn as LocalRayTracing: both give the same image).
    void SetOptions(const lc::sr::SrRenderOptions& options);

    // Builds the quads (local ray tracing), the apparent triangles (polygon distortion) and
    // the VTK pipeline; Render*() call it when something changed.
    void Build() override;
    void Render();
    // sRGB display values in [0, 1] (8-bit framebuffer), 3 per pixel, row 0 at the top, as
    // SrImage::rgb.
    std::vector<float> RenderColour();
    // Object and triangle index per pixel (SrImage::object / triangle), -1 for none; a pass
    // with the same depth test, ids encoded exactly in the 8-bit channels (R: object + 1,
    // G, B: triangle + 1, so at most 254 objects and 65534 triangles per object).
    struct Ids {
        std::vector<int> object, triangle;
    };
    Ids RenderIds();

    double GetBuildSeconds() const { return this->BuildSeconds; }
    std::size_t GetNumberOfTriangles() const { return this->Triangles; }
    std::size_t GetNumberOfQuads() const { return this->Quads; }
    std::size_t GetNumberOfFullScreenQuads() const { return this->FullScreenQuads; }
    // Mean quad area in pixels (the fragment work of local ray tracing per triangle).
    double GetMeanQuadPixels() const { return this->MeanQuadPixels; }

protected:
    vtkLightconeSpecialRelativityRenderer();
    ~vtkLightconeSpecialRelativityRenderer() override;

private:
    vtkLightconeSpecialRelativityRenderer(const vtkLightconeSpecialRelativityRenderer&) = delete;
    void operator=(const vtkLightconeSpecialRelativityRenderer&) = delete;

    // Only the scene, camera or observer time: setting a shading option changes uniforms only.
    vtkMTimeType GetBuildDependencyTime() override { return this->GeometryTime.GetMTime(); }
    void UpdateUniforms(bool ids);
    std::vector<unsigned char> ReadPixels();
    static void OnUpdateShader(vtkObject* caller, unsigned long eid, void* clientData, void* callData);
    void BindPlanck(vtkShaderProgram* program);

    lc::sr::SrScene Scene;
    lc::sr::PinholeCamera Camera;
    bool HasScene = false;
    vtkTimeStamp GeometryTime;  // scene, camera or observer time changed
    int Mode = LocalRayTracing;
    int ToneMap = 0;
    bool Shading = true;
    bool Doppler = true;
    bool ReflectedLight = false;
    bool PerVertexDoppler = false;
    double Background[3] = {0, 0, 0};
    double BuildSeconds = 0;
    double DepthScale = 1;
    double MeanQuadPixels = 0;
    std::size_t Triangles = 0, Quads = 0, FullScreenQuads = 0;
    vtkSmartPointer<vtkActor> RayActor, PolygonActor;
    vtkSmartPointer<vtkCallbackCommand> ShaderCallback;
    lc::views::PlanckTexture Planck;  // destroyed before the base class's Window
};

#endif
