#ifndef lightconeMetricGlsl_h
#define lightconeMetricGlsl_h
// The GLSL of a spacetime for the GPU tracer: lcMetric and lcBoundary generated from the
// metric's C++ code (core/codegen), with the support functions they call (glsl/tanh_finite).
#include "core/spacetime/spacetime.hpp"

#include <string>

namespace lc::views {

// Throws std::invalid_argument naming the metric if it is not written as code.
std::string metricShaderFunctions(const Spacetime& spacetime);

}  // namespace lc::views

#endif
