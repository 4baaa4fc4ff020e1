// mirrors lc::Spacetime::flow (core/spacetime/spacetime.hpp): Hamilton's equations for H = 1/2 g^{mu nu} p_mu p_nu,
//   dx/dl = v = g^{-1} p,  dp_k/dl = 1/2 v^T (d_k g) v,
// with g and d_k g from lcMetric, which is generated from the metric's C++ code (core/codegen).
void lcFlow(vec4 x, vec4 p, out vec4 dx, out vec4 dp)
{
  mat4 g, dg0, dg1, dg2, dg3;
  lcMetric(x, g, dg0, dg1, dg2, dg3);
  vec4 v = inverse(g) * p;
  dx = v;
  dp = 0.5 * vec4(dot(v, dg0 * v), dot(v, dg1 * v), dot(v, dg2 * v), dot(v, dg3 * v));
}
