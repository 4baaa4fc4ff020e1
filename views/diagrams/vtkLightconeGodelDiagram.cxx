// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeGodelDiagram.h"

#include "core/metrics/godel.hpp"
#include "diagram_chart.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/file_extension.hpp"

#include <vtkPen.h>

#include <algorithm>
#include <stdexcept>

vtkLightconeGodelDiagram::vtkLightconeGodelDiagram() = default;
vtkLightconeGodelDiagram::~vtkLightconeGodelDiagram() = default;

void vtkLightconeGodelDiagram::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Windings: " << this->Windings << "\n"
       << indent << "FanRays: " << this->FanRays << "\n"
       << indent << "Size: " << this->Size << "\n"
       << indent << "HighlightedObject: " << this->HighlightedObject << "\n"
       << indent << "MaxObjectsDrawn: " << this->MaxObjectsDrawn << "\n"
       << indent << "ImagePaths: " << this->ImagePaths << "\n";
}

void vtkLightconeGodelDiagram::SetScene(const lc::Scene& scene) {
    if (!scene.spacetime || !scene.spacetime->godelRadius())
        throw std::invalid_argument("the " + this->DiagramName() + " diagram needs a scene with the 'godel' metric");
    this->Scene = scene;
    this->HasScene = true;
    this->Modified();
}

void vtkLightconeGodelDiagram::Build() {
    if (!this->HasScene) throw std::logic_error(std::string(this->GetClassName()) + ": SetScene() first");
    const double a = this->Scene.spacetime->godelRadius().value();
    this->Chart = std::make_unique<lc::views::DiagramChart>(this->Size);
    this->ImagePaths = 0;
    this->HighlightedImagePaths = 0;
    this->ObjectsSummarised = 0;
    this->Draw(*this->Chart, a, lc::godel::ObserverView(a, this->Scene.observer));
}

void vtkLightconeGodelDiagram::AddImagePath(lc::views::DiagramChart& chart, const std::vector<double>& x,
                                            const std::vector<double>& y, int object, const lc::godel::Image& image) {
    // Image k keeps colour k % 8 whatever is highlighted, so the colours match between views.
    const double* colour = lc::views::kImageColours[this->ImagePaths++ % 8];
    float width = lc::views::imagePathWidth(image.winding);
    if (this->HighlightedObject >= 0) {
        const bool emphasised = object == this->HighlightedObject;
        if (emphasised) {
            width += lc::views::kHighlightExtraWidth;
            ++this->HighlightedImagePaths;
        } else {
            colour = lc::views::kDimmedImageColour;
        }
    }
    const std::string& name = this->Scene.spheres[static_cast<std::size_t>(object)].name;
    chart.addCurve(x, y, colour, width, lc::views::imageLabel(name, image), vtkPen::SOLID_LINE);
}

bool vtkLightconeGodelDiagram::DrawnOneByOne(std::size_t object) const {
    return object < static_cast<std::size_t>(this->MaxObjectsDrawn) ||
           static_cast<long>(object) == this->HighlightedObject;
}

void vtkLightconeGodelDiagram::AddSummarisedObjects(lc::views::DiagramChart& chart,
                                                    const std::vector<std::vector<double>>& x,
                                                    const std::vector<std::vector<double>>& y,
                                                    const std::string& what) {
    if (x.empty()) return;
    // Pairs of points, one segment each; at most 16 segments per curve (4096 world lines of 400
    // samples took llvmpipe seconds per frame): a sketch of where the others are.
    std::vector<double> sx, sy;
    for (std::size_t k = 0; k < x.size(); ++k) {
        const std::size_t n = x[k].size(), stride = n > 17 ? (n - 2) / 16 + 1 : 1;
        for (std::size_t from = 0; from + 1 < n;) {
            const std::size_t to = std::min(from + stride, n - 1);
            sx.insert(sx.end(), {x[k][from], x[k][to]});
            sy.insert(sy.end(), {y[k][from], y[k][to]});
            from = to;
        }
    }
    this->ObjectsSummarised = static_cast<int>(x.size());
    const double grey[3] = {0.45, 0.45, 0.45};
    chart.addSegments(sx, sy, grey, 1.0f,
                      what + " of " + std::to_string(x.size()) + " more objects (pick one to draw its light paths)");
}

vtkContextView* vtkLightconeGodelDiagram::GetView() {
    if (!this->Chart) this->Build();
    return this->Chart->view();
}

std::string vtkLightconeGodelDiagram::Encode(const std::string& format) {
    if (!this->Chart) this->Build();
    return this->Chart->encode(format, "Lightcone " + this->DiagramName() + " diagram", this->PlotAspect());
}

void vtkLightconeGodelDiagram::Write(const std::string& path) {
    lc::io::writeFileAtomically(path, this->Encode(lc::io::lowerCaseExtension(path)));
}
