// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: vertexMC is a corner of the triangle's footprint in continuous pixel
// coordinates (lc::sr::apparentFootprint), placed by lcPixelClip; the triangle passes flat.
//VTK::PositionVC::Impl
gl_Position = lcPixelClip(vec3(vertexMC.xy, 1.0));
lcP0V = lcP0; lcP1V = lcP1; lcP2V = lcP2;
lcN0V = lcN0; lcN1V = lcN1; lcN2V = lcN2;
