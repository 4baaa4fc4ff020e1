// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: the Goedel renderer's per-vertex attributes, next to the mapper's own.
//   vertexMC: unit image direction in the observer's frame (e1, e2, e3)
//   lcAux:    xyz the triangle's centroid direction (panorama unwrapping), w the depth lambda
//   lcLight:  linear RGB light factor of the vertex (1 when unlit)
//   lcTemperature: D T of a black-body emitter at the vertex (0: use the texture)
//VTK::PositionVC::Dec
in vec4 lcAux;
in vec3 lcLight;
in float lcTemperature;
out vec3 lcLightVSOut;
out float lcTemperatureVSOut;
