// SPDX-License-Identifier: BSD-3-Clause
// mirrors lc::traceGeodesic (core/spacetime/integrator.cpp): control flow only. Adaptive steps of
// lcDopri5Step under odeint's step control (lcStepErrorNorm, lcDecreaseStep, lcIncreaseStep, all
// generated from odeint's controlled_runge_kutta), the same stops (boundary, affine limit, the
// null condition's lcConstraintDrift, escape). Two rules are the GPU's own, for speed: the
// far-field step cap (lcFarStepPerRadius, see vtkLightconeNumericImageRenderer) and the escape
// test (outgoing beyond lcEscapeRadius; the CPU also waits until the bending still ahead is below
// its escape angle).

// Traces the past-directed null ray seen along frame direction n. Returns 0 (escaped, dir =
// the spatial contravariant tangent at escape), 1 (boundary: a horizon), 2 (failed), 3 (the
// affine limit: background) or, with LC_DISK, 4 (an accretion disk: dir = (g, r, F / F_max),
// glsl/geodesic_disk); steps = trial steps, launchPt = the launch momentum's p_t (conserved in a
// stationary metric: the black-body sky's g is 1 / |p_t|).
int lcTrace(vec3 n, out vec3 dir, out int steps, out float launchPt)
{
  dir = vec3(0.0);
  steps = 0;
  // The generated lc::pastNullMomentumAlong, as lc::LocalFrame::pastNullMomentum launches a ray.
  vec4 p = lcPastNullMomentum(n, lcE0, lcE1, lcE2, lcE3, lcG0r0, lcG0r1, lcG0r2, lcG0r3);
  launchPt = p.x;
  vec4 x = lcObserver;
  float launchScale = max(1.0, dot(p, p));  // |p_0|^2, as the CPU's RayMonitor
  vec4 k1x, k1p;
  lcFlow(x, p, k1x, k1p);
  float h = lcInitialStep;
  float affine = 0.0;
  int crossings = 0;
  for (int it = 0; it < lcMaxSteps; ++it)
  {
    steps = it + 1;
    // Step cap per radius; an outgoing ray beyond lcFarRadius is in the weak field for good
    // (asymptotically flat metrics) and may take longer steps there, error permitting.
    float r = length(x.yzw);
    bool farOutgoing = r > lcFarRadius && dot(x.yzw, k1x.yzw) > 0.0;
    h = min(h, (farOutgoing ? lcFarStepPerRadius : lcStepPerRadius) * max(r, 1.0));  // >= 1: rays from the origin move
    h = min(h, lcMaxAffine - affine);  // end exactly on the affine limit
    vec4 xn, pn, k7x, k7p;
    float err = lcDopri5Step(x, p, k1x, k1p, h, xn, pn, k7x, k7p);
    if (!(err <= 1.0))  // rejected (NaN included: shrunk as far as odeint shrinks, by 5)
    {
      h = lcDecreaseStep(h, err < 1e30 ? err : 1e30);
      if (h < 1e-7) return 2;
      continue;
    }
#ifdef LC_DISK
    vec3 disk;
    if (lcDiskHit(x, k1x, p, k1p, xn, k7x, pn, k7p, h, crossings, disk))
    {
      dir = disk;
      return 4;
    }
#endif
    x = xn;
    p = pn;
    k1x = k7x;
    k1p = k7p;
    affine += h;
    h = lcIncreaseStep(h, err);
    if (any(isnan(x)) || any(isinf(x)) || any(isnan(p)) || any(isinf(p))) return 2;
    // Null condition H = 1/2 p.v (v = g^{-1} p is the first stage of the next step, free): a ray
    // whose drift (the generated lcConstraintDrift, lc::constraintDrift) exceeds the tolerance
    // fails, as ConstraintBlowUp on the CPU; the GPU's tolerance is its own (single precision).
    if (lcConstraintDrift(p, k1x, launchScale) > lcConstraintTolerance) return 2;
#ifdef LC_OTHER_END
    if (lcOtherEnd(x) < lcBoundaryStop)  // a two-ended metric's far side: lc::Spacetime::otherEndDirection
    {
      dir = lcOtherEndDirection(x.yzw, k1x.yzw);
      return 5;
    }
#endif
    if (lcBoundary(x) < lcBoundaryStop) return 1;
    if (lcEscapes != 0 && dot(x.yzw, x.yzw) > lcEscapeRadius * lcEscapeRadius && dot(x.yzw, k1x.yzw) > 0.0)
    {
      dir = normalize(k1x.yzw);
      return 0;
    }
    if (affine >= lcMaxAffine) return 3;
  }
  return 2;
}
