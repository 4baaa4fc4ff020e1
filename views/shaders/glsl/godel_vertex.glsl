// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: the Goedel renderer's vertex body (runs after the mapper's own
// position code and replaces gl_Position with lcProjectImageDirection).
//VTK::PositionVC::Impl
gl_Position = lcProjectImageDirection(normalize(vertexMC.xyz), lcAux.xyz, lcAux.w);
lcLightVSOut = lcLight;
lcTemperatureVSOut = lcTemperature;
