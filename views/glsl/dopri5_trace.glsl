// mirrors lc::traceGeodesic (core/integrator.cpp) with boost::numeric::odeint::runge_kutta_dopri5:
// the Dormand-Prince 5(4) pair with first-same-as-last, error per component relative to
// lcTolerance (1 + max |y|), the same stops (boundary, escape, affine limit, null condition).
float lcMaxAbs(vec4 e, vec4 y0, vec4 y1)
{
  vec4 q = abs(e) / (lcTolerance * (vec4(1.0) + max(abs(y0), abs(y1))));
  return max(max(q.x, q.y), max(q.z, q.w));
}

// Traces the past-directed null ray seen along frame direction n. Returns 0 (escaped, dir =
// the spatial contravariant tangent at escape), 1 (boundary: a horizon), 2 (failed) or 3 (the
// affine limit: background); steps = trial steps.
int lcTrace(vec3 n, out vec3 dir, out int steps)
{
  dir = vec3(0.0);
  steps = 0;
  // k = -e0 + n^i e_i, lowered with g(x0) (lc::LocalFrame::pastNullMomentum).
  vec4 k = -lcE0 + n.x * lcE1 + n.y * lcE2 + n.z * lcE3;
  vec4 p = vec4(dot(lcG0r0, k), dot(lcG0r1, k), dot(lcG0r2, k), dot(lcG0r3, k));
  vec4 x = lcObserver;
  vec4 k1x, k1p;
  lcFlow(x, p, k1x, k1p);
  float h = lcInitialStep;
  float affine = 0.0;
  for (int it = 0; it < lcMaxSteps; ++it)
  {
    steps = it + 1;
    h = min(h, lcStepPerRadius * max(length(x.yzw), lcRadiusFloor));
    h = min(h, lcMaxAffine - affine);  // end exactly on the affine limit
    vec4 k2x, k2p, k3x, k3p, k4x, k4p, k5x, k5p, k6x, k6p, k7x, k7p;
    lcFlow(x + h * (0.2 * k1x), p + h * (0.2 * k1p), k2x, k2p);
    lcFlow(x + h * (3.0 / 40.0 * k1x + 9.0 / 40.0 * k2x), p + h * (3.0 / 40.0 * k1p + 9.0 / 40.0 * k2p), k3x, k3p);
    lcFlow(x + h * (44.0 / 45.0 * k1x - 56.0 / 15.0 * k2x + 32.0 / 9.0 * k3x),
           p + h * (44.0 / 45.0 * k1p - 56.0 / 15.0 * k2p + 32.0 / 9.0 * k3p), k4x, k4p);
    lcFlow(x + h * (19372.0 / 6561.0 * k1x - 25360.0 / 2187.0 * k2x + 64448.0 / 6561.0 * k3x - 212.0 / 729.0 * k4x),
           p + h * (19372.0 / 6561.0 * k1p - 25360.0 / 2187.0 * k2p + 64448.0 / 6561.0 * k3p - 212.0 / 729.0 * k4p),
           k5x, k5p);
    lcFlow(x + h * (9017.0 / 3168.0 * k1x - 355.0 / 33.0 * k2x + 46732.0 / 5247.0 * k3x + 49.0 / 176.0 * k4x - 5103.0 / 18656.0 * k5x),
           p + h * (9017.0 / 3168.0 * k1p - 355.0 / 33.0 * k2p + 46732.0 / 5247.0 * k3p + 49.0 / 176.0 * k4p - 5103.0 / 18656.0 * k5p),
           k6x, k6p);
    vec4 xn = x + h * (35.0 / 384.0 * k1x + 500.0 / 1113.0 * k3x + 125.0 / 192.0 * k4x - 2187.0 / 6784.0 * k5x + 11.0 / 84.0 * k6x);
    vec4 pn = p + h * (35.0 / 384.0 * k1p + 500.0 / 1113.0 * k3p + 125.0 / 192.0 * k4p - 2187.0 / 6784.0 * k5p + 11.0 / 84.0 * k6p);
    lcFlow(xn, pn, k7x, k7p);
    // Fifth minus fourth order solution.
    vec4 ex = h * (71.0 / 57600.0 * k1x - 71.0 / 16695.0 * k3x + 71.0 / 1920.0 * k4x - 17253.0 / 339200.0 * k5x + 22.0 / 525.0 * k6x - 1.0 / 40.0 * k7x);
    vec4 ep = h * (71.0 / 57600.0 * k1p - 71.0 / 16695.0 * k3p + 71.0 / 1920.0 * k4p - 17253.0 / 339200.0 * k5p + 22.0 / 525.0 * k6p - 1.0 / 40.0 * k7p);
    float err = max(lcMaxAbs(ex, x, xn), lcMaxAbs(ep, p, pn));
    if (!(err <= 1.0))  // rejected (NaN included)
    {
      h *= (err > 1.0 && err < 1e30) ? max(0.2, 0.9 * pow(err, -0.2)) : 0.2;
      if (h < 1e-7) return 2;
      continue;
    }
    x = xn;
    p = pn;
    k1x = k7x;
    k1p = k7p;
    affine += h;
    h *= min(5.0, 0.9 * pow(max(err, 1e-10), -0.2));
    if (any(isnan(x)) || any(isinf(x)) || any(isnan(p)) || any(isinf(p))) return 2;
    // Null condition H = 1/2 p.v (v = g^{-1} p is the first stage of the next step, free):
    // a ray whose |H| grew past the tolerance fails, as ConstraintBlowUp on the CPU. In
    // single precision |H| is measured relative to 1/2 sum |p_mu v^mu| (1 at the observer,
    // where the observed frequency is 1), since the terms of p.v grow with the blueshift
    // towards the horizon and float round-off grows with them.
    if (abs(dot(p, k1x)) > lcConstraintTolerance * dot(abs(p), abs(k1x))) return 2;
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
