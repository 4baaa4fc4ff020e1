// SPDX-License-Identifier: BSD-3-Clause
// lc::ImageTexture::sample (core/scene/texture.hpp) on one entry of the post-renderer's float
// texture atlas (lcEntries texel e: first row, width, height, 1 = bilinear as the image texture,
// 0 = nearest for a procedural texture baked at its cells' resolution). The position, the texel
// addressing (u wraps, v is clamped) and the blend are the generated lcTexelPosition, lcTexelIndex
// and lcBilinear; here only the entry's rows in the atlas.
uniform sampler2D lcAtlas;
uniform sampler2D lcEntries;
vec3 lcAtlasTexel(vec4 e, int i, int j)
{
  ivec2 texel = ivec2(lcTexelIndex(vec2(i, j), e.yz));
  return texelFetch(lcAtlas, ivec2(texel.x, int(e.x) + texel.y), 0).rgb;
}
vec3 lcAtlasSample(int entry, vec2 uv)
{
  vec4 e = texelFetch(lcEntries, ivec2(entry, 0), 0);
  vec2 p = lcTexelPosition(uv, e.yz);
  if (e.w < 0.5)  // nearest: the texel whose centre is closest
    return lcAtlasTexel(e, int(floor(p.x + 0.5)), int(floor(p.y + 0.5)));
  int x0 = int(floor(p.x)), y0 = int(floor(p.y));
  return lcBilinear(lcAtlasTexel(e, x0, y0), lcAtlasTexel(e, x0 + 1, y0), lcAtlasTexel(e, x0, y0 + 1),
                    lcAtlasTexel(e, x0 + 1, y0 + 1), p - vec2(x0, y0));
}
