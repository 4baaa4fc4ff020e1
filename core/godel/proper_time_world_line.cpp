// SPDX-License-Identifier: BSD-3-Clause
#include "core/godel/proper_time_world_line.hpp"

#include "core/godel/geodesic.hpp"
#include "core/godel/images.hpp"
#include "core/godel/isometry.hpp"
#include "core/input/number_text.hpp"
#include "core/metrics/godel.hpp"

#include <boost/numeric/odeint.hpp>

#include <algorithm>
#include <limits>
#include <memory>
#include <cmath>
#include <stdexcept>

namespace lc::godel {
namespace {

namespace odeint = boost::numeric::odeint;

// A burn is integrated once and kept as samples (Hermite interpolation): 4000 per unit of a,
// so the longest burn, kMaxBurnLength, keeps 1e6 (64 MB).
constexpr double kBurnSamplesPerA = 4000;
constexpr double kMaxBurnLength = 250;
constexpr double kMaxTripBurn = 4 * kMaxBurnLength;  // 4e6 samples, 256 MB, for a whole trip
// The fastest a body may go, as the object speed range (0.99999999 c): beyond it the Doppler
// factor leaves single precision.
constexpr double kMaxBurnGamma = 7071.07;
using RocketState = std::array<double, 8>;  // x^mu, p_mu (covariant)

// A burn: Hamilton's equations with the force a n_mu, n the unit thrust direction orthogonal to u.
// Sampled on a fine grid by odeint's dense output, read back by cubic Hermite interpolation.
struct RocketBurn {
    double length = 0, step = 0;
    std::vector<Vec4> xs, us;
    // Where the burn passed kMaxBurnGamma relative to the static observers (< 0: never); the
    // integration stops there.
    double tooFastAt = -1;
    Vec4 x(double l) const { return interpolate(l, false); }
    Vec4 u(double l) const { return interpolate(l, true); }
    Vec4 interpolate(double l, bool velocity) const {
        const double s = std::clamp(l / step, 0.0, double(xs.size() - 1));
        const std::size_t i = std::min(static_cast<std::size_t>(s), xs.size() - 2);
        const double f = s - double(i), h = step;
        const Vec4 &x0 = xs[i], &x1 = xs[i + 1], &v0 = us[i], &v1 = us[i + 1];
        if (velocity) {  // derivative of the Hermite cubic
            const double a0 = 6 * f * f - 6 * f, b0 = 3 * f * f - 4 * f + 1, a1 = -6 * f * f + 6 * f,
                         b1 = 3 * f * f - 2 * f;
            return (a0 * x0 + a1 * x1) / h + b0 * v0 + b1 * v1;
        }
        const double h00 = 2 * f * f * f - 3 * f * f + 1, h10 = f * f * f - 2 * f * f + f,
                     h01 = -2 * f * f * f + 3 * f * f, h11 = f * f * f - f * f;
        return h00 * x0 + h10 * h * v0 + h01 * x1 + h11 * h * v1;
    }
};

RocketBurn burn(const GodelCartesian& st, const Vec4& x0, const Vec4& u0, double accel, WorldLineSegment::Thrust thrust,
                double length) {
    using T = WorldLineSegment::Thrust;
    auto direction = [thrust](const Vec4& x) {
        const double r = std::hypot(x(1), x(2));
        const Vec4 radial = r > 0 ? Vec4(0, x(1) / r, x(2) / r, 0) : Vec4(0, 1, 0, 0);
        const Vec4 around = r > 0 ? Vec4(0, -x(2) / r, x(1) / r, 0) : Vec4(0, 0, 1, 0);
        switch (thrust) {
            case T::Outward: return radial;
            case T::Inward: return Vec4(-radial);
            case T::Prograde: return around;
            case T::Retrograde: return Vec4(-around);
            case T::Up: return Vec4(Vec4::Unit(3));
            case T::Down: return Vec4(-Vec4::Unit(3));
        }
        return radial;
    };
    auto system = [&](const RocketState& s, RocketState& ds, double) {
        const Vec4 x(s[0], s[1], s[2], s[3]), p(s[4], s[5], s[6], s[7]);
        const HamiltonianFlow f = st.flow(x, p);
        const Mat4 g = st.metric(x);
        const Vec4 u = f.dxdl;
        Vec4 n = direction(x);
        n -= n.dot(g * u) * u;  // into the rest space of u (g(u,u) = 1)
        const Vec4 force = accel * (g * n) / std::sqrt(-n.dot(g * n));
        for (int k = 0; k < 4; ++k) ds[k] = f.dxdl(k), ds[4 + k] = f.dpdl(k) + force(k);
    };
    RocketBurn b;
    b.length = length;
    // Hermite: 1e-15 in x. The caller holds length to kMaxBurnLength, so this stays <= 1e6.
    const int samples = std::max(64, static_cast<int>(std::ceil(kBurnSamplesPerA * length)));
    b.step = length / samples;
    const Vec4 p0 = st.metric(x0) * u0;
    RocketState s{x0(0), x0(1), x0(2), x0(3), p0(0), p0(1), p0(2), p0(3)};
    struct TooFast {};
    try {
        odeint::integrate_const(odeint::make_dense_output(1e-13, 1e-13, odeint::runge_kutta_dopri5<RocketState>()),
                                system, s, 0.0, length + 0.5 * b.step, b.step, [&](const RocketState& z, double l) {
                                    const Vec4 x(z[0], z[1], z[2], z[3]);
                                    Vec4 u = st.inverseMetric(x) * Vec4(z[4], z[5], z[6], z[7]);
                                    u /= std::sqrt(u.dot(st.metric(x) * u));  // H drifts by ~1e-13: renormalised
                                    // g_tt = 1: u_t is the Lorentz factor relative to the static (dust) observer.
                                    if (!((st.metric(x) * u)(0) <= kMaxBurnGamma)) {
                                        b.tooFastAt = l;
                                        throw TooFast{};
                                    }
                                    if (static_cast<int>(b.xs.size()) <= samples) b.xs.push_back(x), b.us.push_back(u);
                                });
    } catch (const TooFast&) {
    }
    return b;
}

// Cylindrical (t, r, phi, z) event and velocity to the Cartesian chart.
Vec4 cartesian(double t, double r, double phi, double z) { return Vec4(t, r * std::cos(phi), r * std::sin(phi), z); }
Vec4 cartesianVelocity(double r, double phi, double dt, double dr, double dphi, double dz) {
    return Vec4(dt, dr * std::cos(phi) - r * std::sin(phi) * dphi, dr * std::sin(phi) + r * std::cos(phi) * dphi, dz);
}

}  // namespace

std::string WorldLineSegment::name(Kind k) {
    switch (k) {
        case Kind::Rest: return "rest";
        case Kind::Radial: return "radial";
        case Kind::Circle: return "circle";
        case Kind::FreeFall: return "free_fall";
        case Kind::Rocket: return "rocket";
        case Kind::Samples: return "samples";
    }
    return "?";
}

namespace {

// One segment's world line as closed forms (or interpolants) of the proper time since its start.
struct PieceShape {
    double length = 0;
    std::function<Vec4(double)> x, u;
    std::function<ProperTimeWorldLine::ChartBox(double, double)> box;
};
using ChartBox = ProperTimeWorldLine::ChartBox;

// Rest, radial and circle legs: t linear in tau and z constant, so the ends bound them.
std::function<ChartBox(double, double)> linearBox(const std::function<Vec4(double)>& x) {
    return [x](double l0, double l1) {
        const Vec4 p = x(l0), q = x(l1);
        return ChartBox{std::min(p(0), q(0)), std::max(p(0), q(0)), std::min(p(3), q(3)), std::max(p(3), q(3))};
    };
}

// The box of a list of events (a rocket's samples, a sampled leg's events), padded by `pad` in t.
ChartBox eventsBox(std::vector<Vec4>::const_iterator begin, std::vector<Vec4>::const_iterator end, double pad) {
    const double inf = std::numeric_limits<double>::infinity();
    ChartBox b{inf, -inf, inf, -inf};
    for (auto it = begin; it != end; ++it) {
        b.tMin = std::min(b.tMin, (*it)(0) - pad), b.tMax = std::max(b.tMax, (*it)(0) + pad);
        b.zMin = std::min(b.zMin, (*it)(3) - pad), b.zMax = std::max(b.zMax, (*it)(3) + pad);
    }
    return b;
}
// Throws std::invalid_argument naming the segment.
using Fail = std::function<void(const std::string&)>;

// Each kind of segment from event x with velocity u (docs/PHYSICS.md, the time traveller).
PieceShape restPiece(const WorldLineSegment& s, const Vec4& x, const Fail& fail) {
    PieceShape shape;
    if (!(s.properTime > 0)) fail("proper_time must be > 0");
    const Vec4 at = x;
    shape.length = s.properTime;
    shape.x = [at](double l) { return Vec4(at(0) + l, at(1), at(2), at(3)); };
    shape.u = [](double) { return Vec4(Vec4::Unit(0)); };
    shape.box = linearBox(shape.x);
    return shape;
}

PieceShape radialPiece(const WorldLineSegment& s, double a, const Vec4& x, const Fail& fail) {
    const double t0 = x(0), z0 = x(3), r0 = std::hypot(x(1), x(2)), phi0 = std::atan2(x(2), x(1));
    PieceShape shape;
    // u = gamma (e_t + s beta e_r), e_t = d/dt, e_r = sqrt(1 + r^2/4a^2) d/dr (g_tr = 0):
    // dt/dtau = gamma, dr/dtau = s gamma beta sqrt(1 + r^2/4a^2), so
    // r(tau) = 2a sinh(asinh(r0 / 2a) + s gamma beta tau / 2a).
    if (!(s.speed > 0 && s.speed < 1)) fail("speed must lie in (0, 1)");
    if (!(r0 > 1e-12 * a)) fail("starts on the axis, where no radial direction is given");
    if (!(s.toRadius > 0)) fail("to_radius must be > 0");
    const double gamma = 1 / std::sqrt((1 - s.speed) * (1 + s.speed)), gb = gamma * s.speed;
    const double sign = s.toRadius > r0 ? 1 : -1, w0 = std::asinh(r0 / (2 * a));
    shape.length = 2 * a * std::abs(std::asinh(s.toRadius / (2 * a)) - w0) / gb;
    shape.x = [=](double l) {
        return cartesian(t0 + gamma * l, 2 * a * std::sinh(w0 + sign * gb * l / (2 * a)), phi0, z0);
    };
    shape.u = [=](double l) {
        const double w = w0 + sign * gb * l / (2 * a), r = 2 * a * std::sinh(w);
        return cartesianVelocity(r, phi0, gamma, sign * gb * std::cosh(w), 0, 0);
    };
    shape.box = linearBox(shape.x);
    return shape;
}

PieceShape circlePiece(const WorldLineSegment& s, double a, const Vec4& x, const Fail& fail) {
    const double t0 = x(0), z0 = x(3), r0 = std::hypot(x(1), x(2)), phi0 = std::atan2(x(2), x(1));
    PieceShape shape;
    // dt = k dphi, dphi/dtau = sigma omega: omega^2 (k^2 + 2 g_tphi k + g_phiphi) = 1.
    if (!(r0 > 1e-12 * a)) fail("starts on the axis: a circle needs r > 0");
    if (s.turns == 0 || !std::isfinite(s.turns)) fail("turns must be non-zero");
    const double rate = s.dtDphi, sigma = s.turns > 0 ? 1 : -1;
    const double gtphi = r0 * r0 / (kSqrt2 * a), gphiphi = -r0 * r0 * (1 - r0 * r0 / (4 * a * a));
    const double q = rate * rate + 2 * gtphi * rate + gphiphi;
    if (!(q > 0))
        fail("not timelike at r = " + std::to_string(r0 / a) + " a with dt_dphi = " + std::to_string(rate) +
             " (k^2 + 2 g_tphi k + g_phiphi = " + std::to_string(q) +
             " <= 0; beyond r = 2a every |dt_dphi| small enough is timelike)");
    if (!(sigma * (rate + gtphi) > 0)) fail("past-directed (g(u, d/dt) < 0): turn the other way or change dt_dphi");
    const double omega = 1 / std::sqrt(q);
    shape.length = std::abs(s.turns) * 2 * kPi / omega;
    shape.x = [=](double l) { return cartesian(t0 + rate * sigma * omega * l, r0, phi0 + sigma * omega * l, z0); };
    shape.u = [=](double l) {
        return cartesianVelocity(r0, phi0 + sigma * omega * l, rate * sigma * omega, 0, sigma * omega, 0);
    };
    shape.box = linearBox(shape.x);
    return shape;
}

PieceShape rocketPiece(const WorldLineSegment& s, const GodelCartesian& metric, const Vec4& x, const Vec4& u,
                       const Fail& fail) {
    PieceShape shape;
    if (!(s.properTime > 0)) fail("proper_time must be > 0");
    if (!(s.acceleration > 0)) fail("acceleration must be > 0");
    if (!(s.properTime <= kMaxBurnLength))
        fail("a burn of proper_time " + input::significantDigits(s.properTime) + " is longer than " +
             input::significantDigits(kMaxBurnLength) +
             ": a burn is integrated and kept at 4000 samples per unit of proper time (1e6 at the longest); "
             "split it into burns, or coast with free_fall between them");
    const auto b = std::make_shared<const RocketBurn>(burn(metric, x, u, s.acceleration, s.thrust, s.properTime));
    if (b->tooFastAt >= 0)
        fail("the burn passes the Lorentz factor " + input::significantDigits(kMaxBurnGamma) +
             " (speed 0.99999999 c, the fastest a body may go) relative to the dust at proper time " +
             input::significantDigits(b->tooFastAt) + " of its " + input::significantDigits(s.properTime) +
             "; burn for less time or with less acceleration");
    shape.length = s.properTime;
    shape.x = [b](double l) { return b->x(l); };
    shape.u = [b, metric](double l) {  // the interpolant's derivative, made unit with g
        const Vec4 v = b->u(l);
        return Vec4(v / std::sqrt(v.dot(metric.metric(b->x(l)) * v)));
    };
    shape.box = [b](double l0, double l1) {  // the samples around [l0, l1]; Hermite overshoots by ~1e-15
        const auto last = static_cast<std::ptrdiff_t>(b->xs.size()) - 1;
        const auto i0 = std::clamp<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(std::floor(l0 / b->step)), 0, last);
        const auto i1 = std::clamp<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(std::ceil(l1 / b->step)), i0, last);
        return eventsBox(b->xs.begin() + i0, b->xs.begin() + i1 + 1, 1e-9 * b->step);
    };
    return shape;
}

