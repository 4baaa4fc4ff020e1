#include "vtkLightconePostRenderer.h"

#include "offscreen_parts.hpp"
#include "vtkLightconePostRenderMapper.h"

#include "core/colour/srgb.hpp"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkObjectFactory.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <chrono>
#include <stdexcept>

vtkStandardNewMacro(vtkLightconePostRenderer);

namespace {

// The pixels that show something other than the background, as one clip-space quad per run of
// such pixels in a row (seed 000's stencil of empty regions): the background comes from the
// clear colour, so the fragment shader runs only where there is something to colour (a few per
// cent of a Goedel image). Quad edges lie on pixel edges, so each covered pixel is drawn once.
vtkSmartPointer<vtkPolyData> coveredSpans(const lc::RenderResult& data) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    vtkNew<vtkCellArray> quads;
    const double w = data.width, h = data.height;
    for (int j = 0; j < data.height; ++j) {
        const double top = 1 - 2 * j / h, bottom = 1 - 2 * (j + 1) / h;
        for (int i = 0; i < data.width;) {
            const auto shows = [&](int k) {
                return data.pixels[static_cast<std::size_t>(j) * data.width + k].kind != lc::PixelRecord::Background;
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
    const lc::Vec3& b = scene.background;  // the framebuffer holds sRGB, as the shader writes it
    for (int k = 0; k < 3; ++k) this->Background[k] = lc::colour::srgbEncodeDisplay(b(k));
    this->HasInput = true;
    if (!this->Window || this->Window->GetSize()[0] != data.width || this->Window->GetSize()[1] != data.height)
        this->InputTime.Modified();  // a new image size needs a new window
    else {                           // the same window draws the new data
        this->Mapper->SetInputData(this->Spans);
        this->Renderer->SetBackground(this->Background);
    }
    this->Modified();
}

void vtkLightconePostRenderer::SetPostRender(const lc::PostRender& post) { this->Mapper->SetPostRender(post); }

void vtkLightconePostRenderer::Build() {
    if (!this->HasInput) throw std::logic_error("vtkLightconePostRenderer: no scene and pixel data");
    this->Actor = lc::views::clipSpaceQuadActor(this->Mapper);
    this->Mapper->SetInputData(this->Spans);
    this->CreateWindow(this->Mapper->GetImageWidth(), this->Mapper->GetImageHeight());
    this->Renderer->SetBackground(this->Background);
    this->Renderer->AddActor(this->Actor);
    this->MarkBuilt();
}

std::vector<unsigned char> vtkLightconePostRenderer::RenderSrgb() {
    this->BuildIfNeeded();
    return this->DrawAndReadBack(this->Mapper->GetImageWidth(), this->Mapper->GetImageHeight());
}

double vtkLightconePostRenderer::DrawOnly() {
    this->BuildIfNeeded();
    const auto t0 = std::chrono::steady_clock::now();
    this->Window->Render();
    this->Window->WaitForCompletion();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
