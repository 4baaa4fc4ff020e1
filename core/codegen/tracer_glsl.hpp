#pragma once
// The GPU tracer's Hamilton's equations and its Dormand-Prince step, generated from the C++ the
// CPU runs: lc::hamiltonEquations and Boost.Odeint's runge_kutta_dopri5, each instantiated with
// codegen::Expr, so neither the formula nor the Butcher tableau is typed a second time in GLSL.
#include "core/codegen/symbolic_metric.hpp"

namespace lc::codegen {

// void lcFlow(vec4 x, vec4 p, out vec4 dxdl, out vec4 dpdl): calls lcMetric (metricGlsl) and
// evaluates lc::hamiltonEquations on its g and dg (g symmetric: one name per pair of entries).
GeneratedGlsl flowGlsl();

// float lcDopri5Step(vec4 x, vec4 p, vec4 k1x, vec4 k1p, float h,
//                    out vec4 xn, out vec4 pn, out vec4 k7x, out vec4 k7p)
// One step of odeint's runge_kutta_dopri5::do_step (first same as last: k1 given, k7 returned)
// recorded stage by stage: each stage's argument is printed, then `lcFlow` is called on it.
// Returns the step's error norm through lcStepErrorNorm(error, y0, y1) (views/glsl), <= 1 for an
// accepted step.
GeneratedGlsl dopri5StepGlsl();

}  // namespace lc::codegen
