// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What every shader renderer shares: the offscreen window it draws into (one sample per pixel,
// no culling, no FXAA), the clip-space quad a full-screen pass runs on, per-point float arrays
// for shader attributes and textures baked from lc::Texture.
#include "core/scene/texture.hpp"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <initializer_list>
#include <string>

class vtkActor;
class vtkAlgorithm;
class vtkFloatArray;
class vtkOpenGLPolyDataMapper;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderer;
class vtkTexture;

namespace lc::views {

// An unlit actor drawing a quad covering clip space (a vtkPlaneSource from (-1, -1) to (1, 1);
// glsl/clip_quad_vertex passes its points through as clip-space positions) through a
// vtkOpenGLPolyDataMapper (or `mapper`, a technique's subclass): the carrier of a full-screen
// fragment-shader pass.
vtkSmartPointer<vtkActor> clipSpaceQuadActor(vtkOpenGLPolyDataMapper* mapper = nullptr);

// An offscreen window of width x height with one renderer (black background, no culling: the
// props' bounds mean nothing to VTK's camera here; one sample per pixel: exact ids).
vtkSmartPointer<vtkRenderWindow> offscreenWindow(int width, int height);
// The window's renderer.
vtkRenderer* rendererOf(vtkRenderWindow* window);

// A float array of `tuples` tuples of `components`, named (a shader attribute).
vtkSmartPointer<vtkFloatArray> floatArray(const char* name, int components, vtkIdType tuples);
// Tuple i of a 3-component float array, rounded from double.
void putVec3(vtkFloatArray* array, vtkIdType i, const Vec3& v);

// Updates the pipeline ending in the last of `chain` (upstream first) and throws
// std::runtime_error with "<what>: <VTK's message>" if one of them reported an error (theirs and
// their executives' ErrorEvents are observed meanwhile, so VTK does not print them); the chain is
// then marked modified, so that the next update runs it again and reports again.
void updateOrThrow(std::initializer_list<vtkAlgorithm*> chain, const std::string& what);

// The texture sampled at texel centres, u across (wraps), v down the rows (v = 0 at the north
// pole; texel row j is texture coordinate t = v). Procedural textures are baked at 2n x n
// texels and sampled nearest, so checker edges stay sharp; an image texture keeps its own
// texels and is filtered linearly, as lc::ImageTexture::sample does on the CPU. No texture:
// `fallback` everywhere.
vtkSmartPointer<vtkTexture> bakeTexture(const TexturePtr& texture, const Vec3& fallback, int n);

// A two-ended metric's two skies side by side, this side's in u of [0, 1/2), the far side's in
// [1/2, 1), each baked at 2n x n texels and sampled nearest (geodesic_pixel.glsl halves u).
vtkSmartPointer<vtkTexture> bakeSkies(const TexturePtr& sky, const TexturePtr& otherSky, const Vec3& fallback, int n);

}  // namespace lc::views
