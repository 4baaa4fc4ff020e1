// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeSrRayTracingMapper_h
#define vtkLightconeSrRayTracingMapper_h
// Local ray tracing of special relativity (seed 003 sect. 4) as a mapper: the GPU twin of
// lc::sr::SrRenderer's LocalRayTracing. The input (vtkLightconeSrFootprintQuads) is one quad per
// triangle over the conservative screen footprint of its curved apparent image, each corner
// carrying the rest triangle and its normals; every fragment builds its pixel's viewing ray, boosts
// it into the object's rest frame and intersects the rest triangle exactly (glsl/sr_rest_ray_hit on
// the generated lcBoostDirection, lcRestRayDoppler and lcRestTriangleHit), discards a miss and
// writes the apparent distance sigma D as depth; the colour is lcShade (vtkLightconeSrMapper).
#include "vtkLightconeSrMapper.h"

class vtkLightconeSrRayTracingMapper : public vtkLightconeSrMapper {
public:
    static vtkLightconeSrRayTracingMapper* New();
    vtkTypeMacro(vtkLightconeSrRayTracingMapper, vtkLightconeSrMapper)
    void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
    vtkLightconeSrRayTracingMapper();
    ~vtkLightconeSrRayTracingMapper() override = default;

    std::string VertexDeclarations() const override;
    std::string VertexImplementation() const override;
    std::string FragmentDeclarations() const override;
    std::string FragmentImplementation() const override;

private:
    vtkLightconeSrRayTracingMapper(const vtkLightconeSrRayTracingMapper&) = delete;
    void operator=(const vtkLightconeSrRayTracingMapper&) = delete;
};

#endif
