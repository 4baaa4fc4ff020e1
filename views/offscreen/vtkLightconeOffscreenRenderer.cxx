// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeOffscreenRenderer.h"

#include "offscreen_parts.hpp"
#include "read_back.hpp"

#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <chrono>

vtkLightconeOffscreenRenderer::vtkLightconeOffscreenRenderer() = default;
vtkLightconeOffscreenRenderer::~vtkLightconeOffscreenRenderer() = default;

void vtkLightconeOffscreenRenderer::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Built: " << (this->Built ? "yes" : "no") << "\n"
       << indent << "LastRenderSeconds: " << this->LastRenderSeconds << "\n";
}

vtkRenderWindow* vtkLightconeOffscreenRenderer::GetRenderWindow() {
    this->BuildIfNeeded();
    return this->Window;
}

bool vtkLightconeOffscreenRenderer::NeedsBuild() {
    return !this->Built || this->GetBuildDependencyTime() > this->BuildTime.GetMTime();
}

void vtkLightconeOffscreenRenderer::BuildIfNeeded() {
    if (this->NeedsBuild()) this->Build();
}

void vtkLightconeOffscreenRenderer::MarkBuilt() {
    this->Built = true;
    this->BuildTime.Modified();
}

void vtkLightconeOffscreenRenderer::CreateWindow(int width, int height) {
    this->Window = lc::views::offscreenWindow(width, height);
    this->Renderer = lc::views::rendererOf(this->Window);
}

std::vector<unsigned char> vtkLightconeOffscreenRenderer::DrawAndReadBack(int width, int height) {
    const auto t0 = std::chrono::steady_clock::now();
    this->Window->Render();
    std::vector<unsigned char> rgb = lc::views::readBackRgb(this->Window, width, height, this->GetClassName());
    this->LastRenderSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return rgb;
}
