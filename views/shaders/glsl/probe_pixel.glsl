// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: the GLSL probe's pixel (glsl_probe). Row j evaluates the
// probed code at input j; column 2 q + h carries half h (16 bits) of output q's float bits in
// red and green, so that an 8-bit framebuffer returns every float exactly; blue 1 marks a
// pixel the probe drew (the clear colour is black: a shader that failed to compile draws none).
//VTK::TCoord::Impl
{
  int lcColumn = int(gl_FragCoord.x);
  vec4 lcIn = lcInputs[int(gl_FragCoord.y)];
  float lcOut[LC_PROBE_OUTPUTS];
  for (int k = 0; k < LC_PROBE_OUTPUTS; ++k) lcOut[k] = 0.0;
  LC_PROBE_BODY
  uint lcBits = floatBitsToUint(lcOut[lcColumn / 2]);
  uint lcHalf = (lcColumn % 2 == 0) ? (lcBits & 0xFFFFu) : (lcBits >> 16);
  gl_FragData[0] = vec4(float(lcHalf & 0xFFu) / 255.0, float(lcHalf >> 8) / 255.0, 1.0, 1.0);
}
