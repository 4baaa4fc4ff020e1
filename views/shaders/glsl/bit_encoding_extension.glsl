// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: floatBitsToUint for the GLSL probe needs GLSL 3.30 or this
// extension (VTK declares #version 150). Placed right after VTK's #version line.
//VTK::System::Dec
#extension GL_ARB_shader_bit_encoding : require
