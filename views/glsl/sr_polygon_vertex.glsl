// mirrors lc::sr::PinholeCamera::Basis::project (core/sr/camera.cpp) in clip space: vertexMC is
// the apparent vertex relative to the camera, w the forward distance (GL clips what is behind
// the camera). Depth comes from the fragment shader.
//VTK::PositionVC::Impl
{
  vec3 lcP = vertexMC.xyz;
  gl_Position = vec4(lcFocal * dot(lcP, lcRight) / lcCx, lcFocal * dot(lcP, lcUpV) / lcCy, 0.0, dot(lcP, lcFwd));
}
lcA0V = lcA0; lcA1V = lcA1; lcA2V = lcA2;
lcN0V = lcN0; lcN1V = lcN1; lcN2V = lcN2;
lcBetaV = lcBeta; lcMatV = lcMat; lcIdsV = lcIds; lcVDV = lcVD;
