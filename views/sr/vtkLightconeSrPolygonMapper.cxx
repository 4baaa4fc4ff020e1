// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeSrPolygonMapper.h"

#include "core_formula_glsl.hpp"
#include "sr_glsl.hpp"

#include <stdexcept>
#include "lightcone_glsl_sr_flat_hit.h"
#include "lightcone_glsl_sr_polygon_fragment.h"
#include "lightcone_glsl_sr_polygon_fragment_dec.h"
#include "lightcone_glsl_sr_polygon_vertex.h"
#include "lightcone_glsl_sr_polygon_vertex_dec.h"

#include <vtkObjectFactory.h>
#include <vtkOpenGLHelper.h>
#include <vtkShaderProgram.h>

vtkStandardNewMacro(vtkLightconeSrPolygonMapper);

vtkLightconeSrPolygonMapper::vtkLightconeSrPolygonMapper() {
    for (const char* name : {"lcA0", "lcA1", "lcA2", "lcN0", "lcN1", "lcN2", "lcTriangle", "lcVD"})
        this->MapAttribute(name);
}

std::string vtkLightconeSrPolygonMapper::VertexDeclarations() const {
    return std::string(lightcone_glsl_sr_polygon_vertex_dec) + lc::views::cameraProjectionGlsl();
}
void vtkLightconeSrPolygonMapper::CheckProjection(const lc::Camera& camera) const {
    if (camera.projection != lc::Camera::Projection::Pinhole)
        throw std::invalid_argument(
            "SR polygon distortion on the GPU: the camera must be a pinhole (a panorama bends the straight edges the "
            "rasteriser draws); use local ray tracing, or the CPU's polygon distortion");
}
std::string vtkLightconeSrPolygonMapper::VertexImplementation() const { return lightcone_glsl_sr_polygon_vertex; }
std::string vtkLightconeSrPolygonMapper::FragmentDeclarations() const {
    return std::string(lightcone_glsl_sr_polygon_fragment_dec) + lc::views::srTriangleHitsGlsl() +
           lightcone_glsl_sr_flat_hit;
}
std::string vtkLightconeSrPolygonMapper::FragmentImplementation() const { return lightcone_glsl_sr_polygon_fragment; }

void vtkLightconeSrPolygonMapper::SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) {
    this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
    if (cellBO.Program) cellBO.Program->SetUniformi("lcVertexDoppler", this->PerVertexDoppler ? 1 : 0);
}

void vtkLightconeSrPolygonMapper::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "PerVertexDoppler: " << this->PerVertexDoppler << "\n";
}
