// SPDX-License-Identifier: BSD-3-Clause
// calls lc::pinholeHomogeneous (core/scene/camera.hpp, Camera::project; generated
// lcPinholeHomogeneous): vertexMC is the apparent vertex relative to the eye; its homogeneous screen
// offsets (sx w, sy w, w) are clip coordinates as they stand (GL clips what is behind the camera).
// Pinhole only: a panorama would bend the triangle's edges (vtkLightconeSrPolygonMapper refuses it).
//VTK::PositionVC::Impl
vec3 lcScreenH = lcPinholeHomogeneous(vertexMC.xyz, lcForward, lcRight, lcUp, lcTanHalfX, lcTanHalfY);
gl_Position = vec4(lcScreenH.xy, 0.0, lcScreenH.z);
lcA0V = lcA0; lcA1V = lcA1; lcA2V = lcA2;
lcN0V = lcN0; lcN1V = lcN1; lcN2V = lcN2;
lcTriangleV = lcTriangle; lcVDV = lcVD;
