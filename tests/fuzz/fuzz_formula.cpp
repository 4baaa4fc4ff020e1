// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the bytes are a metric file (docs/METRICS.md), read as
// `lightcone metric check` reads it (lc::io::parseFormulaMetric); a metric that loads is then
// evaluated (g, its exact derivatives, Hamilton's equations, the checks) at a few events and
// its GLSL generated, as a render would. lc::io::InputError (a std::runtime_error naming the
// field and column) and std::invalid_argument (the GLSL emitter's constant outside float's
// range) are how bad input is refused; a crash, a sanitizer report, a hang or any other
// exception is a finding.
#include "core/codegen/symbolic_metric.hpp"
#include "core/spacetime/metric_check.hpp"
#include "readers/io/metric_file.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const auto metric = lc::io::parseFormulaMetric(text, "fuzz.json", {});
        for (const lc::Vec4& x : {lc::Vec4(0, 10, 1, 2), lc::Vec4(0, 0, 0, 0), lc::Vec4(1e300, -1e-300, 3, 1e10)}) {
            (void)metric->flow(x, lc::Vec4(1, 0.5, -0.25, 0.125));
            (void)metric->inverseMetric(x);
            (void)metric->boundary(x);
            (void)lc::metricProblemAt(*metric, x);
            (void)metric->farField(x);
        }
        (void)lc::codegen::metricGlsl(*metric->symbolic());
    } catch (const std::runtime_error&) {
        // refused with a message naming file, line, field and column: the expected outcome
    } catch (const std::invalid_argument&) {
        // a constant the GPU cannot hold (float range): refused by the GLSL emitter
    }
    return 0;
}
