// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeSrRayTracingMapper.h"

#include "sr_glsl.hpp"
#include "lightcone_glsl_sr_ray_fragment.h"
#include "lightcone_glsl_sr_ray_fragment_dec.h"
#include "lightcone_glsl_sr_ray_vertex.h"
#include "lightcone_glsl_sr_ray_vertex_dec.h"
#include "lightcone_glsl_sr_rest_ray_hit.h"

#include <vtkObjectFactory.h>

vtkStandardNewMacro(vtkLightconeSrRayTracingMapper);

vtkLightconeSrRayTracingMapper::vtkLightconeSrRayTracingMapper() {
    for (const char* name : {"lcP0", "lcP1", "lcP2", "lcN0", "lcN1", "lcN2"}) this->MapAttribute(name);
}

std::string vtkLightconeSrRayTracingMapper::VertexDeclarations() const { return lightcone_glsl_sr_ray_vertex_dec; }
std::string vtkLightconeSrRayTracingMapper::VertexImplementation() const { return lightcone_glsl_sr_ray_vertex; }
std::string vtkLightconeSrRayTracingMapper::FragmentDeclarations() const {
    return std::string(lightcone_glsl_sr_ray_fragment_dec) + lc::views::srTriangleHitsGlsl() +
           lightcone_glsl_sr_rest_ray_hit;
}
std::string vtkLightconeSrRayTracingMapper::FragmentImplementation() const { return lightcone_glsl_sr_ray_fragment; }

void vtkLightconeSrRayTracingMapper::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
}
