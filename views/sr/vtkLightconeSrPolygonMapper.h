// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeSrPolygonMapper_h
#define vtkLightconeSrPolygonMapper_h
// Polygon distortion of special relativity (seed 003 sect. 3.2, the comparison of its Table 1) as
// a mapper: the GPU twin of lc::sr::SrRenderer's PolygonDistortion. The input
// (vtkLightconeSrApparentTriangles) is the flat triangles through the apparent vertices, relative
// to the eye; the vertex shader projects them through the pinhole (the generated
// lcPinholeHomogeneous, lc::Camera::project's formula), the fragment takes the distance and barycentrics of its
// pixel's ray on the flat triangle (glsl/sr_flat_hit) and colours with the pixel's Doppler factor,
// or, with PerVertexDoppler on, with each apparent vertex's factor interpolated across the
// triangle (the classic per-vertex colouring). A panorama is refused: it would bend the edges that
// the rasteriser draws straight (lc::sr::SrRenderer traces the flat triangles in a panorama).
#include "vtkLightconeSrMapper.h"

class vtkLightconeSrPolygonMapper : public vtkLightconeSrMapper {
public:
    static vtkLightconeSrPolygonMapper* New();
    vtkTypeMacro(vtkLightconeSrPolygonMapper, vtkLightconeSrMapper)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // A uniform, as the base class's settings.
    void SetPerVertexDoppler(bool on) { this->PerVertexDoppler = on; }
    bool GetPerVertexDoppler() const { return this->PerVertexDoppler; }

protected:
    vtkLightconeSrPolygonMapper();
    ~vtkLightconeSrPolygonMapper() override = default;

    std::string VertexDeclarations() const override;
    std::string VertexImplementation() const override;
    std::string FragmentDeclarations() const override;
    std::string FragmentImplementation() const override;
    void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
    void CheckProjection(const lc::Camera& camera) const override;

private:
    vtkLightconeSrPolygonMapper(const vtkLightconeSrPolygonMapper&) = delete;
    void operator=(const vtkLightconeSrPolygonMapper&) = delete;

    bool PerVertexDoppler = false;
};

#endif
