// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: polygon distortion's per-triangle attributes
// (vtkLightconeSrApparentTriangles: the apparent triangle relative to the eye, the rest normals,
// the triangle index, each apparent vertex's Doppler factor), passed to the fragments.
in vec3 lcA0;
in vec3 lcA1;
in vec3 lcA2;
in vec3 lcN0;
in vec3 lcN1;
in vec3 lcN2;
in float lcTriangle;
in float lcVD;
flat out vec3 lcA0V;
flat out vec3 lcA1V;
flat out vec3 lcA2V;
flat out vec3 lcN0V;
flat out vec3 lcN1V;
flat out vec3 lcN2V;
flat out float lcTriangleV;
out float lcVDV;
