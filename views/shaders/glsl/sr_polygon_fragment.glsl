// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::sr::SrRenderer's polygon distortion per pixel (core/sr/renderer.cpp): distance and
// barycentrics on the apparent triangle (lcFlatHit); D per vertex (interpolated) or per pixel.
//VTK::TCoord::Impl
{
  vec3 d = lcCameraDirection(gl_FragCoord.xy);
  float s, u, v;
  lcFlatHit(d, lcA0V, lcA1V, lcA2V, s, u, v);
  float D = lcVertexDoppler != 0 ? lcVDV : lcRestRayDoppler(lcBeta, d);  // generated: lc::sr::restRayDoppler
  gl_FragData[0] = lcOutput(d, s, D, u, v, lcN0V, lcN1V, lcN2V, lcTriangleV);
}
