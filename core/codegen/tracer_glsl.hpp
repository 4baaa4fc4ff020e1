// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The GPU tracer's Hamilton's equations, its Dormand-Prince step and its step control, generated
// from the C++ the CPU runs: lc::hamiltonEquations, Boost.Odeint's runge_kutta_dopri5 and the
// error checker and step adjuster of odeint's controlled stepper, each instantiated with
// codegen::Expr, so neither a formula nor the Butcher tableau is typed a second time in GLSL.
#include "core/codegen/symbolic_metric.hpp"

namespace lc::codegen {

// void lcFlow(vec4 x, vec4 p, out vec4 dxdl, out vec4 dpdl): calls lcMetric (metricGlsl) and
// evaluates lc::hamiltonEquations on its g and dg (g symmetric: one name per pair of entries).
GeneratedGlsl flowGlsl();

// float lcDopri5Step(vec4 x, vec4 p, vec4 k1x, vec4 k1p, float h,
//                    out vec4 xn, out vec4 pn, out vec4 k7x, out vec4 k7p)
// One step of odeint's runge_kutta_dopri5::do_step (first same as last: k1 given, k7 returned)
// recorded stage by stage: each stage's argument is printed, then `lcFlow` is called on it.
// Returns the step's error norm, lcStepErrorNorm (stepControlGlsl) at the uniform lcTolerance,
// <= 1 for an accepted step.
GeneratedGlsl dopri5StepGlsl();

// The step control of odeint's controlled_runge_kutta for dopri5 (what make_dense_output and
// make_controlled build on the CPU), three functions:
//   float lcStepErrorNorm(vec4 x, vec4 p, vec4 dxdl, vec4 dpdl, vec4 ex, vec4 ep, float h, float tolerance)
//     default_error_checker::error with eps_abs = eps_rel = tolerance: max over the 8 components
//     of |e| / (tolerance (1 + |y| + |h| |dy/dl|)), y the state before the step, dy/dl its
//     derivative, e the step's error estimate;
//   float lcDecreaseStep(float h, float err)   default_step_adjuster::decrease_step (err > 1);
//   float lcIncreaseStep(float h, float err)   lc::increasedStep (odeint's increase_step),
// with dopri5's error and stepper orders.
GeneratedGlsl stepControlGlsl();

// float lcConstraintDrift(vec4 p, vec4 v, float launchScale): lc::constraintDrift, the null
// condition's drift relative to the size of its terms, as the CPU tracer stops on it.
GeneratedGlsl constraintDriftGlsl();

}  // namespace lc::codegen
