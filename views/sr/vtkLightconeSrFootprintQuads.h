// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeSrFootprintQuads_h
#define vtkLightconeSrFootprintQuads_h
// The fragments local ray tracing must run (seed 003 sect. 4.1), as the quads
// vtkLightconeSrRayTracingMapper draws: for every triangle of the input mesh (at rest in a frame
// moving with Beta, whose origin passes the event ObjectOrigin, as vtkLightconePhotoObjectFilter's
// special relativity), seen by an observer at rest at the camera's position at ObserverTime, one
// screen-space quad over the conservative footprint of its curved apparent image
// (lc::sr::apparentFootprint: the whole screen where the bound fails). Points: the quad's corners in
// continuous pixel coordinates (row 0 at the top). Point data, the same on the four corners:
// "lcP0" (rest vertex 0, triangle index in the input), "lcP1", "lcP2" (rest vertices 1, 2),
// "lcN0".."lcN2" (rest normals). A triangle whose footprint misses the image has no quad.
// The input must be triangles with point normals; an empty mesh gives an empty output. Bad
// parameters (|beta| >= 1, non-finite values, a camera ObserverCamera::validate refuses) are errors.
#include "core/sr/observer_camera.hpp"

#include <vtkPolyDataAlgorithm.h>

#include <cstddef>

class vtkLightconeSrFootprintQuads : public vtkPolyDataAlgorithm {
public:
    static vtkLightconeSrFootprintQuads* New();
    vtkTypeMacro(vtkLightconeSrFootprintQuads, vtkPolyDataAlgorithm)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // Velocity of the object's frame (default (0.5, 0, 0)) and an event on the world line of its
    // origin (default (0, 0, 0, -5)).
    vtkSetVector3Macro(Beta, double);
    vtkGetVector3Macro(Beta, double);
    vtkSetVector4Macro(ObjectOrigin, double);
    vtkGetVector4Macro(ObjectOrigin, double);
    // The observer's time (default 0); it sits at the camera's position.
    vtkSetMacro(ObserverTime, double);
    vtkGetMacro(ObserverTime, double);
    // The camera (Modified() only when it changes).
    void SetCamera(const lc::sr::ObserverCamera& camera);
    const lc::sr::ObserverCamera& GetCamera() const { return this->Camera; }

    // Of the last execution: quads, quads covering the whole image, and the sum of the quads'
    // areas in pixels (the fragment work of local ray tracing).
    std::size_t GetNumberOfQuads() const { return this->Quads; }
    std::size_t GetNumberOfFullScreenQuads() const { return this->FullScreenQuads; }
    double GetFootprintPixels() const { return this->FootprintPixels; }

protected:
    vtkLightconeSrFootprintQuads();
    ~vtkLightconeSrFootprintQuads() override = default;
    int FillInputPortInformation(int port, vtkInformation* info) override;
    int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

    double Beta[3] = {0.5, 0.0, 0.0};
    double ObjectOrigin[4] = {0.0, 0.0, 0.0, -5.0};
    double ObserverTime = 0;
    lc::sr::ObserverCamera Camera;

private:
    vtkLightconeSrFootprintQuads(const vtkLightconeSrFootprintQuads&) = delete;
    void operator=(const vtkLightconeSrFootprintQuads&) = delete;

    std::size_t Quads = 0, FullScreenQuads = 0;
    double FootprintPixels = 0;
};

#endif
