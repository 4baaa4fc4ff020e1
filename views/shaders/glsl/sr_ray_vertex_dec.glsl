// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: local ray tracing's per-triangle attributes (vtkLightconeSrFootprintQuads:
// the rest triangle, its triangle index in lcP0.w, its rest normals), passed flat to the fragments.
in vec4 lcP0;
in vec3 lcP1;
in vec3 lcP2;
in vec3 lcN0;
in vec3 lcN1;
in vec3 lcN2;
flat out vec4 lcP0V;
flat out vec3 lcP1V;
flat out vec3 lcP2V;
flat out vec3 lcN0V;
flat out vec3 lcN1V;
flat out vec3 lcN2V;
