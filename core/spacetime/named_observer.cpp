// SPDX-License-Identifier: BSD-3-Clause
#include "core/spacetime/named_observer.hpp"

#include "core/metrics/boyer_lindquist.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <functional>
#include <stdexcept>

namespace lc {
namespace {

const char* const kNames[] = {"static", "zamo", "carter", "free_fall", "normal"};

[[noreturn]] void notHere(const std::string& observer, const std::string& why, const std::string& alternatives) {
    throw std::invalid_argument("no " + observer + " observer here: " + why + "; " + alternatives);
}

double norm2(const Mat4& g, const Vec4& v) { return v.dot(g * v); }

Vec4 unitTimelike(const Mat4& g, const Vec4& v) { return v / std::sqrt(norm2(g, v)); }

// d/dphi in a chart whose z axis is the symmetry axis (Kerr-Schild Cartesian, formula metrics
// that declare a "radius").
Vec4 axialKilling(const Vec4& x) { return Vec4(0, -x(2), x(1), 0); }

const Spacetime::KerrNewmanParameters& kerrNewmanOnly(const std::optional<Spacetime::KerrNewmanParameters>& kn,
                                                      const Spacetime& st, const std::string& observer) {
    if (!kn)
        notHere(observer, "it is defined for Kerr-Newman holes (schwarzschild, kerr, kerr-newman), not " + st.name(),
                "use static, zamo or normal, or give the 4-velocity as four numbers");
    return *kn;
}

Vec4 staticObserver(const Mat4& g, const std::function<std::string()>& alternatives) {
    if (!(g(0, 0) > 0))
        notHere("static",
                "d/dt is not timelike (g_tt = " + std::to_string(g(0, 0)) +
                    " in the (+,-,-,-) signature Lightcone computes in, where timelike is g_tt > 0): spacetime "
                    "drags every observer here, as in an ergoregion, inside a horizon or in a warp bubble faster than "
                    "light",
                "the observers that exist here: " + alternatives() + "; or give the 4-velocity as four numbers");
    return unitTimelike(g, Vec4::Unit(0));
}

Vec4 zamo(const Spacetime& st, const Mat4& g, const Vec4& x) {
    if (!st.equatorialRadius())
        notHere("zamo", st.name() + " declares no axial symmetry about the chart's z axis",
                "use static or normal, or give the 4-velocity as four numbers");
    const Vec4 t = Vec4::Unit(0), phi = axialKilling(x);
    const double gPhiPhi = norm2(g, phi);
    // On the axis d/dphi vanishes and the ZAMO is the static observer.
    const Vec4 u = std::abs(gPhiPhi) > 1e-300 ? Vec4(t - phi * (t.dot(g * phi) / gPhiPhi)) : t;
    if (!(norm2(g, u) > 0))
        notHere("zamo", "d/dt + omega d/dphi is not timelike (inside a horizon)",
                "observers inside a horizon are not available");
    return unitTimelike(g, u);
}

Vec4 carter(const Spacetime::KerrNewmanParameters& kn, const Mat4& g, const Vec4& x) {
    const double a = kn.spin, r = kerrSchildRadius(x(1), x(2), x(3), a);
    const double delta = r * r - 2 * kn.mass * r + a * a + kn.charge * kn.charge;
    if (!(delta > 0))
        notHere("carter", "Delta = r^2 - 2 M r + a^2 + Q^2 <= 0 (inside the horizon)",
                "observers inside a horizon are not available");
    return unitTimelike(g, (r * r + a * a) * Vec4::Unit(0) + a * axialKilling(x));
}

// E = g(u, d/dt) = 1, L_z = -g(u, d/dphi) = 0 and u^theta = 0 (Carter's Q = 0) fix u up to one
// parameter along the null space of those three rows; g(u, u) = 1 picks two roots, of which
// the infalling one (dr(u) < 0).
Vec4 freeFall(const Spacetime::KerrNewmanParameters& kn, const Mat4& g, const Vec4& x) {
    const BoyerLindquistGradients bl = boyerLindquistGradients(x, kn.spin);
    const double rPlus =
        kn.mass + std::sqrt(std::max(0.0, kn.mass * kn.mass - kn.spin * kn.spin - kn.charge * kn.charge));
    if (!(bl.r > rPlus * (1 + 1e-9)))
        notHere("free_fall", "the event is inside the horizon", "observers inside a horizon are not available");
    Eigen::Matrix<double, 3, 4> rows;
    rows.row(0) = (g * Vec4::Unit(0)).transpose();
    rows.row(1) = (g * axialKilling(x)).transpose();
    rows.row(2) = bl.dCosTheta.transpose();
    const Eigen::FullPivLU<Eigen::Matrix<double, 3, 4>> lu(rows);
    const Vec4 particular = lu.solve(Eigen::Vector3d(1, 0, 0));
    const Vec4 kernel = lu.kernel().col(0);
    // g(p + l k, p + l k) = 1: A l^2 + 2 B l + C = 0.
    const double A = norm2(g, kernel), B = particular.dot(g * kernel), C = norm2(g, particular) - 1;
    const double disc = B * B - A * C;
    if (!(disc >= 0) || A == 0)
        notHere("free_fall", "no timelike solution with E = 1, L = 0, Q = 0 here",
                "give the 4-velocity as four numbers");
    for (const double sign : {1.0, -1.0}) {
        const Vec4 u = particular + ((-B + sign * std::sqrt(disc)) / A) * kernel;
        if (bl.dr.dot(u) < 0 && u(0) > 0) return u;
    }
    notHere("free_fall", "no infalling solution with E = 1, L = 0, Q = 0 here", "give the 4-velocity as four numbers");
}

Vec4 normal(const Spacetime& st, const Vec4& x) {
    const Mat4 gInverse = st.inverseMetric(x);
    if (!(gInverse(0, 0) > 0))
        notHere("normal", "the slice t = const is not spacelike here (g^tt = " + std::to_string(gInverse(0, 0)) + ")",
                "give the 4-velocity as four numbers");
    // u_a = d_a t / sqrt(g^tt): u^t = sqrt(g^tt) > 0.
    return gInverse.col(0) / std::sqrt(gInverse(0, 0));
}

}  // namespace

std::optional<NamedObserver> namedObserverFrom(const std::string& name) {
    for (int k = 0; k < 5; ++k)
        if (name == kNames[k]) return static_cast<NamedObserver>(k);
    return std::nullopt;
}

std::string nameOf(NamedObserver observer) { return kNames[static_cast<int>(observer)]; }

std::string namedObserverNames() { return "static, zamo, carter, free_fall, normal"; }

Vec4 namedObserverVelocity(const Spacetime& st, const Vec4& x, NamedObserver observer) {
    if (const Boundary b = st.boundary(x); b == Boundary::Horizon && st.kerrNewmanParameters())
        // The built-in holes are charted in outgoing Kerr-Schild coordinates, whose inside is the
        // white hole: nothing falls in there. The ingoing charts in data/metrics hold the fall.
        notHere(nameOf(observer),
                "the event is at or inside the metric's horizon, which this chart crosses as a white hole's: nothing "
                "falls in there",
                "move the observer outside it, or for views from inside a black hole use the ingoing chart of "
                "metrics/kerr_rain.json or metrics/schwarzschild_rain.json with the observer's 4-velocity as four "
                "numbers (docs/PHYSICS.md 9d)");
    else if (b != Boundary::None)
        notHere(nameOf(observer), "the event is at or inside the metric's horizon or singularity",
                "move the observer outside it");
    const Mat4 g = st.metric(x);
    switch (observer) {
        case NamedObserver::Static: return staticObserver(g, [&] { return namedObserversAt(st, x); });
        case NamedObserver::Zamo: return zamo(st, g, x);
        case NamedObserver::Carter: return carter(kerrNewmanOnly(st.kerrNewmanParameters(), st, "carter"), g, x);
        case NamedObserver::FreeFall: return freeFall(kerrNewmanOnly(st.kerrNewmanParameters(), st, "free_fall"), g, x);
        case NamedObserver::Normal: return normal(st, x);
    }
    throw std::logic_error("namedObserverVelocity: unknown observer");
}

std::string namedObserversAt(const Spacetime& spacetime, const Vec4& x) {
    std::string found;
    for (int k = 1; k < 5; ++k) try {  // static: where the others are asked for (staticObserver)
            const Vec4 u = namedObserverVelocity(spacetime, x, static_cast<NamedObserver>(k));
            if (u.allFinite()) found += (found.empty() ? "" : ", ") + std::string(kNames[k]);
        } catch (const std::invalid_argument&) {
            // not here
        }
    return found.empty() ? "none" : found;
}

}  // namespace lc
