// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: local ray tracing's flat per-triangle inputs.
flat in vec4 lcP0V;
flat in vec3 lcP1V;
flat in vec3 lcP2V;
flat in vec3 lcN0V;
flat in vec3 lcN1V;
flat in vec3 lcN2V;