PieceShape samplesPiece(const WorldLineSegment& s, const GodelCartesian& metric, const Vec4& x, const Fail& fail) {
    PieceShape shape;
    const auto& smp = s.samples;
    if (smp.size() < 2) fail("needs at least two samples");
    if ((smp.front().second - x).norm() > 1e-9 * (1 + x.norm()))
        fail(
            "the first sample is not where the world line is (the centre event, or the previous "
            "segment's end)");
    auto events = std::make_shared<std::vector<std::pair<double, Vec4>>>();
    for (std::size_t i = 0; i < smp.size(); ++i) {
        const double dtau = i ? smp[i].first - smp[i - 1].first : 0;
        if (i && !(dtau > 0)) fail("sample " + std::to_string(i) + ": proper times must increase");
        if (i) {
            const Vec4 d = smp[i].second - smp[i - 1].second;
            const Mat4 g = metric.metric(0.5 * (smp[i].second + smp[i - 1].second));
            const double dd = d.dot(g * d);
            if (!(dd > 0) || !((g * d)(0) > 0))
                fail("chord " + std::to_string(i - 1) + " to " + std::to_string(i) +
                     " is not future timelike (g(dx, dx) = " + std::to_string(dd) + ")");
            if (std::abs(std::sqrt(dd) - dtau) > 0.01 * dtau)
                fail("chord " + std::to_string(i - 1) + " to " + std::to_string(i) + " has proper length " +
                     std::to_string(std::sqrt(dd)) + " but its proper times differ by " + std::to_string(dtau));
        }
        events->emplace_back(smp[i].first - smp.front().first, smp[i].second);
    }
    shape.length = events->back().first;
    auto chord = [events](double l) {
        const auto& e = *events;
        auto it = std::upper_bound(e.begin() + 1, e.end() - 1, l,
                                   [](double v, const std::pair<double, Vec4>& q) { return v < q.first; });
        return std::pair<const std::pair<double, Vec4>*, const std::pair<double, Vec4>*>(&*(it - 1), &*it);
    };
    shape.x = [chord](double l) {
        const auto [a0, a1] = chord(l);
        return Vec4(a0->second + (l - a0->first) / (a1->first - a0->first) * (a1->second - a0->second));
    };
    shape.u = [chord, metric](double l) {  // the chord's direction, unit where the body is
        const auto [a0, a1] = chord(l);
        const Vec4 d = a1->second - a0->second;
        const Vec4 at = a0->second + (l - a0->first) / (a1->first - a0->first) * d;
        return Vec4(d / std::sqrt(d.dot(metric.metric(at) * d)));
    };
    const std::function<Vec4(double)> along = shape.x;
    shape.box = [events, along](double l0, double l1) {  // straight chords: the ends and the events between
        std::vector<Vec4> corners{along(l0), along(l1)};
        const auto less = [](double v, const std::pair<double, Vec4>& q) { return v < q.first; };
        for (auto it = std::upper_bound(events->begin(), events->end(), l0, less);
             it != events->end() && it->first < l1; ++it)
            corners.push_back(it->second);
        return eventsBox(corners.begin(), corners.end(), 0);
    };
    return shape;
}

