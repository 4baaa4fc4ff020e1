// calls lc::sr::pinholePixelHomogeneous (core/sr/camera.hpp, PinholeCamera::Basis::project; generated
// lcSrPixelHomogeneous): vertexMC is the apparent vertex relative to the eye; lcPixelClip makes its
// homogeneous pixel coordinates clip coordinates (GL clips what is behind the camera).
//VTK::PositionVC::Impl
gl_Position = lcPixelClip(lcSrPixelHomogeneous(vertexMC.xyz, lcFocal, lcCx, lcCy, lcSrForward, lcSrRight, lcSrUp));
lcA0V = lcA0; lcA1V = lcA1; lcA2V = lcA2;
lcN0V = lcN0; lcN1V = lcN1; lcN2V = lcN2;
lcTriangleV = lcTriangle; lcVDV = lcVD;
