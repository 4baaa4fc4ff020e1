// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeGodelLayerTriangles_h
#define vtkLightconeGodelLayerTriangles_h
// One photo-object layer of vtkLightconePhotoObjectFilter (a block of its multiblock output,
// directions in the camera frame) as the triangles vtkLightconeGodelImageMapper draws: every
// triangle owns its three vertices (points: the unit image directions, float), so that each vertex
// can carry its triangle's centroid direction for the panorama seam; texture coordinates (the
// input's "TCoords", kept continuous across the u = 0/1 seam), "lcAux" (centroid direction, depth
// lambda), "lcLight" (the input's per-vertex light, 1 without) and "lcTemperature" (the observed
// temperature D T of a black-body emitter, clamped to the Planck table of lc::shadePixels; 0 for
// a textured object). An empty block gives an empty output; a missing block or array is an error.
#include <vtkPolyDataAlgorithm.h>

class vtkLightconeGodelLayerTriangles : public vtkPolyDataAlgorithm {
public:
    static vtkLightconeGodelLayerTriangles* New();
    vtkTypeMacro(vtkLightconeGodelLayerTriangles, vtkPolyDataAlgorithm)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // The block of the input multiblock: the layer 2 n + b (winding n, branch b).
    vtkSetClampMacro(Block, int, 0, VTK_INT_MAX);
    vtkGetMacro(Block, int);
    // Emitted black-body temperature in K; 0 (default): the object shows its texture.
    vtkSetClampMacro(Temperature, double, 0.0, VTK_DOUBLE_MAX);
    vtkGetMacro(Temperature, double);

protected:
    vtkLightconeGodelLayerTriangles();
    ~vtkLightconeGodelLayerTriangles() override = default;
    int FillInputPortInformation(int port, vtkInformation* info) override;
    int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

    int Block = 0;
    double Temperature = 0;

private:
    vtkLightconeGodelLayerTriangles(const vtkLightconeGodelLayerTriangles&) = delete;
    void operator=(const vtkLightconeGodelLayerTriangles&) = delete;
};

#endif
