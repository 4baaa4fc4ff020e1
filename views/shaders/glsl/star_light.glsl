// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::LightMap::at (core/scene/texture.hpp) on the float texture lcStarLight of a star
// sky's texels (red b, green b T): the position, the addressing (u wraps, v is clamped) and the
// blend are the generated lcTexelPosition, lcTexelIndex and lcBilinear, the texels fetched
// exactly, so the GPU blends the same numbers as the CPU. Returns (b, T); T = 0 where b = 0.
uniform sampler2D lcStarLight;
vec3 lcStarLightTexel(vec2 size, int i, int j)
{
  return vec3(texelFetch(lcStarLight, ivec2(lcTexelIndex(vec2(i, j), size)), 0).rg, 0.0);
}
vec2 lcStarLightAt(vec2 uv)
{
  vec2 size = vec2(textureSize(lcStarLight, 0));
  vec2 p = lcTexelPosition(uv, size);
  int x0 = int(floor(p.x)), y0 = int(floor(p.y));
  vec3 c = lcBilinear(lcStarLightTexel(size, x0, y0), lcStarLightTexel(size, x0 + 1, y0),
                      lcStarLightTexel(size, x0, y0 + 1), lcStarLightTexel(size, x0 + 1, y0 + 1), p - vec2(x0, y0));
  return c.x > 0.0 ? vec2(c.x, c.y / c.x) : vec2(0.0);
}
