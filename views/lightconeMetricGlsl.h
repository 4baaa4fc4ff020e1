#ifndef lightconeMetricGlsl_h
#define lightconeMetricGlsl_h
// The GLSL of a spacetime for the GPU tracer, generated from C++ (core/codegen): lcMetric and
// lcBoundary from the metric's code, lcFlow from lc::hamiltonEquations and lcDopri5Step from
// Boost.Odeint's dopri5, with the support functions they call (glsl/tanh_finite,
// glsl/step_error_norm).
#include "core/spacetime/spacetime.hpp"

#include <string>

namespace lc::views {

// lcMetric and lcBoundary. Throws std::invalid_argument naming the metric if it is not written
// as code.
std::string metricShaderFunctions(const Spacetime& spacetime);
// metricShaderFunctions, then lcFlow and lcDopri5Step: everything lcTrace (glsl/geodesic_trace)
// calls. The stepper reads the uniform lcTolerance.
std::string tracerShaderFunctions(const Spacetime& spacetime);

}  // namespace lc::views

#endif
