// mirrors nothing in core: local ray tracing's flat per-triangle inputs.
//VTK::PositionVC::Dec
flat in vec4 lcP0V;
flat in vec4 lcP1V;
flat in vec4 lcP2V;
flat in vec3 lcN0V;
flat in vec3 lcN1V;
flat in vec3 lcN2V;
flat in vec4 lcBetaV;
flat in vec4 lcObsV;
flat in vec4 lcMatV;
