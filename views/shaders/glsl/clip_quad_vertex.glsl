// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: a full-screen quad whose points are already clip-space positions.
//VTK::PositionVC::Impl
gl_Position = vec4(vertexMC.xy, 0.0, 1.0);
