// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeSrApparentTriangles_h
#define vtkLightconeSrApparentTriangles_h
// The apparent mesh of special relativity (the block "apparent" of vtkLightconePhotoObjectFilter
// in SPECIAL_RELATIVITY mode: each vertex where it emitted the light the observer receives, with
// its Doppler factor and the input's rest normals) as the triangles vtkLightconeSrPolygonMapper
// draws: every triangle owns its three vertices (points: the apparent vertex minus Eye, the
// observer's position, in float), each carrying the whole triangle for the fragment's flat hit.
// Point data: "lcA0".."lcA2" (the triangle's apparent vertices minus Eye), "lcN0".."lcN2" (its
// rest normals), "lcTriangle" (its index in the input) and "lcVD" (the vertex's Doppler factor).
// An empty block gives an empty output; a missing block or array, or a cell that is not a
// triangle, is an error.
#include <vtkPolyDataAlgorithm.h>

class vtkLightconeSrApparentTriangles : public vtkPolyDataAlgorithm {
public:
    static vtkLightconeSrApparentTriangles* New();
    vtkTypeMacro(vtkLightconeSrApparentTriangles, vtkPolyDataAlgorithm)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // The observer's position in S (the camera's; default the origin).
    vtkSetVector3Macro(Eye, double);
    vtkGetVector3Macro(Eye, double);

protected:
    vtkLightconeSrApparentTriangles();
    ~vtkLightconeSrApparentTriangles() override = default;
    int FillInputPortInformation(int port, vtkInformation* info) override;
    int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

    double Eye[3] = {0.0, 0.0, 0.0};

private:
    vtkLightconeSrApparentTriangles(const vtkLightconeSrApparentTriangles&) = delete;
    void operator=(const vtkLightconeSrApparentTriangles&) = delete;
};

#endif
