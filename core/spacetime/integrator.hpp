// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Hamiltonian null/timelike geodesic tracing with Boost.Odeint, accuracy chosen by the caller
// and reported back (steps, drift of H, why the ray stopped).
#include "core/spacetime/spacetime.hpp"

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace lc {

enum class StepperKind { RK4, CashKarp54, Dopri5, Dopri87, BulirschStoer };

// "rk4", "cash_karp54", "dopri5", "dopri87" (runge_kutta_prince_dormand87.hpp), "bulirsch_stoer";
// throws with the list on error.
StepperKind parseStepper(const std::string& name);
std::string stepperName(StepperKind kind);
const std::vector<std::string>& stepperNames();

enum class StopReason {
    Escaped,           // moves out of an asymptotically flat spacetime, its direction settled
    Horizon,           // crossed a horizon (black: nothing comes back)
    MaxAffine,         // reached the affine parameter limit
    MaxSteps,          // reached the step limit
    ConstraintBlowUp,  // |H| grew beyond TraceOptions::constraintTolerance
    Singularity,       // chart or curvature singularity, or a non-finite state
    StepUnderflow,     // the adaptive step fell below TraceOptions::minStep
    Hit,               // the segment visitor asked to stop (e.g. an object was hit)
    OtherEnd           // reached a two-ended spacetime's other asymptotic end (a wormhole's far side)
};
std::string stopReasonName(StopReason r);
// Every reason's name by code (PixelRecord::stopReason, Python's lightcone.StopReason).
std::vector<std::string> stopReasonNames();

struct TraceOptions {
    StepperKind stepper = StepperKind::Dopri5;
    double absTol = 1e-10;
    double relTol = 1e-10;
    double initialStep = 1e-2;  // also the fixed step of rk4
    double minStep = 1e-14;
    double maxStep = 0;  // 0: unlimited
    // Balls in chart coordinates a ray must not step across unseen (a scene's static spheres,
    // core/render/numeric.cpp): a step's coordinate chord is held to half the larger of the
    // distance to a ball's surface and its radius, so a grazing ray cannot cross one within a
    // step, while far from every ball steps stay long.
    struct Ball {
        Vec3 centre;
        double radius;
    };
    std::vector<Ball> balls;
    // Asymptotically flat metrics (Spacetime::farField): a step's chord may come no closer to
    // the field's non-analytic core than 1/stepPerDistance of its own length, so the Taylor
    // series behind every Runge-Kutta error estimate converges along the step and a long step
    // cannot jump over the strong field unseen; where even the whole bending over a step is
    // below the tolerance, a longer step is allowed (the far field costs O(log distance)).
    // 0: the stepper's own, 1 for dopri5 and 0.5 for the others (their error estimates then
    // hold; docs/PERFORMANCE.md). Infinite disables the rule.
    double stepPerDistance = 0;
    // Infinite: no limit. Rays of an asymptotically flat metric end anyway (escape, horizon,
    // maxSteps); other metrics need a finite one (the scene reader sets Goedel's from its
    // windings).
    double maxAffine = std::numeric_limits<double>::infinity();
    std::size_t maxSteps = 1000000;
    // Asymptotically flat metrics: a ray escapes when it moves away from the field's centre,
    // beyond escapeRadius from the origin (outside every object) and beyond the metric's
    // capture radius, and the bending still ahead of it (weak-field bound) is below
    // escapeAngle (radians; 0: absTol + relTol).
    double escapeRadius = 0;
    double escapeAngle = 0;
    // Rays carrying a bundle (the image's magnification, core/curvature/ray_bundle): the bending
    // ahead changes across the bundle by about 4M lever / d^2 per radian of image angle (lever:
    // the observer's distance from the field's centre, the ray's impact parameter per radian);
    // a ray escapes only once that, too, is below escapeAngle, and the far-field steps that
    // skip the error estimate (stepPerDistance) keep the spread's bending below the tolerance too.
    // 0: directions only.
    double escapeLever = 0;
    double constraintTolerance = 1e-3;  // |H| above this stops the ray
    // After every accepted step where light can orbit, restore H, the momenta of the metric's
    // declared symmetries (p . xi for d/dt and rotations) and a spinning Kerr-Newman hole's
    // Carter constant to their starting values by the least change of p
    // (core/spacetime/constants_of_motion): rays near unstable photon orbits then keep their
    // orbit, and their deflection its accuracy (docs/PHYSICS.md section 7b).
    bool holdConstants = true;
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
