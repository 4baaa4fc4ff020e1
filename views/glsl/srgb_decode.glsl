// mirrors lc::colour::srgbDecode (core/colour/srgb.cpp), per component: display sRGB to linear.
vec3 lcSrgbDecode(vec3 e)
{
  return mix(e / 12.92, pow((e + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), e));
}
