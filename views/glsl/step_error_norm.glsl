// the GPU tracer's own error norm for lcDopri5Step (no core twin: the CPU uses odeint's
// controlled stepper): max over components of |e| / (lcTolerance (1 + max(|y0|, |y1|))), <= 1 for
// an accepted step; e is the fifth- minus fourth-order solution, y0 and y1 the states before and after.
float lcStepErrorNorm(vec4 e, vec4 y0, vec4 y1)
{
  vec4 q = abs(e) / (lcTolerance * (vec4(1.0) + max(abs(y0), abs(y1))));
  return max(max(q.x, q.y), max(q.z, q.w));
}
