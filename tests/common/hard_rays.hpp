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

struct HardRay {
    std::string name;
    // Traces the ray with these options (the stepper and tolerance set by the caller) and returns
    // its relative error against the reference; infinity when the ray did not reach its end.
    std::function<double(const TraceOptions&)> relativeError;
};

constexpr double kNoAnswer = std::numeric_limits<double>::infinity();

// Asymptotically flat rays: the relative error of the total deflection of a ray from `distance`
// with impact parameter b (impactParameterRay: b > 0 turns against a Kerr hole's spin).
inline double deflectionError(const Spacetime& st, double b, double distance, double exact, const TraceOptions& o) {
    const DeflectionResult d = measureDeflection(st, impactParameterRay(st, b, distance), o);
    if (d.trace.reason != StopReason::Escaped) return kNoAnswer;
    return std::abs(d.deflection - exact) / exact;
}

inline HardRay warpWall(double v, double sigma) {
    return {"warp wall v=" + std::to_string(v).substr(0, 3) + " sigma=" + std::to_string(int(sigma)),
            [v, sigma](const TraceOptions& opt) {
                const double R = 1;
                const Alcubierre st(v, R, sigma);
                // From the bubble's centre against its motion: k = (1, v - 1, 0, 0) is null there (f = 1).
                PhasePoint start;
                start.x = Vec4::Zero();
                start.p = st.metric(start.x) * Vec4(1, v - 1, 0, 0);
                TraceOptions o = opt;
                o.maxAffine = 3;  // well past the wall, unless it escapes first (flat beyond 20 / sigma)
                const TraceResult r = traceGeodesic(st, start, o);
                if (r.reason != StopReason::MaxAffine && r.reason != StopReason::Escaped) return kNoAnswer;
                const double t = r.end.x(0), xi = r.end.x(1) - v * t;
                return std::abs(t - alcubierreAxisTime(v, R, sigma, xi)) / t;
            }};
}

inline std::vector<HardRay> hardRays() {
    std::vector<HardRay> rays;
    for (double v : {0.5, 5.0})
        for (double sigma : {8.0, 35.0, 200.0}) rays.push_back(warpWall(v, sigma));
    rays.push_back({"Schwarzschild photon-sphere grazer b=3sqrt3(1+1e-3)", [](const TraceOptions& o) {
                        const double b = 3 * std::sqrt(3.0) * (1 + 1e-3);
                        return deflectionError(KerrNewman(1, 0, 0), b, 1e6, kerrEquatorialDeflection(0, b).alpha, o);
                    }});
    rays.push_back({"Schwarzschild b=10 from 1e10 M", [](const TraceOptions& o) {
                        return deflectionError(KerrNewman(1, 0, 0), 10, 1e10, kerrEquatorialDeflection(0, 10).alpha, o);
                    }});
    rays.push_back({"Kerr a=0.998 prograde, turning at r=1.2 (horizon 1.063)", [](const TraceOptions& o) {
                        const double a = 0.998, L = kerrEquatorialAngularMomentum(a, 1.2, +1);
                        return deflectionError(KerrNewman(1, a, 0), -L, 1e6, kerrEquatorialDeflection(a, L).alpha, o);
                    }});
    rays.push_back({"Goedel psi=1.2 over ten windings", [](const TraceOptions& opt) {
                        const double a = 1, psi = 1.2, w = std::sqrt(1 + std::cos(psi) * std::cos(psi)) / (2 * a);
                        const GodelCartesian g(a);
                        TraceOptions o = opt;
                        o.maxAffine = 10 * kPi / w;  // r returns to the axis every pi / w
                        const TraceResult r = traceGeodesic(g, pastRay(g, psi, 0.3), o);
                        if (r.reason != StopReason::MaxAffine) return kNoAnswer;
                        const Vec4 exact = closedFormNull(a, psi, 0.3, o.maxAffine);
                        return (r.end.x - exact).norm() / exact.norm();
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
