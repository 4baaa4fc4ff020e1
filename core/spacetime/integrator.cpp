// SPDX-License-Identifier: BSD-3-Clause
#include "core/spacetime/integrator.hpp"

#include "core/spacetime/constants_of_motion.hpp"
#include "core/spacetime/runge_kutta_prince_dormand87.hpp"

#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <stdexcept>

namespace lc {
namespace odeint = boost::numeric::odeint;
namespace {

using State = std::array<double, 8>;  // x^0..x^3, p_0..p_3

PhasePoint toPhase(const State& s) {
    PhasePoint q;
    for (int i = 0; i < 4; ++i) {
        q.x(i) = s[i];
        q.p(i) = s[4 + i];
    }
    return q;
}
State toState(const PhasePoint& q) {
    State s;
    for (int i = 0; i < 4; ++i) {
        s[i] = q.x(i);
        s[4 + i] = q.p(i);
    }
    return s;
}

// Hamilton's equations as an odeint system.
struct HamiltonSystem {
    const Spacetime* st;
    void operator()(const State& s, State& ds, double /*l*/) const {
        const PhasePoint q = toPhase(s);
        const HamiltonianFlow f = st->flow(q.x, q.p);
        for (int i = 0; i < 4; ++i) {
            ds[i] = f.dxdl(i);
            ds[4 + i] = f.dpdl(i);
        }
    }
};

bool finite(const State& s) {
    for (double v : s)
        if (!std::isfinite(v)) return false;
    return true;
}

// Cubic Hermite interpolation of the state between two accepted steps, from the end values
// and end derivatives: 4th-order accurate, enough to locate crossings inside one step.
State hermite(const State& a, const State& da, const State& b, const State& db, double l0, double l1, double l) {
    const double h = l1 - l0, s = (l - l0) / h;
    const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
    const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
    State r;
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = h00 * a[i] + h10 * h * da[i] + h01 * b[i] + h11 * h * db[i];
    return r;
}

// The tolerance as an angle: what a unit momentum may turn by unnoticed (momenta of rays are
// of order one; the renderer rescales them so).
double angleTolerance(const TraceOptions& opt) { return opt.absTol + opt.relTol; }

double stepLimit(const Spacetime& st, const TraceOptions& opt, const PhasePoint& q, const Vec4& v);

// Shared bookkeeping of one ray: stop tests after each accepted step, drift, visitor.
class RayMonitor {
public:
    RayMonitor(const Spacetime& st, const TraceOptions& opt, const SegmentVisitor& visitor, TraceResult& res)
        : st_(st), opt_(opt), visitor_(visitor), res_(res), constants_(st, res.end) {
        // |H| scales with the square of the momentum: an observer at gamma = 1000 launches
        // momenta ~ 2000, so the blow-up test is relative to the launch momentum's size.
        hScale_ = std::max(1.0, res_.end.p.squaredNorm());
    }

