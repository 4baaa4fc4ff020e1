// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Evaluates GLSL functions on the GPU at sample points and returns their float results
// exactly, so that each shader function can be tested against its C++ twin in core/ (not only
// through whole images). The code runs in a fragment shader of VTK's OpenGL pipeline, as the
// renderers' does; results come back bit for bit through an 8-bit window (two pixels per float).
// Needs an X server (xvfb-run).
#include "planck_texture.hpp"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace lc::views {

struct GlslProbe {
    std::string declarations;  // GLSL functions (e.g. a generated lcMetric)
    // GLSL statements that read `vec4 lcIn` and assign `lcOut[0 .. outputs-1]`.
    std::string body;
    int outputs = 1;
    // Custom fragment uniforms the probed code reads: 1 to 4 floats each (float .. vec4).
    std::vector<std::pair<std::string, std::vector<float>>> uniforms;
    std::vector<std::pair<std::string, int>> intUniforms;
    // If set, lcPlanck is bound to this lookup texture (and its uniforms set) for glsl/planck_lookup.
    PlanckTexture* planck = nullptr;
    colour::ToneMap planckToneMap = colour::ToneMap::ColourOnly;
};

// One row of `outputs` floats per input. Throws std::invalid_argument for 0 inputs or more
// than 256, 0 outputs or more than 512, and std::runtime_error if the probe drew nothing. For
// the project's own GLSL only: VTK 9.1's mapper crashes after a shader fails to compile (it
// prints the compiler's message first), so code that may not compile must not come here.
std::vector<std::vector<float>> evaluateOnGpu(const GlslProbe& probe, const std::vector<std::array<float, 4>>& inputs);

}  // namespace lc::views
