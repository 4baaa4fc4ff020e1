// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconePostRenderer.h"

#include "offscreen_parts.hpp"
#include "vtkLightconePostRenderMapper.h"

#include "core/colour/srgb.hpp"
#include "core/render/post_render.hpp"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkObjectFactory.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkLightconePostRenderer);

namespace {

// The pixels whose colour the settings change (objects and disks: lc::PixelShader::settingsChange),
// as one clip-space quad per run of such pixels in a row (seed 000's stencil of empty regions):
// everything else (sky, horizon, background) is the same in every frame, drawn once into the
// background texture, so the fragment shader runs only where a slider changes something (a few per
// cent of a Goedel image, none of a Kerr sky). Quad edges lie on pixel edges, so each covered pixel
// is drawn once.
vtkSmartPointer<vtkPolyData> coveredSpans(const lc::RenderResult& data) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    vtkNew<vtkCellArray> quads;
    const double w = data.width, h = data.height;
    for (int j = 0; j < data.height; ++j) {
        const double top = 1 - 2 * j / h, bottom = 1 - 2 * (j + 1) / h;
        for (int i = 0; i < data.width;) {
            const auto shows = [&](int k) {
                return lc::PixelShader::settingsChange(data.pixels[static_cast<std::size_t>(j) * data.width + k]);
            };
            if (!shows(i)) {
                ++i;
                continue;
            }
            const int begin = i;
            while (i < data.width && shows(i)) ++i;
            const double left = 2 * begin / w - 1, right = 2 * i / w - 1;
            const vtkIdType first = points->InsertNextPoint(left, bottom, 0);
            points->InsertNextPoint(right, bottom, 0);
            points->InsertNextPoint(right, top, 0);
            points->InsertNextPoint(left, top, 0);
            const vtkIdType t0[3] = {first, first + 1, first + 2}, t1[3] = {first, first + 2, first + 3};
            quads->InsertNextCell(3, t0);
            quads->InsertNextCell(3, t1);
        }
    }
    auto spans = vtkSmartPointer<vtkPolyData>::New();
    spans->SetPoints(points);
    spans->SetPolys(quads);
    return spans;
}

// The pixels no setting changes, coloured once as lc::shadePixels colours them and encoded as the
// shader writes (lcSrgbEncodeDisplay, then 8 bits): the background texture, row 0 at the bottom.
vtkSmartPointer<vtkTexture> unchangingPixels(const lc::Scene& scene, const lc::RenderResult& data) {
    const std::vector<float> rgb = lc::shadePixels(scene, data);
    vtkNew<vtkImageData> image;
    image->SetDimensions(data.width, data.height, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
    for (int j = 0; j < data.height; ++j)
        for (int i = 0; i < data.width; ++i) {
            const std::size_t from = static_cast<std::size_t>(j) * data.width + i;
            unsigned char* to = out + 3 * (static_cast<std::size_t>(data.height - 1 - j) * data.width + i);
            for (int c = 0; c < 3; ++c) {
                const double v = lc::PixelShader::settingsChange(data.pixels[from])
                                     ? 0.0
                                     : lc::colour::srgbEncodeDisplay(rgb[3 * from + c]);
                to[c] = static_cast<unsigned char>(std::lround(255.0 * std::clamp(v, 0.0, 1.0)));
            }
        }
    auto texture = vtkSmartPointer<vtkTexture>::New();
    texture->SetInputData(image);
    texture->InterpolateOff();  // texel for pixel
    texture->RepeatOff();
    return texture;
}

}  // namespace

vtkLightconePostRenderer::vtkLightconePostRenderer() : Mapper(vtkSmartPointer<vtkLightconePostRenderMapper>::New()) {}
vtkLightconePostRenderer::~vtkLightconePostRenderer() = default;

void vtkLightconePostRenderer::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Mapper:\n";
    this->Mapper->PrintSelf(os, indent.GetNextIndent());
}

vtkLightconePostRenderMapper* vtkLightconePostRenderer::GetMapper() { return this->Mapper; }

void vtkLightconePostRenderer::SetInput(const lc::Scene& scene, const lc::RenderResult& data) {
    this->Mapper->SetScene(scene);
    this->Mapper->SetPixelData(data);
    this->Spans = coveredSpans(data);
    this->Unchanging = unchangingPixels(scene, data);
    this->HasInput = true;
    if (!this->Window || this->Window->GetSize()[0] != data.width || this->Window->GetSize()[1] != data.height)
        this->InputTime.Modified();  // a new image size needs a new window
    else {                           // the same window draws the new data
        this->Mapper->SetInputData(this->Spans);
        this->Renderer->SetBackgroundTexture(this->Unchanging);
        this->DrawUnchangingPixels(true);
    }
    this->Modified();
}

void vtkLightconePostRenderer::SetPostRender(const lc::PostRender& post) { this->Mapper->SetPostRender(post); }

void vtkLightconePostRenderer::Build() {
    if (!this->HasInput) throw std::logic_error("vtkLightconePostRenderer: no scene and pixel data");
    this->Actor = lc::views::clipSpaceQuadActor(this->Mapper);
    this->Mapper->SetInputData(this->Spans);
    this->CreateWindow(this->Mapper->GetImageWidth(), this->Mapper->GetImageHeight());
    this->Renderer->SetBackgroundTexture(this->Unchanging);
    this->DrawUnchangingPixels(true);
    this->Renderer->AddActor(this->Actor);
    this->MarkBuilt();
}

void vtkLightconePostRenderer::DrawUnchangingPixels(bool draw) {
    // Drawn in the first frame; later frames keep the colour buffer and draw only the spans, which
    // cover every pixel the settings change, each opaque.
    this->Renderer->SetTexturedBackground(draw);
    this->Renderer->SetPreserveColorBuffer(!draw);
}

std::vector<unsigned char> vtkLightconePostRenderer::RenderSrgb() {
    this->BuildIfNeeded();
    std::vector<unsigned char> rgb =
        this->DrawAndReadBack(this->Mapper->GetImageWidth(), this->Mapper->GetImageHeight());
    this->DrawUnchangingPixels(false);
    return rgb;
}

double vtkLightconePostRenderer::DrawOnly() {
    this->BuildIfNeeded();
    const auto t0 = std::chrono::steady_clock::now();
    this->Window->Render();
    this->Window->WaitForCompletion();
    this->DrawUnchangingPixels(false);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
