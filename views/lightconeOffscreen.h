#ifndef lightconeOffscreen_h
#define lightconeOffscreen_h
// Pieces every full-screen shader pass shares: the clip-space quad a fragment shader runs on
// and the offscreen window it draws into (one sample per pixel, no culling, no FXAA).
#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;
class vtkRenderWindow;

namespace lc::views {

// Two triangles covering clip space (points are clip-space positions; glsl/clip_quad_vertex
// passes them through), with texture coordinates so that a mapper declares the actor's
// texture sampler.
vtkSmartPointer<vtkPolyData> clipSpaceQuad();

// An offscreen window of width x height with one renderer holding `actor`.
vtkSmartPointer<vtkRenderWindow> offscreenWindow(int width, int height, vtkActor* actor);

}  // namespace lc::views

#endif
