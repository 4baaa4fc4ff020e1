// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The GLSL of a spacetime for the GPU tracer, generated from C++ (core/codegen): lcMetric and
// lcBoundary from the metric's code, lcFlow from lc::hamiltonEquations, lcDopri5Step from
// Boost.Odeint's dopri5 and the step control (lcStepErrorNorm, lcDecreaseStep, lcIncreaseStep)
// from odeint's controlled stepper, with the support function they call (glsl/tanh_finite).
#include "core/spacetime/spacetime.hpp"

#include <string>

namespace lc::views {

// lcMetric and lcBoundary. Throws std::invalid_argument naming the metric if it is not written
// as code.
std::string metricShaderFunctions(const Spacetime& spacetime);
// metricShaderFunctions, then lcFlow, the step control and lcDopri5Step: everything lcTrace
// (glsl/geodesic_trace) calls. The stepper reads the uniform lcTolerance.
std::string tracerShaderFunctions(const Spacetime& spacetime);

}  // namespace lc::views