    // Returns true if the ray must stop after the step [l0, l1].
    bool accept(double l0, const State& s0, double l1, const State& s1, std::function<PhasePoint(double)> at) {
        ++res_.steps;
        if (!finite(s1)) return stop(StopReason::Singularity);  // the end stays the last finite state
        res_.affine = l1;
        res_.end = toPhase(s1);
        velocity_ = st_.inverseMetric(res_.end.x) * res_.end.p;
        const Vec4& v = velocity_;
        const double H = 0.5 * std::abs(res_.end.p.dot(v));
        if (!std::isfinite(H)) return stop(StopReason::Singularity);
        res_.maxHamiltonianDrift = std::max(res_.maxHamiltonianDrift, H);
        if (visitor_) {
            Segment seg{l0, l1, toPhase(s0), res_.end, std::move(at)};
            if (visitor_(seg)) return stop(StopReason::Hit);
        }
        switch (st_.boundary(res_.end.x)) {
            case Boundary::Horizon: return stop(StopReason::Horizon);
            case Boundary::Singularity: return stop(StopReason::Singularity);
            case Boundary::OtherEnd: return stop(StopReason::OtherEnd);
            case Boundary::None: break;
        }
        if (constraintDrift<double>(res_.end.p, v, hScale_) > opt_.constraintTolerance)
            return stop(StopReason::ConstraintBlowUp);
        if (st_.asymptoticallyFlat() && escaping(res_.end.x, v)) return stop(StopReason::Escaped);
        if (l1 >= opt_.maxAffine * (1 - 1e-15)) return stop(StopReason::MaxAffine);
        if (res_.steps >= opt_.maxSteps) return stop(StopReason::MaxSteps);
        return false;
    }
    bool stop(StopReason r) {
        res_.reason = r;
        return true;
    }
    // TraceOptions::holdConstants: restores the constants of motion in the state just accepted
    // (whose velocity the stop tests computed), from which the next step starts; whether it changed.
    bool restoreConstants(State& s) const {
        if (!opt_.holdConstants) return false;
        PhasePoint q = toPhase(s);
        if (!constants_.restore(q, velocity_)) return false;
        s = toState(q);
        return true;
    }
    // The largest next step from the last accepted state (stepLimit), from the velocity the
    // stop tests computed.
    double nextStepLimit() const { return stepLimit(st_, opt_, res_.end, velocity_); }

private:
    // v = dx/dl. Beyond its capture radius an outgoing ray never returns; the bending still
    // ahead at distance d with impact parameter b is, in the weak field, 2M/b (1 - sqrt(1 -
    // b^2/d^2)) <= 2 M b / d^2; the test takes twice that plus the spin's M a / d^2 term.
    bool escaping(const Vec4& x, const Vec4& v) const {
        if (x.tail<3>().dot(v.tail<3>()) <= 0 || x.tail<3>().squaredNorm() < opt_.escapeRadius * opt_.escapeRadius)
            return false;
        const FarField ff = st_.farField(x);
        const Vec3 sep = x.tail<3>() - ff.centre, w = v.tail<3>() - ff.velocity * v(0);
        const double d = sep.norm();
        if (sep.dot(w) <= 0 || d < ff.captureRadius) return false;
        if (ff.mass <= 0) return true;
        const double b = sep.cross(w).norm() / w.norm();
        const double ahead = 4 * ff.mass * (std::max(b, opt_.escapeLever) + ff.spin) / (d * d);
        return ahead <= (opt_.escapeAngle > 0 ? opt_.escapeAngle : angleTolerance(opt_));
    }
    const Spacetime& st_;
    const TraceOptions& opt_;
    const SegmentVisitor& visitor_;
    TraceResult& res_;
    double hScale_ = 1;
    Vec4 velocity_ = Vec4::Zero();  // dx/dl at res_.end
    ConstantsOfMotion constants_;
};

// Longest chord L (relative to the field's centre) from distance rho outside the core whose
// every point stays at least L / kappa from it, given that its closest approach is at least
// max(rho - L, beta): L = kappa max(rho - L, beta).
double chordWithinConvergence(double rho, double beta, double kappa) {
    return std::max(kappa * rho / (1 + kappa), kappa * beta);
}

// Longest chord over which the whole weak-field bending, at most 2 M L / dmin^2 with dmin >=
// max(rho - L, beta), stays below `angle`: L = c max(rho - L, beta)^2 with c = angle / 2M.
double chordBelowBending(double rho, double beta, double mass, double angle) {
    const double c = angle / (2 * mass);
    const double approaching = 2 * c * rho * rho / (2 * c * rho + 1 + std::sqrt(4 * c * rho + 1));
    return std::max(approaching, c * beta * beta);
}

// TraceOptions::stepPerDistance, or the stepper's own where it is 0.
// dopri5's error estimate holds to chords of half the distance (1; measured on the deflection
// table and the hard rays, docs/PERFORMANCE.md); dopri87's degrades there (0.5).
double farFieldRatio(const TraceOptions& opt) {
    if (opt.stepPerDistance > 0) return opt.stepPerDistance;
    return opt.stepper == StepperKind::Dopri5 ? 1.0 : 0.5;
}

// Largest step allowed at the state q with velocity v = dx/dl = g^-1 p (0: no limit):
// TraceOptions::maxStep and, for asymptotically flat metrics, the far-field rule of
// TraceOptions::stepPerDistance.
double stepLimit(const Spacetime& st, const TraceOptions& opt, const PhasePoint& q, const Vec4& v) {
    const Vec4& x = q.x;
    double limit = opt.maxStep > 0 ? opt.maxStep : 0;
    auto tighten = [&limit](double l) { limit = limit > 0 ? std::min(limit, l) : l; };
    if (!opt.balls.empty()) {
        const double speed = std::max(v.tail<3>().norm(), 1e-300);
        for (const auto& b : opt.balls)
            tighten(0.5 * std::max((x.tail<3>() - b.centre).norm() - b.radius, b.radius) / speed);
    }
    const double kappa = farFieldRatio(opt);
    if (std::isfinite(kappa) && st.asymptoticallyFlat()) {
        const FarField ff = st.farField(x);
        if (ff.mass <= 0 && ff.size <= 0) return limit;  // flat everywhere: nothing to jump over
        const Vec3 sep = x.tail<3>() - ff.centre, w = v.tail<3>() - ff.velocity * v(0);
        // The separation changes at most this fast per unit affine parameter; a slow body's
        // step is held to the chord in coordinate time too.
        const double speed = std::max(v.tail<3>().norm() + ff.velocity.norm() * std::abs(v(0)), std::abs(v(0)));
        const double d = sep.norm(), rho = d - ff.size;
        if (rho <= 0) {  // inside the core (a warp bubble): the step control alone, within 0.1 of its size
            // In coordinate time too, except for light in a core that does not change with t: on a
            // static wormhole's far side dt/dl stays finite while the chart shrinks (measured: a ray
            // to the Ellis wormhole's far sky took 1066 steps, 164 now; to the drainhole's, 35759
            // and 194). A slow body's world line keeps the time chord (its proper time).
            // g(v, v) = p.v: no metric evaluation for it.
            const bool light = std::abs(q.p.dot(v)) < 1e-6 * v(0) * v(0);
            const bool staticLight = light && ff.velocity.norm() == 0 && st.declaredStationary();
            const double coreSpeed = staticLight ? v.tail<3>().norm() : speed;
            tighten(0.1 * ff.size / std::max(coreSpeed, 1e-300));
            return limit;
        }
        const double wn = w.norm();
        // Closest approach of the straight relative chord, if ahead; otherwise the distance only grows.
        double beta = rho;
        if (wn > 0 && sep.dot(w) < 0) beta = sep.cross(w).norm() / wn - ff.size;
        // At least kappa / 100 of the core's size: else steps shrink like the distance to the core
        // and a ray crossing into it never arrives (every ray towards an Alcubierre bubble seen from
        // outside, or into a wormhole's throat, ended by step underflow).
        double chord = std::max(chordWithinConvergence(rho, beta, kappa), 0.01 * kappa * ff.size);
        if (ff.mass > 0) {
            const double closest = std::max(beta, 0.0);
            double bending = chordBelowBending(rho, closest, ff.mass, angleTolerance(opt));
            // A bundle's spread (lever per radian, TraceOptions::escapeLever) bends by lever / dmin
            // times more: its chord keeps that below the tolerance too.
            const double dmin = std::max(closest, rho - bending);
            if (opt.escapeLever > dmin)
                bending = chordBelowBending(rho, closest, ff.mass, angleTolerance(opt) * dmin / opt.escapeLever);
            chord = std::max(chord, bending);
        }
        tighten(chord / std::max(speed, 1e-300));
    }
    return limit;
}

// How many times a step that lands where the metric is not finite is quartered before the ray
// stops as singular (4^-30: from any step down to below minStep).
constexpr int kMaxShrinks = 30;

// Hairer, Norsett and Wanner (Solving Ordinary Differential Equations I, section II.4): after a
// rejected try the next step does not grow beyond the one taken. Odeint lets it grow again at
// once, and where the error rises along the ray (the approach to a hole) most steps were then
// tried twice.
double notGrown(double proposed, double taken) {
    return std::copysign(std::min(std::abs(proposed), std::abs(taken)), proposed);
}

double clampStep(double dl, double limit) { return limit > 0 ? std::copysign(std::min(std::abs(dl), limit), dl) : dl; }

// The first trial step: TraceOptions::initialStep, or the far field's allowance where that is
// longer (a ray from 10^10 M would otherwise spend a dozen steps growing its step from 1).
double firstStep(const Spacetime& st, const TraceOptions& opt, const State& s) {
    const PhasePoint q = toPhase(s);
    const double limit = stepLimit(st, opt, q, st.inverseMetric(q.x) * q.p);
    if (st.asymptoticallyFlat() && limit > opt.initialStep) return limit;
    return clampStep(opt.initialStep, limit);
}

// Steppers with odeint's dense output (Bulirsch-Stoer; dopri5 has its own loop, runDopri5): the
// interpolant is the stepper's own.
template <class DenseStepper>
void runDense(DenseStepper stepper, const HamiltonSystem& sys, State s, const TraceOptions& opt, RayMonitor& mon,
              TraceResult& res) {
    stepper.initialize(s, 0.0, firstStep(*sys.st, opt, s));
    int shrinks = 0;
    for (;;) {
        auto span = stepper.do_step(sys);
        const State s0 = stepper.previous_state();
        State s1 = stepper.current_state();
        // A step into a region where the metric is not finite (past a horizon the step was too
        // long to see) is taken again shorter; a ray that keeps landing there stops as singular.
        if (!finite(s1) && finite(s0) && shrinks < kMaxShrinks) {
            ++shrinks;
            ++res.rejected;
            stepper.initialize(s0, span.first, 0.25 * (span.second - span.first));
            continue;
        }
        shrinks = 0;
        if (span.second > opt.maxAffine) {  // end exactly on the limit, from the dense output
            span.second = opt.maxAffine;
            stepper.calc_state(opt.maxAffine, s1);
        }
        auto at = [&stepper](double l) {
            State q;
            stepper.calc_state(l, q);
            return toPhase(q);
        };
        if (mon.accept(span.first, s0, span.second, s1, at)) return;
        if (std::abs(stepper.current_time_step()) < opt.minStep) {
            mon.stop(StopReason::StepUnderflow);
            return;
        }
        const double limit = mon.nextStepLimit();
        State next = stepper.current_state();
        const bool restored = mon.restoreConstants(next);
        if (restored || (limit > 0 && std::abs(stepper.current_time_step()) > limit))
            stepper.initialize(next, stepper.current_time(), clampStep(stepper.current_time_step(), limit));
    }
}

// Dormand-Prince 5(4) as Odeint's dense-output stepper runs it (the same controlled tries, the
// same interpolant), with the state and its derivative held here: a step shortened by the step
// limit or a state whose constants were restored would make Odeint's dense stepper evaluate the
// derivative at the start of the next step again (re-initialised), which is one flow of the seven
// a step costs; shortening the step leaves the state and so its derivative as they were.
void runDopri5(const HamiltonSystem& sys, State s, const TraceOptions& opt, RayMonitor& mon, TraceResult& res) {
    auto stepper = odeint::make_controlled(opt.absTol, opt.relTol, odeint::runge_kutta_dopri5<State>());
    constexpr int kMaxTries = 500;  // as Odeint's failed_step_checker
    State ds, s1, ds1;
    sys(s, ds, 0.0);
    double l = 0, dl = firstStep(*sys.st, opt, s);
    int shrinks = 0;
    for (;;) {
        double l1 = l;
        int tries = 0;
        while (stepper.try_step(sys, s, ds, l1, s1, ds1, dl) == odeint::fail) {
            ++res.rejected;
            if (++tries > kMaxTries) {
                mon.stop(StopReason::StepUnderflow);
                return;
            }
        }
        // A step into a region where the metric is not finite (past a horizon the step was too
        // long to see) is taken again shorter; a ray that keeps landing there stops as singular.
        if (!finite(s1) && finite(s) && shrinks < kMaxShrinks) {
            ++shrinks;
            ++res.rejected;
            dl = 0.25 * (l1 - l);
            continue;
        }
        shrinks = 0;
        // The interpolant spans the step as taken, also where its end is moved back to maxAffine.
        const double stepEnd = l1;
        auto interpolate = [&](double lq, State& q) {
            stepper.stepper().calc_state(lq, q, s, ds, l, s1, ds1, stepEnd);
        };
        if (l1 > opt.maxAffine) {  // end exactly on the limit, from the dense output
            interpolate(opt.maxAffine, s1);
            l1 = opt.maxAffine;
        }
        auto at = [&interpolate](double lq) {
            State q;
            interpolate(lq, q);
            return toPhase(q);
        };
        if (mon.accept(l, s, l1, s1, at)) return;
        if (std::abs(dl) < opt.minStep) {
            mon.stop(StopReason::StepUnderflow);
            return;
        }
        if (tries > 0) dl = notGrown(dl, l1 - l);
        dl = clampStep(dl, mon.nextStepLimit());
        if (mon.restoreConstants(s1)) sys(s1, ds1, l1);
        s = s1;
        ds = ds1;
        l = l1;
    }
}

// Controlled steppers without dense output (Cash-Karp, Fehlberg): retry until accepted, then
// interpolate with cubic Hermite.
template <class Controlled>
void runControlled(Controlled stepper, const HamiltonSystem& sys, State s, const TraceOptions& opt, RayMonitor& mon,
                   TraceResult& res) {
    double l = 0, dl = std::min(firstStep(*sys.st, opt, s), opt.maxAffine);
    State ds0, ds1;
    sys(s, ds0, l);
    for (;;) {
        const State s0 = s;
        const double l0 = l;
        int tries = 0;
        while (stepper.try_step(sys, s, ds0, l, dl) == odeint::fail ||
               (!finite(s) && tries < kMaxShrinks)) {  // as in runDense: a step into a non-finite metric
            ++res.rejected;
            if (!finite(s)) {
                s = s0;
                l = l0;
                dl *= 0.25;
            }
            if (std::abs(dl) < opt.minStep || ++tries > 200) {
                mon.stop(StopReason::StepUnderflow);
                return;
            }
        }
        sys(s, ds1, l);
        const State d0 = ds0, d1 = ds1;
        const double l1 = l;
        auto at = [s0, d0, s, d1, l0, l1](double lq) { return toPhase(hermite(s0, d0, s, d1, l0, l1, lq)); };
        if (mon.accept(l0, s0, l1, s, at)) return;
        if (tries > 0) dl = notGrown(dl, l1 - l0);
        dl = clampStep(dl, mon.nextStepLimit());
        if (l + dl > opt.maxAffine) dl = opt.maxAffine - l;  // end exactly on the limit
        if (mon.restoreConstants(s))
            sys(s, ds0, l);
        else
            ds0 = ds1;
    }
}

void runFixed(const HamiltonSystem& sys, State s, const TraceOptions& opt, RayMonitor& mon) {
    odeint::runge_kutta4<State> stepper;
    double l = 0;
    State ds0, ds1;
    for (;;) {
        const double dl = std::min(opt.initialStep, opt.maxAffine - l);  // end exactly on the limit
        const State s0 = s;
        sys(s0, ds0, l);
        stepper.do_step(sys, s, l, dl);
        sys(s, ds1, l + dl);
        const State d0 = ds0, d1 = ds1;
        const double l0 = l;
        l += dl;
        const double l1 = l;
        auto at = [s0, d0, s, d1, l0, l1](double lq) { return toPhase(hermite(s0, d0, s, d1, l0, l1, lq)); };
        if (mon.accept(l0, s0, l1, s, at)) return;
        mon.restoreConstants(s);
    }
}

}  // namespace

const std::vector<std::string>& stepperNames() {
    static const std::vector<std::string> names{"rk4", "cash_karp54", "dopri5", "dopri87", "bulirsch_stoer"};
    return names;
}

StepperKind parseStepper(const std::string& name) {
    const auto& n = stepperNames();
    for (std::size_t i = 0; i < n.size(); ++i)
        if (n[i] == name) return static_cast<StepperKind>(i);
    std::string list;
    for (const auto& s : n) list += (list.empty() ? "" : ", ") + s;
    if (name == "fehlberg78")
        throw std::invalid_argument(
            "stepper 'fehlberg78' was replaced by dopri87 (Prince and Dormand's 8(7) pair): "
            "Fehlberg's error estimate misses sharp features such as a warp drive's wall "
            "(docs/PERFORMANCE.md); expected one of: " +
            list);
    throw std::invalid_argument("unknown stepper '" + name + "' (expected one of: " + list + ")");
}

std::string stepperName(StepperKind kind) { return stepperNames().at(static_cast<std::size_t>(kind)); }

std::string stopReasonName(StopReason r) {
    switch (r) {
        case StopReason::Escaped: return "escaped";
        case StopReason::Horizon: return "horizon";
        case StopReason::MaxAffine: return "max_affine";
        case StopReason::MaxSteps: return "max_steps";
        case StopReason::ConstraintBlowUp: return "constraint_blowup";
        case StopReason::Singularity: return "singularity";
        case StopReason::StepUnderflow: return "step_underflow";
        case StopReason::Hit: return "hit";
        case StopReason::OtherEnd: return "other_end";
    }
    return "unknown";
}

std::vector<std::string> stopReasonNames() {
    std::vector<std::string> names;
    for (int k = 0; k <= static_cast<int>(StopReason::OtherEnd); ++k) names.push_back(stopReasonName(StopReason(k)));
    return names;
}

TraceResult traceGeodesic(const Spacetime& st, const PhasePoint& start, const TraceOptions& opt,
                          const SegmentVisitor& visitor) {
    TraceResult res;
    res.end = start;
    res.maxHamiltonianDrift = std::abs(st.hamiltonian(start.x, start.p));
    RayMonitor mon(st, opt, visitor, res);
    const HamiltonSystem sys{&st};
    const State s = toState(start);
    if (!finite(s)) {
        mon.stop(StopReason::Singularity);
        return res;
    }
    if (!st.asymptoticallyFlat() && !std::isfinite(opt.maxAffine))
        throw std::invalid_argument("rays of metric '" + st.name() +
                                    "' do not escape: the trace needs a finite max affine length");
    // Signed limit: integrate towards +maxAffine. Odeint gives up by throwing when a dense
    // stepper cannot find an acceptable step; for one ray that is a stop reason, not an error.
    try {
        switch (opt.stepper) {
            case StepperKind::RK4: runFixed(sys, s, opt, mon); break;
            case StepperKind::Dopri5: runDopri5(sys, s, opt, mon, res); break;
            case StepperKind::BulirschStoer:
                runDense(odeint::bulirsch_stoer_dense_out<State>(opt.absTol, opt.relTol), sys, s, opt, mon, res);
                break;
            case StepperKind::CashKarp54:
                runControlled(odeint::make_controlled(opt.absTol, opt.relTol, odeint::runge_kutta_cash_karp54<State>()),
                              sys, s, opt, mon, res);
                break;
            case StepperKind::Dopri87:
                runControlled(controlledPrinceDormand87<State>(opt.absTol, opt.relTol), sys, s, opt, mon, res);
                break;
        }
    } catch (const odeint::odeint_error&) {
        mon.stop(StopReason::StepUnderflow);
    }
    return res;
}

std::vector<std::pair<double, PhasePoint>> sampleGeodesic(const Spacetime& st, const PhasePoint& start,
                                                          const TraceOptions& opt, TraceResult* result) {
    std::vector<std::pair<double, PhasePoint>> out{{0.0, start}};
    const TraceResult r = traceGeodesic(st, start, opt, [&out](const Segment& s) {
        out.emplace_back(s.l1, s.s1);
        return false;
    });
    if (result) *result = r;
    return out;
}

}  // namespace lc
