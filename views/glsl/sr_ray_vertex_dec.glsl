// mirrors nothing in core: per-triangle data of local ray tracing, passed flat to the fragments.
//VTK::PositionVC::Dec
in vec4 lcP0;
in vec4 lcP1;
in vec4 lcP2;
in vec3 lcN0;
in vec3 lcN1;
in vec3 lcN2;
in vec4 lcBeta;
in vec4 lcObs;
in vec4 lcMat;
flat out vec4 lcP0V;
flat out vec4 lcP1V;
flat out vec4 lcP2V;
flat out vec3 lcN0V;
flat out vec3 lcN1V;
flat out vec3 lcN2V;
flat out vec4 lcBetaV;
flat out vec4 lcObsV;
flat out vec4 lcMatV;
