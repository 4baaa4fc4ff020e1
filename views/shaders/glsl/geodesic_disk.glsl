// SPDX-License-Identifier: BSD-3-Clause
// mirrors the CPU's intersectDisks and recordDiskHit (core/render/numeric.cpp) for the tracer of
// glsl/geodesic_trace, compiled in when the scene has a disk (LC_DISK): the equatorial plane z = 0
// crossed inside an accepted step is found on the step's cubic Hermite interpolant (the CPU uses
// odeint's dense output); the orbits' Omega, u^t and F / F_max come from a table the mapper fills
// from lc::ThinDiskModel (vtkLightconeGeodesicTracerMapper), evenly spaced in log r. The radius
// (lcDiskRadius, from the metric's equatorial radius), g (lcKeplerianRedshift) and the local temperature (lcDiskLocalTemperature)
// are generated from the core's templates.
uniform float lcDiskInner;
uniform float lcDiskOuter;
uniform float lcDiskLogR0;
uniform float lcDiskLogStep;
uniform int lcDiskEmission;  // 0 black body, 1 bolometric intensity (grey)
uniform float lcDiskTemperature;
uniform vec3 lcDiskTable[LC_DISK_TABLE];

// The cubic Hermite interpolant of a step of length h at fraction s.
vec4 lcHermite(vec4 a, vec4 da, vec4 b, vec4 db, float h, float s)
{
  float s2 = s * s, s3 = s2 * s;
  return (2.0 * s3 - 3.0 * s2 + 1.0) * a + (s3 - 2.0 * s2 + s) * h * da + (3.0 * s2 - 2.0 * s3) * b +
         (s3 - s2) * h * db;
}

// The fraction of the step where its interpolant's z is 0 (z0 and z1 of opposite signs): Newton
// from the chord's root.
float lcPlaneCrossing(float z0, float dz0, float z1, float dz1, float h)
{
  float s = z0 / (z0 - z1);
  for (int i = 0; i < 4; ++i)
  {
    float s2 = s * s, s3 = s2 * s;
    float f = (2.0 * s3 - 3.0 * s2 + 1.0) * z0 + (s3 - 2.0 * s2 + s) * h * dz0 + (3.0 * s2 - 2.0 * s3) * z1 +
              (s3 - s2) * h * dz1;
    float df = (6.0 * s2 - 6.0 * s) * z0 + (3.0 * s2 - 4.0 * s + 1.0) * h * dz0 + (6.0 * s - 6.0 * s2) * z1 +
               (3.0 * s2 - 2.0 * s) * h * dz1;
    s = clamp(s - f / df, 0.0, 1.0);
  }
  return s;
}

// (Omega, u^t, F / F_max) of the circular orbit at radius label r.
vec3 lcDiskOrbit(float r)
{
  float u = (log(r) - lcDiskLogR0) / lcDiskLogStep;
  int i = clamp(int(floor(u)), 0, LC_DISK_TABLE - 2);
  return mix(lcDiskTable[i], lcDiskTable[i + 1], clamp(u - float(i), 0.0, 1.0));
}

// True when the step from (x0, k0x, p0, k0p) to (x1, k1x, p1, k1p) over h meets the disk; then
// hit = (g, r, F / F_max).
bool lcDiskHit(vec4 x0, vec4 k0x, vec4 p0, vec4 k0p, vec4 x1, vec4 k1x, vec4 p1, vec4 k1p, float h,
               inout int crossings, out vec3 hit)
{
  hit = vec3(0.0);
  if (x0.w == 0.0 || (x0.w > 0.0) == (x1.w > 0.0)) return false;
  float s = lcPlaneCrossing(x0.w, k0x.w, x1.w, k1x.w, h);
  vec4 xc = lcHermite(x0, k0x, x1, k1x, h, s);
  vec4 pc = lcHermite(p0, k0p, p1, k1p, h, s);
  float r = lcDiskRadius(xc);
  if (r < lcDiskInner || r > lcDiskOuter)
  {
    crossings += 1;
    return false;
  }
  vec3 orbit = lcDiskOrbit(r);
  // The observer measures g(p, e0) = -1 on the launched momentum (lc::LocalFrame::pastNullMomentum).
  hit = vec3(lcKeplerianRedshift(xc, pc, orbit.x, orbit.y, -1.0), r, orbit.z);
  return true;
}