PieceShape freeFallPiece(const WorldLineSegment& s, double a, const Vec4& x, const Vec4& u, const Fail& fail) {
    PieceShape shape;
    // The geodesic with the velocity the body has: moved to the origin, where the chart
    // is Minkowskian, it is docs/PHYSICS.md section 2's OriginGeodesic::timelike.
    if (!(s.properTime > 0)) fail("proper_time must be > 0");
    const Isometry toOrigin = Isometry::movingToOrigin(a, x);
    Vec4 v = toOrigin.pushForward(x, u);
    v /= std::sqrt(v(0) * v(0) - v.tail<3>().squaredNorm());
    const FreeFall fall(OriginGeodesic::timelike(a, v(0), v(3), std::atan2(v(2), v(1))), toOrigin.inverse());
    shape.length = s.properTime;
    shape.x = [fall](double l) { return fall.position(l); };
    shape.u = [fall](double l) { return fall.velocity(l); };
    // t is monotonic in the chart where the geodesic leaves the axis (it stays inside r = 2a,
    // where t is a time function); the isometry to the world chart shifts t by less than
    // Isometry::kTimeShiftBound a either way, and z by a constant.
    shape.box = [fall, a](double l0, double l1) {
        const Vec4 p = fall.position(l0), q = fall.position(l1);
        const double pad = 2 * Isometry::kTimeShiftBound * a;
        return ChartBox{std::min(p(0), q(0)) - pad, std::max(p(0), q(0)) + pad, std::min(p(3), q(3)),
                        std::max(p(3), q(3))};
    };
    return shape;
}

