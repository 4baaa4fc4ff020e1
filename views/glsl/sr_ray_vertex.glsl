// mirrors lc::sr::PinholeCamera's pixel coordinates (core/sr/camera.hpp): vertexMC is the quad
// corner in continuous pixel coordinates, row 0 at the top; everything else is passed flat.
//VTK::PositionVC::Impl
gl_Position = vec4(2.0 * vertexMC.x / lcW - 1.0, 1.0 - 2.0 * vertexMC.y / lcH, 0.0, 1.0);
lcP0V = lcP0; lcP1V = lcP1; lcP2V = lcP2;
lcN0V = lcN0; lcN1V = lcN1; lcN2V = lcN2;
lcBetaV = lcBeta; lcObsV = lcObs; lcMatV = lcMat;
