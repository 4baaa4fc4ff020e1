// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::sr::SrRenderer's local ray tracing per pixel (core/sr/renderer.cpp): the pixel's
// ray against this triangle in its rest frame; no hit discards the fragment.
//VTK::TCoord::Impl
{
  vec3 d = lcCameraDirection(gl_FragCoord.xy);
  float sigma, D, u, v;
  if (!lcRestRayHit(d, lcBeta, lcObserverRest.yzw, lcP0V.xyz, lcP1V, lcP2V, sigma, D, u, v)) discard;
  gl_FragData[0] = lcOutput(d, sigma * D, D, u, v, lcN0V, lcN1V, lcN2V, lcP0V.w);
}