PieceShape pieceFor(const WorldLineSegment& s, double a, const GodelCartesian& metric, const Vec4& x, const Vec4& u,
                    const Fail& fail) {
    switch (s.kind) {
        case WorldLineSegment::Kind::Rest: return restPiece(s, x, fail);
        case WorldLineSegment::Kind::Radial: return radialPiece(s, a, x, fail);
        case WorldLineSegment::Kind::Circle: return circlePiece(s, a, x, fail);
        case WorldLineSegment::Kind::Rocket: return rocketPiece(s, metric, x, u, fail);
        case WorldLineSegment::Kind::Samples: return samplesPiece(s, metric, x, fail);
        case WorldLineSegment::Kind::FreeFall: return freeFallPiece(s, a, x, u, fail);
    }
    throw std::logic_error("world line: unknown segment kind");
}

// Timelike and future-directed along the piece (closed forms; checked at samples too), and
// starting where the previous one ends.
void checkPiece(const PieceShape& p, const GodelCartesian& metric, const Vec4& x, const Fail& fail) {
    for (int i = 0; i <= 16; ++i) {
        const double l = p.length * i / 16;
        const Vec4 ui = p.u(l), xi = p.x(l);
        const Mat4 g = metric.metric(xi);
        const double uu = ui.dot(g * ui), future = (g * ui)(0);
        // g(u,u) sums terms as large as gamma^2 (and r^2 far out) that cancel to 1, and far out
        // g_xx itself is 1 - c x^2 cancelling to 1/(1 + r^2/4a^2): rounding leaves ~1e-16 of
        // sum |u^m u^n| max(|g_mn|, 1), so the test allows 1e-12 of that besides 1e-9.
        const Mat4 size = g.cwiseAbs().cwiseMax(1.0);
        const double scale = ui.cwiseAbs().dot(size * ui.cwiseAbs());
        if (!(std::abs(uu - 1) <= 1e-9 + 1e-12 * scale))
            fail("not a unit timelike velocity: g(u,u) = " + input::significantDigits(uu, 12) +
                 " differs from 1 by more than 1e-9 + 1e-12 of its terms' size " + input::significantDigits(scale));
        if (!(future > 0)) fail("past-directed (g(u, d/dt) = " + std::to_string(future) + ")");
    }
    if ((p.x(0) - x).norm() > 1e-9 * (1 + x.norm())) fail("does not start where the previous segment ends");
}

}  // namespace

