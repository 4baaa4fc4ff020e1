// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: polygon distortion's per-triangle inputs.
flat in vec3 lcA0V;
flat in vec3 lcA1V;
flat in vec3 lcA2V;
flat in vec3 lcN0V;
flat in vec3 lcN1V;
flat in vec3 lcN2V;
flat in float lcTriangleV;
in float lcVDV;
