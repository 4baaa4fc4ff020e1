// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The hard cases the tracer's tolerance must hold on (issue: "the tolerance means what it
// says"), each a ray with an independent reference: warp-drive walls from soft to sharp, slow and
// superluminal (a separable equation), a photon-sphere grazer and a ray from 10^10 M
// (Schwarzschild's exact deflection integral), a near-extremal Kerr ray turning just outside the
// horizon (Kerr's equatorial integral), a Goedel ray over ten windings (the closed form).
// tests/core/test_tolerance_convergence.cpp asserts them; bench_work_precision times them.
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/spacetime/integrator.hpp"
#include "core/spacetime/scattering.hpp"
#include "tests/common/geodesic_oracles.hpp"
#include "tests/common/godel_null_oracle.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace lc::test {

// What the tracer answered: where the ray ended and how far it turned, if it got there.
struct HardRayAnswer {
    bool reached = false;
    Vec4 end = Vec4::Zero();
    double deflection = 0;
};

constexpr double kNoAnswer = std::numeric_limits<double>::infinity();

struct HardRay {
    std::string name;
    // Traces the ray with these options (the stepper and tolerance set by the caller): the part
    // bench_work_precision times.
    std::function<HardRayAnswer(const TraceOptions&)> trace;
    // The answer's error relative to the independent reference; infinity when it did not arrive.
    std::function<double(const HardRayAnswer&)> error;
    double relativeError(const TraceOptions& o) const { return error(trace(o)); }
};

// Asymptotically flat rays: the total deflection of a ray from `distance` with impact parameter b
// (impactParameterRay: b > 0 turns against a Kerr hole's spin), against the exact one.
inline HardRay deflectionRay(std::string name, KerrNewman hole, double b, double distance, double exact) {
    return {std::move(name),
            [hole, b, distance](const TraceOptions& o) {
                const DeflectionResult d = measureDeflection(hole, impactParameterRay(hole, b, distance), o);
                return HardRayAnswer{d.trace.reason == StopReason::Escaped, d.trace.end.x, d.deflection};
            },
            [exact](const HardRayAnswer& a) { return a.reached ? std::abs(a.deflection - exact) / exact : kNoAnswer; }};
}

inline HardRay warpWall(double v, double sigma) {
    return {"warp wall v=" + std::to_string(v).substr(0, 3) + " sigma=" + std::to_string(int(sigma)),
            [v, sigma](const TraceOptions& opt) {
                const Alcubierre st(v, 1, sigma);
                // From the bubble's centre against its motion: k = (1, v - 1, 0, 0) is null there (f = 1).
                PhasePoint start;
                start.x = Vec4::Zero();
                start.p = st.metric(start.x) * Vec4(1, v - 1, 0, 0);
                TraceOptions o = opt;
                o.maxAffine = 3;  // well past the wall, unless it escapes first (flat beyond 20 / sigma)
                const TraceResult r = traceGeodesic(st, start, o);
                return HardRayAnswer{r.reason == StopReason::MaxAffine || r.reason == StopReason::Escaped, r.end.x, 0};
            },
            [v, sigma](const HardRayAnswer& a) {
                if (!a.reached) return kNoAnswer;
                const double t = a.end(0), xi = a.end(1) - v * t;
                return std::abs(t - alcubierreAxisTime(v, 1, sigma, xi)) / t;
            }};
}

inline std::vector<HardRay> hardRays() {
    std::vector<HardRay> rays;
    for (double v : {0.5, 5.0})
        for (double sigma : {8.0, 35.0, 200.0}) rays.push_back(warpWall(v, sigma));
    const double grazer = 3 * std::sqrt(3.0) * (1 + 1e-3);
    rays.push_back(deflectionRay("Schwarzschild photon-sphere grazer b=3sqrt3(1+1e-3)", KerrNewman(1, 0, 0), grazer,
                                 1e6, kerrEquatorialDeflection(0, grazer).alpha));
    rays.push_back(deflectionRay("Schwarzschild b=10 from 1e10 M", KerrNewman(1, 0, 0), 10, 1e10,
                                 kerrEquatorialDeflection(0, 10).alpha));
    const double a = 0.998, L = kerrEquatorialAngularMomentum(a, 1.2, +1);
    rays.push_back(deflectionRay("Kerr a=0.998 prograde, turning at r=1.2 (horizon 1.063)", KerrNewman(1, a, 0), -L,
                                 1e6, kerrEquatorialDeflection(a, L).alpha));
    constexpr double kPsi = 1.2, kPhi0 = 0.3;
    const double w = std::sqrt(1 + std::cos(kPsi) * std::cos(kPsi)) / 2;  // a = 1
    rays.push_back({"Goedel psi=1.2 over ten windings",
                    [w](const TraceOptions& opt) {
                        const GodelCartesian g(1);
                        TraceOptions o = opt;
                        o.maxAffine = 10 * kPi / w;  // r returns to the axis every pi / w
                        const TraceResult r = traceGeodesic(g, pastRay(g, kPsi, kPhi0), o);
                        return HardRayAnswer{r.reason == StopReason::MaxAffine, r.end.x, 0};
                    },
                    [w](const HardRayAnswer& ans) {
                        if (!ans.reached) return kNoAnswer;
                        const Vec4 exact = closedFormNull(1, kPsi, kPhi0, 10 * kPi / w);
                        return (ans.end - exact).norm() / exact.norm();
                    }});
    return rays;
}

// The options every hard ray starts from: the stepper, and tolerance as both absolute and
// relative error per step.
inline TraceOptions hardRayOptions(StepperKind stepper, double tolerance) {
    TraceOptions o;
    o.stepper = stepper;
    o.absTol = o.relTol = tolerance;
    o.initialStep = 1e-2;
    return o;
}

}  // namespace lc::test
