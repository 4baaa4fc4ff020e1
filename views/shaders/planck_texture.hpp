// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The black-body colour table (lc::colour::BlackbodyTable, Planck -> CIE XYZ -> sRGB) as a
// float lookup texture for fragment shaders: two rows (colour-only and reference-luminance
// tone maps), linear filtering, so texture() interpolates like BlackbodyTable::lookup.
#include "core/colour/blackbody.hpp"

#include <vtkSmartPointer.h>

#include <memory>

class vtkRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkUniforms;

namespace lc::views {

class PlanckTexture {
public:
    PlanckTexture();  // lc::colour::standardBlackbodyTable(): 500 K to 10^7 K
    PlanckTexture(double tMinK, double tMaxK, int samples);
    ~PlanckTexture();
    const colour::BlackbodyTable& table() const { return *table_; }
    // Creates the texture in the window's context on first use and binds it to `uniform`.
    void bind(vtkRenderWindow* window, vtkShaderProgram* program, const char* uniform = "lcPlanck");
    void release(vtkRenderWindow* window);
    void deactivate();
    // The custom uniforms of the GLSL lookup (glsl/planck_lookup): lcTMin, lcTMax, lcSamples, lcTexRow.
    void setUniforms(vtkUniforms* fragmentUniforms, colour::ToneMap map) const;
    // The same set on a program directly, for mappers declaring them (glsl/planck_uniforms).
    void setUniforms(vtkShaderProgram* program, colour::ToneMap map) const;

private:
    std::shared_ptr<const colour::BlackbodyTable> table_;
    vtkSmartPointer<vtkTextureObject> texture_;
};

}  // namespace lc::views
