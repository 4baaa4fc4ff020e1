// SPDX-License-Identifier: BSD-3-Clause
#include "planck_texture.hpp"

#include <vtkOpenGLRenderWindow.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtkUniforms.h>

#include <stdexcept>

namespace lc::views {

// The table the CPU paths look colours up in: the GPU interpolates the same texels.
PlanckTexture::PlanckTexture() : table_(colour::standardBlackbodyTable()) {}
PlanckTexture::PlanckTexture(double tMinK, double tMaxK, int samples)
    : table_(std::make_shared<colour::BlackbodyTable>(tMinK, tMaxK, samples)) {}
PlanckTexture::~PlanckTexture() = default;

void PlanckTexture::bind(vtkRenderWindow* window, vtkShaderProgram* program, const char* uniform) {
    auto* win = vtkOpenGLRenderWindow::SafeDownCast(window);
    if (!win || !program) return;
    if (!texture_) {
        const int n = table_->samples();
        std::vector<float> texels(static_cast<std::size_t>(6 * n));
        const auto& a = table_->texels(colour::ToneMap::ColourOnly);
        const auto& b = table_->texels(colour::ToneMap::ReferenceLog);
        std::copy(a.begin(), a.end(), texels.begin());
        std::copy(b.begin(), b.end(), texels.begin() + 3 * n);
        texture_ = vtkSmartPointer<vtkTextureObject>::New();
        texture_->SetContext(win);
        texture_->SetMinificationFilter(vtkTextureObject::Linear);
        texture_->SetMagnificationFilter(vtkTextureObject::Linear);
        texture_->SetWrapS(vtkTextureObject::ClampToEdge);
        texture_->SetWrapT(vtkTextureObject::ClampToEdge);
        if (!texture_->Create2DFromRaw(static_cast<unsigned>(n), 2, 3, VTK_FLOAT, texels.data()))
            throw std::runtime_error("cannot create the Planck lookup texture");
    }
    texture_->Activate();
    program->SetUniformi(uniform, texture_->GetTextureUnit());
}

void PlanckTexture::deactivate() {
    if (texture_) texture_->Deactivate();
}

void PlanckTexture::release(vtkRenderWindow* window) {
    if (texture_ && window) texture_->ReleaseGraphicsResources(window);
}

void PlanckTexture::setUniforms(vtkUniforms* fs, colour::ToneMap map) const {
    fs->SetUniformf("lcTexRow", map == colour::ToneMap::ColourOnly ? 0.25f : 0.75f);
    fs->SetUniformf("lcTMin", float(table_->tMin()));
    fs->SetUniformf("lcTMax", float(table_->tMax()));
    fs->SetUniformf("lcSamples", float(table_->samples()));
}

void PlanckTexture::setUniforms(vtkShaderProgram* program, colour::ToneMap map) const {
    program->SetUniformf("lcTexRow", map == colour::ToneMap::ColourOnly ? 0.25f : 0.75f);
    program->SetUniformf("lcTMin", float(table_->tMin()));
    program->SetUniformf("lcTMax", float(table_->tMax()));
    program->SetUniformf("lcSamples", float(table_->samples()));
}

}  // namespace lc::views
