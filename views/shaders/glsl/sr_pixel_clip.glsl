// SPDX-License-Identifier: BSD-3-Clause
// mirrors nothing in core: GL's viewport transform, inverted, for an image of lcWidth x lcHeight
// pixels with row 0 at the top: homogeneous pixel coordinates (px w, py w, w) (lc::Camera::project's
// x and y times w) become clip coordinates (w < 0 is clipped). The depth is written by the
// fragment shader.
vec4 lcPixelClip(vec3 h)
{
  return vec4(2.0 * h.x / lcWidth - h.z, h.z - 2.0 * h.y / lcHeight, 0.0, h.z);
}
