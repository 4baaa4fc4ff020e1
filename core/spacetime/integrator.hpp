#pragma once
// Hamiltonian null/timelike geodesic tracing with Boost.Odeint, accuracy chosen by the caller
// and reported back (steps, drift of H, why the ray stopped).
#include "core/spacetime/spacetime.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lc {

enum class StepperKind { RK4, CashKarp54, Dopri5, Fehlberg78, BulirschStoer };

// "rk4", "cash_karp54", "dopri5", "fehlberg78", "bulirsch_stoer"; throws with the list on error.
StepperKind parseStepper(const std::string& name);
std::string stepperName(StepperKind kind);
const std::vector<std::string>& stepperNames();

enum class StopReason {
    Escaped,           // left the strong-field region of an asymptotically flat spacetime
    Horizon,           // crossed a horizon (black: nothing comes back)
    MaxAffine,         // reached the affine parameter limit
    MaxSteps,          // reached the step limit
    ConstraintBlowUp,  // |H| grew beyond TraceOptions::constraintTolerance
    Singularity,       // chart or curvature singularity, or a non-finite state
    StepUnderflow,     // the adaptive step fell below TraceOptions::minStep
    Hit                // the segment visitor asked to stop (e.g. an object was hit)
};
std::string stopReasonName(StopReason r);

struct TraceOptions {
    StepperKind stepper = StepperKind::Dopri5;
    double absTol = 1e-10;
    double relTol = 1e-10;
    double initialStep = 1e-2;  // also the fixed step of rk4
    double minStep = 1e-14;
    double maxStep = 0;  // 0: unlimited
    // Asymptotically flat metrics: a step may not exceed this fraction of the distance from the
    // spatial origin, so a long step from far away cannot jump over the strong-field region
    // while its error estimate, sampled only far away, stays small. 0 disables.
    double stepPerRadius = 0.1;
    double maxAffine = 1e6;
    std::size_t maxSteps = 1000000;
    double escapeRadius = 1e3;          // asymptotically flat metrics only
    double constraintTolerance = 1e-3;  // |H| above this stops the ray
};

// One accepted step [l0, l1]; at(l) interpolates the state inside it (odeint's dense output
// for dopri5 and bulirsch_stoer, cubic Hermite from the end derivatives otherwise).
struct Segment {
    double l0 = 0, l1 = 0;
    PhasePoint s0, s1;
    std::function<PhasePoint(double)> at;
};

// Called after every accepted step; return true to stop the ray with StopReason::Hit.
using SegmentVisitor = std::function<bool(const Segment&)>;

struct TraceResult {
    PhasePoint end;
    double affine = 0;
    StopReason reason = StopReason::MaxSteps;
    std::size_t steps = 0;           // accepted steps
    std::size_t rejected = 0;        // rejected trial steps (adaptive steppers)
    double maxHamiltonianDrift = 0;  // max |H| along the ray (0 exactly for a null ray)
};

TraceResult traceGeodesic(const Spacetime& st, const PhasePoint& start, const TraceOptions& opt,
                          const SegmentVisitor& visitor = {});

// Convenience: every accepted state, for plotting polylines.
std::vector<std::pair<double, PhasePoint>> sampleGeodesic(const Spacetime& st, const PhasePoint& start,
                                                          const TraceOptions& opt, TraceResult* result = nullptr);

}  // namespace lc
