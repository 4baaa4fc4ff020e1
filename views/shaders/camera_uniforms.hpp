// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The camera's uniforms (glsl/camera_uniforms), set in one place for every shader that looks
// through lc::Camera: the geodesic tracer, the Goedel image and both special-relativity techniques.
#include "core/scene/camera.hpp"

class vtkShaderProgram;

namespace lc::views {

// The axes, projection, half fields and image size of `camera`, whose forward and up are frame
// components (lc::frameCamera's result).
void setCameraUniforms(vtkShaderProgram* program, const Camera& camera);

}  // namespace lc::views
