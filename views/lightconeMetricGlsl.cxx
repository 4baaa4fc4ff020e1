#include "lightconeMetricGlsl.h"

#include "lightcone_glsl_tanh_finite.h"

#include "core/codegen/symbolic_metric.hpp"

#include <stdexcept>

namespace lc::views {

std::string metricShaderFunctions(const Spacetime& spacetime) {
    const auto symbolic = spacetime.symbolic();
    if (!symbolic)
        throw std::invalid_argument("the GPU geodesic renderer draws metrics written as code (core/metrics); metric '" +
                                    spacetime.name() + "' is not (use the numeric renderer)");
    return lightcone_glsl_tanh_finite + codegen::metricGlsl(*symbolic).source;
}

}  // namespace lc::views
