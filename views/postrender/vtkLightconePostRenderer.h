// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconePostRenderer_h
#define vtkLightconePostRenderer_h
// Post-rendering on the GPU, offscreen (seed 000 section 5.2): the image of a render coloured
// again from its per-pixel data by vtkLightconePostRenderMapper, read back as 8-bit sRGB, the
// bytes `lightcone shade` writes for the same settings (lc::shadePixels is the reference).
// Changing the settings (SetPostRender) redraws without rebuilding: a frame is one draw.
#include "core/render/post_render.hpp"
#include "core/render/render.hpp"

#include "vtkLightconeOffscreenRenderer.h"

#include <vtkSmartPointer.h>

#include <vector>

class vtkActor;
class vtkPolyData;
class vtkTexture;
class vtkLightconePostRenderMapper;

class vtkLightconePostRenderer : public vtkLightconeOffscreenRenderer {
public:
    static vtkLightconePostRenderer* New();
    vtkTypeMacro(vtkLightconePostRenderer, vtkLightconeOffscreenRenderer)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // The scene, then its per-pixel data (their size is the image size; throws for an object the
    // scene does not have), then any settings.
    void SetInput(const lc::Scene& scene, const lc::RenderResult& data);
    void SetPostRender(const lc::PostRender& post);

    void Build() override;
    // The image, 8-bit sRGB, 3 bytes per pixel, row 0 at the top.
    std::vector<unsigned char> RenderSrgb();
    // Draws once without reading back (for frame rates); returns the seconds until the GPU is done.
    double DrawOnly();
    vtkLightconePostRenderMapper* GetMapper();

protected:
    vtkLightconePostRenderer();
    ~vtkLightconePostRenderer() override;
    vtkMTimeType GetBuildDependencyTime() override { return this->InputTime.GetMTime(); }

private:
    vtkLightconePostRenderer(const vtkLightconePostRenderer&) = delete;
    void operator=(const vtkLightconePostRenderer&) = delete;
    void DrawUnchangingPixels(bool draw);

    vtkSmartPointer<vtkLightconePostRenderMapper> Mapper;
    vtkSmartPointer<vtkActor> Actor;
    vtkSmartPointer<vtkPolyData> Spans;      // what the shader draws: the pixels the settings change
    vtkSmartPointer<vtkTexture> Unchanging;  // the others, coloured once: the background texture
    vtkTimeStamp InputTime;
    bool HasInput = false;
};

#endif
