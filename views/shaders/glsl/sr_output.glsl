// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::sr::SrImage's per-pixel outputs (core/sr/renderer.hpp): the colour, or for the id
// pass the object (red, + 1) and triangle (green/blue, + 1); depth on one monotonic scale for
// every triangle of every object, the apparent distance. (gl_FragData is VTK's macro for an
// output declared later: only main() may write it, so this returns the value.)
vec4 lcOutput(vec3 d, float depth, float D, float u, float v, vec3 n0, vec3 n1, vec3 n2, float tri)
{
  vec4 res;
  if (lcIdPass != 0)
  {
    float t = tri + 1.0;
    float hi = floor(t / 256.0);
    res = vec4((lcObjectId + 1.0) / 255.0, hi / 255.0, (t - 256.0 * hi) / 255.0, 1.0);
  }
  else
    res = vec4(lcShade(d, depth, D, u, v, n0, n1, n2), 1.0);
  gl_FragDepth = depth / (depth + lcDepthScale);
  return res;
}
