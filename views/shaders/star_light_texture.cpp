// SPDX-License-Identifier: BSD-3-Clause
#include "star_light_texture.hpp"

#include <vtkOpenGLRenderWindow.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include <stdexcept>

namespace lc::views {

StarLightTexture::StarLightTexture(TexturePtr sky) : sky_(std::move(sky)) {
    if (!sky_ || !sky_->lightMap()) throw std::invalid_argument("StarLightTexture: the sky is not a star sky");
}
StarLightTexture::~StarLightTexture() = default;

void StarLightTexture::bind(vtkRenderWindow* window, vtkShaderProgram* program, const char* uniform) {
    auto* win = vtkOpenGLRenderWindow::SafeDownCast(window);
    if (!win || !program) return;
    if (!texture_) {
        const LightMap& map = *sky_->lightMap();
        texture_ = vtkSmartPointer<vtkTextureObject>::New();
        texture_->SetContext(win);
        // Nearest and clamped: glsl/star_light fetches texels by index and blends them itself.
        texture_->SetMinificationFilter(vtkTextureObject::Nearest);
        texture_->SetMagnificationFilter(vtkTextureObject::Nearest);
        texture_->SetWrapS(vtkTextureObject::ClampToEdge);
        texture_->SetWrapT(vtkTextureObject::ClampToEdge);
        if (!texture_->Create2DFromRaw(static_cast<unsigned>(map.width), static_cast<unsigned>(map.height), 2,
                                       VTK_FLOAT, const_cast<float*>(map.texels.data())))
            throw std::runtime_error("cannot create the star sky's texture (" + std::to_string(map.width) + " x " +
                                     std::to_string(map.height) + " texels)");
    }
    texture_->Activate();
    program->SetUniformi(uniform, texture_->GetTextureUnit());
}

void StarLightTexture::deactivate() {
    if (texture_) texture_->Deactivate();
}

void StarLightTexture::release(vtkRenderWindow* window) {
    if (texture_ && window) texture_->ReleaseGraphicsResources(window);
    texture_ = nullptr;
}

}  // namespace lc::views
