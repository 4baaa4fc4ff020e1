// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeGodelImageRenderer_h
#define vtkLightconeGodelImageRenderer_h
// The egocentric image of a Goedel scene drawn through VTK's OpenGL pipeline (seed 001 section
// 6): the GPU twin of lc::renderGodelPerVertex. Each object's mesh (spheres tessellated
// latitudes x longitudes, with texture coordinates and, when lit, the light per vertex) goes
// through vtkLightconePhotoObjectFilter (every image of every vertex for windings 0..N on both
// branches, at rest or moving: lc::buildPhotoObject, the builder of the CPU renderer); each
// (winding, branch) block becomes the triangles of vtkLightconeGodelLayerTriangles, drawn by a
// vtkLightconeGodelImageMapper (projection, depth ordering of every image in one depth buffer,
// texture, Planck colour, day/night). Panorama seam: every triangle owns its vertices and knows its
// centroid, so the vertex shader unwraps each vertex next to it; a second mapper per layer draws
// the copy shifted by a full turn. Camera turns change uniforms only: the geometry is built once.
#include "core/render/photo_scene.hpp"
#include "core/scene/scene.hpp"

#include "planck_texture.hpp"
#include "vtkLightconeOffscreenRenderer.h"

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cstdint>
#include <vector>

class vtkActor;
class vtkLightconeGodelImageMapper;
class vtkLightconePhotoObjectFilter;
class vtkRenderWindow;
class vtkRenderer;

class vtkLightconeGodelImageRenderer : public vtkLightconeOffscreenRenderer {
public:
    static vtkLightconeGodelImageRenderer* New();
    vtkTypeMacro(vtkLightconeGodelImageRenderer, vtkLightconeOffscreenRenderer)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // The scene must use the 'godel' metric with a static observer (anywhere). The camera's
    // width x height is the size of the image. Windings default to scene.settings.windings.
    void SetScene(const lc::Scene& scene);

    vtkSetClampMacro(Latitudes, int, 4, 2000);
    vtkGetMacro(Latitudes, int);
    vtkSetClampMacro(Longitudes, int, 4, 4000);
    vtkGetMacro(Longitudes, int);
    vtkSetClampMacro(Windings, int, 0, 50);
    vtkGetMacro(Windings, int);
    // Texture resolution of the baked sphere textures (u x v = 2n x n texels).
    vtkSetClampMacro(TextureSize, int, 8, 8192);
    vtkGetMacro(TextureSize, int);
    // Per-vertex lighting by the scene's point lights (godel::ShadowTester through
    // lc::GodelLighting); without lights the objects are self-luminous.
    vtkSetMacro(Lighting, bool);
    vtkGetMacro(Lighting, bool);
    vtkBooleanMacro(Lighting, bool);

    // Photo-objects solved elsewhere (lc::buildPhotoScene of this scene with this renderer's
    // windings, latitudes and longitudes, e.g. on a worker thread or for the CPU renderer), given to
    // each object's vtkLightconePhotoObjectFilter; null: the filters solve them. Cleared by SetScene().
    // A lit scene's photo-objects carry their light per vertex (PhotoSceneOptions::vertexLight).
    void SetPhotoScene(std::shared_ptr<const std::vector<lc::PhotoSceneObject>> photos);

    // Builds the photo-objects and the VTK pipeline (done by Render() when the scene or a
    // setting changed since the last build).
    void Build() override;
    // Only the camera orientation changes: uniforms are updated, the geometry is kept.
    void SetCameraOrientation(const lc::Vec3& forward, const lc::Vec3& up);

    // Draws offscreen (a window of the camera's width x height). RenderColour(): linear RGB
    // floats in [0, 1] (8-bit framebuffer), 3 per pixel, row 0 at the top (lc::Camera's rows).
    // RenderObjectIds(): the flat-colour pass without texture, sphere index per pixel (the
    // numbering of Scene::spheres, as PixelRecord::object), -1 where no object was drawn.
    void Render();
    std::vector<float> RenderColour();
    std::vector<int> RenderObjectIds();

    double GetVertexSeconds() const { return this->VertexSeconds; }
    double GetMaximumLambda() const { return this->MaxLambda; }
    std::size_t GetNumberOfTriangles() const { return this->Triangles; }
    int GetNumberOfLayers() const { return static_cast<int>(this->Layers.size()); }

protected:
    vtkLightconeGodelImageRenderer();
    ~vtkLightconeGodelImageRenderer() override;

private:
    vtkLightconeGodelImageRenderer(const vtkLightconeGodelImageRenderer&) = delete;
    void operator=(const vtkLightconeGodelImageRenderer&) = delete;

    struct Layer {
        int object = 0;
        vtkLightconeGodelImageMapper* mapper = nullptr;      // owned by the renderer's actors
        vtkLightconeGodelImageMapper* twinMapper = nullptr;  // the +-360 degree copy (panorama)
    };
    // Build's steps: every object's photo-object (its images' vertices, lit where the scene has
    // lights), then its layers of triangles drawn by the image mapper.
    std::vector<vtkSmartPointer<vtkLightconePhotoObjectFilter>> BuildPhotoObjects();
    void AddObjectLayers(std::size_t object, vtkLightconePhotoObjectFilter* photo);
    bool IsLit() const { return this->Lighting && !this->Scene.lights.empty(); }
    void UpdateUniforms(bool objectIds);
    std::vector<unsigned char> ReadPixels();

    lc::Scene Scene;
    std::shared_ptr<const std::vector<lc::PhotoSceneObject>> PhotoScene;
    bool HasScene = false;
    int Latitudes = 100;
    int Longitudes = 200;
    int Windings = 1;
    int TextureSize = 512;
    bool Lighting = true;
    double VertexSeconds = 0;
    double MaxLambda = 1;
    std::size_t Triangles = 0;
    std::vector<Layer> Layers;
    lc::views::PlanckTexture Planck;  // black-body emitters: looked up per fragment
};

#endif
