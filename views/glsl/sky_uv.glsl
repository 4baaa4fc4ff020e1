// mirrors lc::toSkyUv (core/render.cpp): u = 1/2 + atan2(y, x) / 2 pi, v = acos(z) / pi.
vec2 lcSkyUv(vec3 d)
{
  return vec2(0.5 + atan(d.y, d.x) / 6.28318530717958647, acos(clamp(d.z, -1.0, 1.0)) / 3.14159265358979323846);
}
