// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeSrImageRenderer_h
#define vtkLightconeSrImageRenderer_h
// Special relativity on the GPU (seed 003, Mueller, Grottel, Weiskopf): the VTK/OpenGL twin of
// lc::sr::SrRenderer (core/sr/renderer.cpp), offscreen. It owns, per object of the scene, two
// pipelines on the object's rest mesh (vtkPolyData with point normals), one per technique:
//
// LocalRayTracing (seed 003 sect. 4): mesh -> vtkLightconeSrFootprintQuads (one screen quad per
// triangle over the conservative footprint of its curved apparent image) ->
// vtkLightconeSrRayTracingMapper (each fragment intersects its pixel's ray with the rest triangle
// exactly, in the rest frame).
//
// PolygonDistortion (seed 003 sect. 3.2, the comparison of its Table 1): mesh ->
// vtkLightconePhotoObjectFilter (SPECIAL_RELATIVITY: the apparent mesh) ->
// vtkLightconeSrApparentTriangles -> vtkLightconeSrPolygonMapper (flat triangles through the
// apparent vertices, coloured with the pixel's Doppler factor, or with PerVertexDoppler each
// apparent vertex's, interpolated).
//
// Both write the apparent distance on one depth scale, so one depth buffer orders all triangles of
// all objects; the colour is clamp(f Planck(D T)) with f the Phong factor in the rest frame, as
// SrRenderer (vtkLightconeSrMapper). Only the technique shown is executed. The scene, camera,
// observer time and mode set the pipelines' parameters (Build(), timed by GetBuildSeconds(): the
// algorithms that re-executed); the shading options are uniforms of the mappers.
#include "core/scene/scene.hpp"
#include "core/sr/observer_camera.hpp"
#include "core/sr/renderer.hpp"

#include "planck_texture.hpp"
#include "vtkLightconeOffscreenRenderer.h"

#include <vtkSmartPointer.h>
#include <vtkTimeStamp.h>

#include <cstddef>
#include <vector>

class vtkActor;
class vtkLightconePhotoObjectFilter;
class vtkLightconeSrApparentTriangles;
class vtkLightconeSrFootprintQuads;
class vtkLightconeSrMapper;
class vtkLightconeSrPolygonMapper;
class vtkLightconeSrRayTracingMapper;
class vtkPolyData;

class vtkLightconeSrImageRenderer : public vtkLightconeOffscreenRenderer {
public:
    static vtkLightconeSrImageRenderer* New();
    vtkTypeMacro(vtkLightconeSrImageRenderer, vtkLightconeOffscreenRenderer)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    enum { LocalRayTracing = 0, PolygonDistortion = 1 };

    // Objects at rest in their moving frames, observer and light at rest in S. The camera's
    // width x height is the image size. Throws std::invalid_argument naming the object and value
    // for a bad camera, more than 254 objects or 65534 triangles in one (the id pass's 8-bit
    // channels), non-finite values, negative material values, normals not one per vertex, a
    // triangle referring to a missing vertex. SetCamera and SetObserverTime check theirs alike. The
    // camera is the scene's (pinhole or panorama, both fields of view honoured); polygon
    // distortion needs a pinhole (SetCamera, SetScene and SetMode refuse the pair).
    void SetScene(const lc::sr::SrScene& scene, const lc::sr::ObserverCamera& camera);
    // A 'minkowski' lc::Scene, converted as lc::renderSrImage does (spheres as
    // 96 x 48 UV spheres, meshes as given, first light, background).
    void SetScene(const lc::Scene& scene);
    void SetCamera(const lc::sr::ObserverCamera& camera);
    void SetObserverTime(double t);
    const lc::sr::SrScene& GetSrScene() const { return this->Scene; }
    const lc::sr::ObserverCamera& GetCamera() const { return this->Camera; }

    // Which technique is drawn (and executed).
    void SetMode(int mode);
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

    // Makes the pipelines of a new scene and sets their parameters, then updates the technique
    // shown (its quads or apparent triangles); Render*() call it when something changed.
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
    // Local ray tracing's quads (0 after a polygon-distortion build).
    std::size_t GetNumberOfQuads() const { return this->Quads; }
    std::size_t GetNumberOfFullScreenQuads() const { return this->FullScreenQuads; }
    // Mean quad area in pixels (the fragment work of local ray tracing per triangle).
    double GetMeanQuadPixels() const { return this->MeanQuadPixels; }

protected:
    vtkLightconeSrImageRenderer();
    ~vtkLightconeSrImageRenderer() override;

private:
    vtkLightconeSrImageRenderer(const vtkLightconeSrImageRenderer&) = delete;
    void operator=(const vtkLightconeSrImageRenderer&) = delete;

    // One object's two pipelines on its rest mesh.
    struct ObjectPipelines {
        vtkSmartPointer<vtkPolyData> mesh;
        vtkSmartPointer<vtkLightconeSrFootprintQuads> quads;
        vtkSmartPointer<vtkLightconeSrRayTracingMapper> rayMapper;
        vtkSmartPointer<vtkActor> rayActor;
        vtkSmartPointer<vtkLightconePhotoObjectFilter> photoObject;
        vtkSmartPointer<vtkLightconeSrApparentTriangles> apparent;
        vtkSmartPointer<vtkLightconeSrPolygonMapper> polygonMapper;
        vtkSmartPointer<vtkActor> polygonActor;
    };

    // The scene, camera, observer time or mode: setting a shading option changes uniforms only.
    vtkMTimeType GetBuildDependencyTime() override { return this->GeometryTime.GetMTime(); }
    void MakePipelines();
    void SetPipelineParameters();
    void UpdateUniforms(bool ids);
    std::vector<unsigned char> ReadPixels();

    lc::sr::SrScene Scene;
    lc::sr::ObserverCamera Camera;
    bool HasScene = false;
    vtkTimeStamp GeometryTime;  // scene, camera, observer time or mode changed
    vtkTimeStamp SceneTime;     // the objects changed: new pipelines
    vtkTimeStamp PipelinesTime;
    std::vector<ObjectPipelines> Pipelines;
    bool ActorsAdded = false;  // the pipelines' actors are in the renderer
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
    lc::views::PlanckTexture Planck;  // destroyed before the base class's Window
};

#endif
