// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconePostRenderMapper_h
#define vtkLightconePostRenderMapper_h
// The GPU twin of lc::shadePixels with an lc::PostRender (seed 000 section 5.2, Fig. 2): the
// per-pixel data of a render (object, u, v, frequency ratio, emission time, light) become float
// textures, and a fragment shader on a full-screen quad colours each pixel again: re-texturing
// with uv offset and scale, the black-body colour at a chosen temperature seen through the
// frequency ratio (the Planck lookup texture), a window of emission times over a second texture,
// blinking lights. Changing the settings changes uniforms only; textures are uploaded again only
// when the pixel data or the set of textures changes.
//
// Shaders: glsl/post_render_dec, glsl/texture_atlas (lc::ImageTexture::sample on a float atlas
// of every texture), glsl/post_render_pixel, and the formulas generated from
// core/render/post_render.hpp (core_formula_glsl's postRenderGlsl). The output is sRGB-encoded
// as the image writer encodes, so the 8-bit read-back compares with `lightcone shade` files.
#include "core/render/post_render.hpp"
#include "core/render/render.hpp"
#include "core/scene/scene.hpp"

#include <vtkOpenGLPolyDataMapper.h>
#include <vtkSmartPointer.h>

#include <memory>
#include <vector>

class vtkTextureObject;

namespace lc::views {
class PlanckTexture;
}

class vtkLightconePostRenderMapper : public vtkOpenGLPolyDataMapper {
public:
    static vtkLightconePostRenderMapper* New();
    vtkTypeMacro(vtkLightconePostRenderMapper, vtkOpenGLPolyDataMapper)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // The scene the data were rendered from: its textures, temperatures, sky, background, lights.
    void SetScene(const lc::Scene& scene);
    // The per-pixel data (e.g. read from `render --data`); its size is the image size. Throws for
    // an object index the scene does not have.
    void SetPixelData(const lc::RenderResult& data);
    void SetPostRender(const lc::PostRender& post);
    const lc::PostRender& GetPostRender() const { return this->Post; }
    int GetImageWidth() const { return this->Width; }
    int GetImageHeight() const { return this->Height; }
    // Texels in the texture atlas (all textures the image can show), after the last draw.
    int GetAtlasWidth() const { return this->AtlasWidth; }
    int GetAtlasHeight() const { return this->AtlasHeight; }

    void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
    vtkLightconePostRenderMapper();
    ~vtkLightconePostRenderMapper() override;

    void ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
    void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
    void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;

private:
    vtkLightconePostRenderMapper(const vtkLightconePostRenderMapper&) = delete;
    void operator=(const vtkLightconePostRenderMapper&) = delete;

    std::vector<lc::TexturePtr> ChosenTextures() const;
    std::vector<lc::TexturePtr> ShownTextures() const;
    void Upload(vtkRenderWindow* window);

    lc::Scene Scene;
    lc::PostRender Post;
    int Width = 0, Height = 0;
    std::vector<float> PixelA, PixelB, PixelC;  // RGBA per pixel, row 0 at the top
    bool PixelsChanged = false;
    std::vector<lc::TexturePtr> UploadedTextures;  // the atlas on the GPU holds these
    std::vector<lc::TexturePtr> TableTextures;     // the object table on the GPU shows these
    bool SceneChanged = true;
    int AtlasWidth = 0, AtlasHeight = 0;
    int SkyEntry = -1, OtherSkyEntry = -1, OutsideEntry = -1, DiskEntry = -1;
    vtkSmartPointer<vtkTextureObject> PixelTextureA, PixelTextureB, PixelTextureC, AtlasTexture, EntryTexture,
        ObjectTexture;
    std::unique_ptr<lc::views::PlanckTexture> Planck;
};

#endif
