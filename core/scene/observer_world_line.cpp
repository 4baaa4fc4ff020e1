// SPDX-License-Identifier: BSD-3-Clause
// The observer's world line for animations: the orbit of d/dt, or the timelike geodesic.
#include "core/scene/observer_world_line.hpp"

#include "core/input/number_text.hpp"

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace lc {
namespace {

std::string tauText(double tau) { return input::significantDigits(tau); }

double squaredNorm(const Spacetime& st, const Vec4& x, const Vec4& u) { return u.dot(st.metric(x) * u); }

// dt/dtau of a static observer at x: 1/sqrt(g_tt); throws where d/dt is not timelike.
double staticRate(const Spacetime& st, const Vec4& x, double tau) {
    const double gtt = st.metric(x)(0, 0);
    if (!(gtt > 0) || !std::isfinite(gtt))
        throw std::invalid_argument("a static observer cannot stay at rest at proper time " + tauText(tau) +
                                    ": d/dt is not timelike there (g_tt = " + tauText(gtt) +
                                    " in the (+,-,-,-) signature, where timelike is g_tt > 0); use observer motion "
                                    "free_fall");
    return 1 / std::sqrt(gtt);
}

// The proper times of one direction (all >= 0 after the sign is taken out), in increasing order,
// each with the indices of the requested times it answers.
std::map<double, std::vector<std::size_t>> oneSide(const std::vector<double>& taus, double sign) {
    std::map<double, std::vector<std::size_t>> side;
    for (std::size_t k = 0; k < taus.size(); ++k)
        if (sign * taus[k] > 0) side[sign * taus[k]].push_back(k);
    return side;
}

void staticSide(const Spacetime& st, const Vec4& start, double sign, const std::vector<double>& taus,
                std::vector<ObserverEvent>& out) {
    namespace odeint = boost::numeric::odeint;
    double t = start(0), tau = 0;
    Vec4 x = start;
    for (const auto& [target, indices] : oneSide(taus, sign)) {
        auto rate = [&](const double& time, double& dtdtau, double) {
            Vec4 at = start;
            at(0) = time;
            dtdtau = sign * staticRate(st, at, sign * tau);
        };
        odeint::integrate_adaptive(odeint::make_controlled(1e-12, 1e-12, odeint::runge_kutta_dopri5<double>()), rate, t,
                                   tau, target, std::max(1e-6, 0.01 * (target - tau)));
        tau = target;
        x(0) = t;
        const Vec4 u = staticRate(st, x, sign * tau) * Vec4::Unit(0);
        for (std::size_t k : indices) out[k] = {x, u};
    }
}

void freeFallSide(const Spacetime& st, const Vec4& start, const Vec4& u0, double sign, const std::vector<double>& taus,
                  const TraceOptions& options, std::vector<ObserverEvent>& out) {
    const auto side = oneSide(taus, sign);
    if (side.empty()) return;
    TraceOptions opt = options;
    opt.maxAffine = side.rbegin()->first;
    opt.constraintTolerance = std::numeric_limits<double>::infinity();  // H = 1/2 here, not 0
    opt.escapeRadius = std::numeric_limits<double>::infinity();         // an observer does not "escape"
    // Past-directed momentum for negative proper times: the affine parameter then runs backwards in tau.
    const PhasePoint p0{start, sign * (st.metric(start) * u0)};
    auto pending = side.begin();
    const TraceResult r = traceGeodesic(st, p0, opt, [&](const Segment& seg) {
        for (; pending != side.end() && pending->first <= seg.l1; ++pending) {
            const PhasePoint s = seg.at(pending->first);
            const Vec4 u = sign * (st.inverseMetric(s.x) * s.p);
            for (std::size_t k : pending->second) out[k] = {s.x, u};
        }
        return false;
    });
    // The last step can end a rounding error short of the last time asked for.
    for (; pending != side.end() && r.reason == StopReason::MaxAffine &&
           pending->first - r.affine <= 1e-12 * std::max(1.0, pending->first);
         ++pending)
        for (std::size_t k : pending->second) out[k] = {r.end.x, sign * (st.inverseMetric(r.end.x) * r.end.p)};
    if (pending != side.end())
        throw std::invalid_argument("the observer's free fall ends at proper time " + tauText(sign * r.affine) + " (" +
                                    stopReasonName(r.reason) + "), before " + tauText(sign * pending->first));
}

}  // namespace

ObserverMotion parseObserverMotion(const std::string& name) {
    if (name == "static") return ObserverMotion::Static;
    if (name == "free_fall") return ObserverMotion::FreeFall;
    throw std::invalid_argument("unknown observer motion '" + name + "' (expected static or free_fall)");
}

std::string observerMotionName(ObserverMotion motion) {
    return motion == ObserverMotion::Static ? "static" : "free_fall";
}

ObserverMotion defaultObserverMotion(const Vec4& velocity) {
    return velocity.tail<3>().norm() > 0 ? ObserverMotion::FreeFall : ObserverMotion::Static;
}

std::vector<ObserverEvent> observerWorldLine(const Spacetime& st, const Vec4& start, const Vec4& velocity,
                                             ObserverMotion motion, const std::vector<double>& taus,
                                             const TraceOptions& options) {
    for (double tau : taus)
        if (!std::isfinite(tau)) throw std::invalid_argument("proper time " + tauText(tau) + " is not finite");
    const double norm2 = squaredNorm(st, start, velocity);
    if (!(norm2 > 0) || !(velocity(0) > 0))
        throw std::invalid_argument("the observer's velocity is not future timelike");
    const Vec4 u0 = velocity / std::sqrt(norm2);
    std::vector<ObserverEvent> out(taus.size(), ObserverEvent{start, u0});
    if (motion == ObserverMotion::Static) {
        if (velocity.tail<3>().norm() > 0)
            throw std::invalid_argument(
                "a static observer is at rest in the chart, but this one has a spatial velocity (use free_fall)");
        const Vec4 uStatic = staticRate(st, start, 0) * Vec4::Unit(0);
        for (auto& e : out) e.velocity = uStatic;
        for (double sign : {1.0, -1.0}) staticSide(st, start, sign, taus, out);
    } else {
        for (double sign : {1.0, -1.0}) freeFallSide(st, start, u0, sign, taus, options, out);
    }
    return out;
}

}  // namespace lc
