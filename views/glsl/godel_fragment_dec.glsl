// mirrors nothing in core: the Goedel renderer's fragment inputs from its vertex shader.
//VTK::PositionVC::Dec
in vec3 lcLightVSOut;
in float lcTemperatureVSOut;
