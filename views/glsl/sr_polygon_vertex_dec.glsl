// mirrors nothing in core: per-triangle data of polygon distortion, passed to the fragments.
//VTK::PositionVC::Dec
in vec3 lcA0;
in vec3 lcA1;
in vec3 lcA2;
in vec3 lcN0;
in vec3 lcN1;
in vec3 lcN2;
in vec4 lcBeta;
in vec4 lcMat;
in vec2 lcIds;
in float lcVD;
flat out vec3 lcA0V;
flat out vec3 lcA1V;
flat out vec3 lcA2V;
flat out vec3 lcN0V;
flat out vec3 lcN1V;
flat out vec3 lcN2V;
flat out vec4 lcBetaV;
flat out vec4 lcMatV;
flat out vec2 lcIdsV;
out float lcVDV;
