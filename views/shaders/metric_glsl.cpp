// SPDX-License-Identifier: BSD-3-Clause
#include "metric_glsl.hpp"

#include "lightcone_glsl_tanh_finite.h"

#include "core/codegen/symbolic_metric.hpp"
#include "core_formula_glsl.hpp"
#include "core/codegen/tracer_glsl.hpp"

#include <stdexcept>

namespace lc::views {

std::string metricShaderFunctions(const Spacetime& spacetime) {
    const auto symbolic = spacetime.symbolic();
    if (!symbolic)
        throw std::invalid_argument("the GPU geodesic renderer draws metrics written as code (core/metrics); metric '" +
                                    spacetime.name() + "' is not (use the numeric renderer)");
    const std::string metric = codegen::metricGlsl(*symbolic).source;
    // The Bessel functions only where the metric calls them (Einstein-Rosen waves).
    const bool bessel = metric.find("lcBesselJ") != std::string::npos;
    return lightcone_glsl_tanh_finite + (bessel ? besselGlsl() : std::string()) + metric;
}

std::string tracerShaderFunctions(const Spacetime& spacetime) {
    // Generated once: none depends on the metric (lcFlow calls lcMetric).
    static const std::string flowAndStep = codegen::flowGlsl().source + codegen::stepControlGlsl().source +
                                           codegen::constraintDriftGlsl().source + codegen::dopri5StepGlsl().source;
    return metricShaderFunctions(spacetime) + flowAndStep;
}

}  // namespace lc::views