ProperTimeWorldLine::ProperTimeWorldLine(double a, const Vec4& start, std::vector<WorldLineSegment> segments) : a_(a) {
    if (!(a > 0)) throw std::invalid_argument("world line: the Goedel parameter a must be > 0");
    if (segments.empty()) throw std::invalid_argument("world line: no segments");
    const GodelCartesian metric(a);
    Vec4 x = start, u = Vec4::Unit(0);  // the static observer: g_tt = 1
    double tau = 0, burning = 0;
    for (std::size_t k = 0; k < segments.size(); ++k) {
        const WorldLineSegment& s = segments[k];
        const std::string where =
            "world line segment " + std::to_string(k) + " (" + WorldLineSegment::name(s.kind) + ")";
        const Fail fail = [&](const std::string& why) { throw std::invalid_argument(where + ": " + why); };
        if (s.kind == WorldLineSegment::Kind::Rocket && !((burning += s.properTime) <= kMaxTripBurn))
            fail("the trip's rocket burns add up to " + input::significantDigits(burning) + ", beyond " +
                 input::significantDigits(kMaxTripBurn) + " (each is kept as 4000 samples per unit of proper time)");
        PieceShape shape = pieceFor(s, a, metric, x, u, fail);
        checkPiece(shape, metric, x, fail);
        Piece p;
        p.tau0 = tau;
        p.length = shape.length;
        p.x = std::move(shape.x);
        p.u = std::move(shape.u);
        p.box = std::move(shape.box);
        if (!(tau + p.length <= kMaxDuration))
            fail("the trip's proper time reaches " + input::significantDigits(tau + p.length) + ", beyond " +
                 input::significantDigits(kMaxDuration) +
                 " (its part the observer can see is searched block by block)");
        x = p.x(p.length);
        u = p.u(p.length);
        tau += p.length;
        pieces_.push_back(std::move(p));
    }
}

