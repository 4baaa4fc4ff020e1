// mirrors lc::ImageTexture::sample (core/scene/texture.hpp) on one entry of the post-renderer's float texture atlas (lcEntries texel e: first row, width, height, 1 = bilinear as the image texture, 0 = nearest for a procedural texture baked at its cells' resolution); u wraps, v is clamped.
uniform sampler2D lcAtlas;
uniform sampler2D lcEntries;
vec3 lcAtlasTexel(vec4 e, int i, int j)
{
  int w = int(e.y), h = int(e.z);
  i = ((i % w) + w) % w;
  j = clamp(j, 0, h - 1);
  return texelFetch(lcAtlas, ivec2(i, int(e.x) + j), 0).rgb;
}
vec3 lcAtlasSample(int entry, vec2 uv)
{
  vec4 e = texelFetch(lcEntries, ivec2(entry, 0), 0);
  float u = uv.x - floor(uv.x), v = clamp(uv.y, 0.0, 1.0);
  if (e.w < 0.5)
    return lcAtlasTexel(e, int(floor(u * e.y)), int(floor(v * e.z)));
  float x = u * e.y - 0.5, y = v * e.z - 0.5;
  int x0 = int(floor(x)), y0 = int(floor(y));
  float fx = x - float(x0), fy = y - float(y0);
  return (1.0 - fy) * ((1.0 - fx) * lcAtlasTexel(e, x0, y0) + fx * lcAtlasTexel(e, x0 + 1, y0)) +
         fy * ((1.0 - fx) * lcAtlasTexel(e, x0, y0 + 1) + fx * lcAtlasTexel(e, x0 + 1, y0 + 1));
}
