#ifndef vtkLightconeGodelImageRenderer_h
#define vtkLightconeGodelImageRenderer_h
// The egocentric image of a Goedel scene drawn through VTK's OpenGL pipeline (seed 001
// section 6): the GPU twin of lc::renderGodelPerVertex. For every sphere the photo-object is
// built on the CPU (godel::PhotoObjectBuilder: every vertex gets its images for windings
// 0..N on both branches); each (winding, branch) layer becomes a vtkPolyData whose points are
// the unit image directions in the observer's static frame (e1, e2, e3) and whose point data
// carry the depth lambda and the texture coordinates. A vertex-shader replacement projects
// the direction (pinhole or equirectangular panorama, the formulas of lc::Camera::project)
// and writes clip-space depth lambda / lambdaMax, so that one depth buffer orders all images
// of all objects; the fragment shader samples the sphere's texture (baked into a vtkTexture)
// and multiplies it by the per-vertex light (godel lighting, optional).
//
// Panorama seam: the triangles are not shared-vertex meshes on the GPU: every triangle owns
// its three vertices and carries its centroid direction, so the vertex shader unwraps each
// vertex's azimuth relative to the triangle's centroid (no triangle smears across the image)
// and a second copy of every layer, shifted by -+360 degrees, draws the part of a triangle
// that sticks out over the +-180 degree edge on the other side. Camera rotation only changes
// uniforms: the geometry is built once per scene.
#include "core/render/photo_scene.hpp"
#include "core/scene/scene.hpp"

#include "lightconePlanckTexture.h"
#include "vtkLightconeOffscreenRenderer.h"

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cstdint>
#include <vector>

class vtkActor;
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

    // Photo-objects built elsewhere (lc::buildPhotoScene of this scene with this renderer's
    // windings, latitudes and longitudes, e.g. on a worker thread, so that only the drawing is
    // left to the GL thread); null: Build() computes them. Cleared by SetScene().
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
        vtkSmartPointer<vtkActor> actor, wrapActor;  // wrapActor: the +-360 degree copy (panorama)
    };
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
    static void OnUpdateShader(vtkObject* caller, unsigned long event, void* self, void* program);
};

#endif
