// mirrors boost::numeric::odeint::runge_kutta_dopri5::do_step as lc::traceGeodesic uses it
// (core/spacetime/integrator.cpp) on lcFlow: one Dormand-Prince 5(4) step of size h from (x, p) with the
// first stage k1 given (first-same-as-last), giving the fifth-order state (xn, pn), its stage
// k7 (the next step's k1) and the error norm: max over components of |y5 - y4| /
// (lcTolerance (1 + max(|y0|, |y1|))), <= 1 for an accepted step.
float lcMaxAbs(vec4 e, vec4 y0, vec4 y1)
{
  vec4 q = abs(e) / (lcTolerance * (vec4(1.0) + max(abs(y0), abs(y1))));
  return max(max(q.x, q.y), max(q.z, q.w));
}

float lcDopri5Step(vec4 x, vec4 p, vec4 k1x, vec4 k1p, float h, out vec4 xn, out vec4 pn, out vec4 k7x, out vec4 k7p)
{
  vec4 k2x, k2p, k3x, k3p, k4x, k4p, k5x, k5p, k6x, k6p;
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
  xn = x + h * (35.0 / 384.0 * k1x + 500.0 / 1113.0 * k3x + 125.0 / 192.0 * k4x - 2187.0 / 6784.0 * k5x + 11.0 / 84.0 * k6x);
  pn = p + h * (35.0 / 384.0 * k1p + 500.0 / 1113.0 * k3p + 125.0 / 192.0 * k4p - 2187.0 / 6784.0 * k5p + 11.0 / 84.0 * k6p);
  lcFlow(xn, pn, k7x, k7p);
  // Fifth minus fourth order solution.
  vec4 ex = h * (71.0 / 57600.0 * k1x - 71.0 / 16695.0 * k3x + 71.0 / 1920.0 * k4x - 17253.0 / 339200.0 * k5x + 22.0 / 525.0 * k6x - 1.0 / 40.0 * k7x);
  vec4 ep = h * (71.0 / 57600.0 * k1p - 71.0 / 16695.0 * k3p + 71.0 / 1920.0 * k4p - 17253.0 / 339200.0 * k5p + 22.0 / 525.0 * k6p - 1.0 / 40.0 * k7p);
  return max(lcMaxAbs(ex, x, xn), lcMaxAbs(ep, p, pn));
}
