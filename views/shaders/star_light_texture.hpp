// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A star sky's map of brightness b and b T (lc::LightMap) as a two-channel float texture for
// glsl/star_light, which fetches its texels exactly and blends them as the CPU does.
#include "core/scene/texture.hpp"

#include <vtkSmartPointer.h>

class vtkRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

namespace lc::views {

class StarLightTexture {
public:
    // The sky is kept alive: its map is uploaded on the first bind.
    explicit StarLightTexture(TexturePtr sky);
    ~StarLightTexture();
    const TexturePtr& sky() const { return sky_; }
    // Creates the texture in the window's context on first use and binds it to `uniform`.
    void bind(vtkRenderWindow* window, vtkShaderProgram* program, const char* uniform = "lcStarLight");
    void release(vtkRenderWindow* window);
    void deactivate();

private:
    TexturePtr sky_;
    vtkSmartPointer<vtkTextureObject> texture_;
};

}  // namespace lc::views