const ProperTimeWorldLine::Piece& ProperTimeWorldLine::pieceAt(double tau, double& local) const {
    tau = std::clamp(tau, 0.0, duration());
    auto it =
        std::upper_bound(pieces_.begin(), pieces_.end(), tau, [](double t, const Piece& p) { return t < p.tau0; });
    const Piece& p = *(it == pieces_.begin() ? it : it - 1);
    local = std::clamp(tau - p.tau0, 0.0, p.length);
    return p;
}

Vec4 ProperTimeWorldLine::position(double tau) const {
    double l;
    const Piece& p = pieceAt(tau, l);
    return p.x(l);
}

Vec4 ProperTimeWorldLine::velocity(double tau) const {
    double l;
    const Piece& p = pieceAt(tau, l);
    return p.u(l);
}

std::vector<ProperTimeWorldLine::Junction> ProperTimeWorldLine::junctions() const {
    std::vector<Junction> out;
    const GodelCartesian metric(a_);
    for (std::size_t k = 0; k < pieces_.size(); ++k) {
        double gamma = 1;
        if (k > 0) {
            const Vec4 x = pieces_[k].x(0);
            gamma = pieces_[k - 1].u(pieces_[k - 1].length).dot(metric.metric(x) * pieces_[k].u(0));
        }
        out.push_back({pieces_[k].tau0, gamma});
    }
    return out;
}

std::vector<std::pair<double, double>> ProperTimeWorldLine::spansWhere(
    const std::function<bool(const ChartBox&)>& wanted) const {
    std::vector<std::pair<double, double>> spans;
    // Blocks of kSpanBlock a, longer where the trip would need more than 2.5e5 of them.
    const double block = std::max(kSpanBlock * a_, duration() / 2.5e5);
    for (const Piece& p : pieces_) {
        const double n = std::max(1.0, std::ceil(p.length / block));
        for (double k = 0; k < n; ++k) {
            const double l0 = p.length * k / n, l1 = p.length * (k + 1) / n;
            if (!wanted(p.box(l0, l1))) continue;
            if (!spans.empty() && spans.back().second >= p.tau0 + l0 - 1e-12 * (1 + p.tau0))
                spans.back().second = p.tau0 + l1;
            else
                spans.emplace_back(p.tau0 + l0, p.tau0 + l1);
        }
    }
    return spans;
}

std::vector<Vec4> ProperTimeWorldLine::sampled(int n) const {
    std::vector<Vec4> out;
    n = std::max(n, 1);
    for (int i = 0; i <= n; ++i) out.push_back(position(duration() * i / n));
    return out;
}

}  // namespace lc::godel
