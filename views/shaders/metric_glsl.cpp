// SPDX-License-Identifier: BSD-3-Clause
#include "metric_glsl.hpp"

#include "lightcone_glsl_tanh_finite.h"

#include "core/codegen/symbolic_metric.hpp"
#include "core/codegen/tracer_glsl.hpp"

#include <stdexcept>

namespace lc::views {

std::string metricShaderFunctions(const Spacetime& spacetime) {
    const auto symbolic = spacetime.symbolic();
    if (!symbolic)
        throw std::invalid_argument("the GPU geodesic renderer draws metrics written as code (core/metrics); metric '" +
                                    spacetime.name() + "' is not (use the numeric renderer)");
    return lightcone_glsl_tanh_finite + codegen::metricGlsl(*symbolic).source;
}

std::string tracerShaderFunctions(const Spacetime& spacetime) {
    // Generated once: none depends on the metric (lcFlow calls lcMetric).
    static const std::string flowAndStep = codegen::flowGlsl().source + codegen::stepControlGlsl().source +
                                           codegen::constraintDriftGlsl().source + codegen::dopri5StepGlsl().source;
    return metricShaderFunctions(spacetime) + flowAndStep;
}

}  // namespace lc::views
