// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: the Goedel mapper's fragment inputs from its vertex shader and its
// uniforms (vtkLightconeGodelImageMapper::SetMapperShaderParameters).
//VTK::PositionVC::Dec
in vec3 lcLightVSOut;
in float lcTemperatureVSOut;
uniform int lcMode;         // 0 colour, 1 object ids
uniform float lcObjectId;   // (object + 1) / 255
