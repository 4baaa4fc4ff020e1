// mirrors lc::toSkyUv (core/render/numeric.cpp): u = 1/2 + atan2(y, x) / 2 pi, v = acos(z) / pi.
// GLSL leaves atan(0, 0) undefined (llvmpipe gives 3 pi / 4) where std::atan2 gives 0: a
// direction along the pole gets u = 1/2 on both (found by the per-function test).
vec2 lcSkyUv(vec3 d)
{
  float phi = (d.x == 0.0 && d.y == 0.0) ? 0.0 : atan(d.y, d.x);
  return vec2(0.5 + phi / 6.28318530717958647, acos(clamp(d.z, -1.0, 1.0)) / 3.14159265358979323846);
}
