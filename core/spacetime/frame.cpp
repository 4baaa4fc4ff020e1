// SPDX-License-Identifier: BSD-3-Clause
#include "core/spacetime/frame.hpp"

#include <stdexcept>

namespace lc {

std::optional<LocalFrame> LocalFrame::fromMetric(const Mat4& g, const Vec4& x, const Vec4& uIn) {
    const double uu = uIn.dot(g * uIn);
    if (!(uu > 0)) return std::nullopt;
    LocalFrame f;
    f.x = x;
    f.e[0] = uIn / std::sqrt(uu);
    // Gram-Schmidt with the Lorentzian product; spatial vectors have g(e,e) = -1.
    for (int i = 1; i < 4; ++i) {
        Vec4 v = Vec4::Unit(i);
        v -= v.dot(g * f.e[0]) * f.e[0];                              // g(e0,e0) = +1
        for (int j = 1; j < i; ++j) v += v.dot(g * f.e[j]) * f.e[j];  // g(ej,ej) = -1
        const double n = v.dot(g * v);
        if (!(n < 0)) return std::nullopt;
        f.e[i] = v / std::sqrt(-n);
    }
    return f;
}

LocalFrame LocalFrame::withVelocity(const Spacetime& st, const Vec4& x, const Vec4& uIn) {
    const Mat4 g = st.metric(x);
    const double uu = uIn.dot(g * uIn);
    if (!(uu > 0) || uIn(0) <= 0)
        throw std::invalid_argument("observer 4-velocity is not future-directed timelike at this event (g(u,u) = " +
                                    std::to_string(uu) + " in the (+,-,-,-) signature, where timelike is g(u,u) > 0)");
    const std::optional<LocalFrame> f = fromMetric(g, x, uIn);
    if (!f) throw std::runtime_error("cannot build a spatial frame vector at this event");
    return *f;
}

LocalFrame LocalFrame::staticObserver(const Spacetime& st, const Vec4& x) { return withVelocity(st, x, Vec4::Unit(0)); }

Vec4 LocalFrame::pastNullMomentum(const Spacetime& st, const Vec3& n) const {
    return pastNullMomentumAlong<double>(n.normalized(), e, st.metric(x));
}

Vec3 LocalFrame::directionOf(const Spacetime& st, const Vec4& p) const {
    const Vec4 k = st.inverseMetric(x) * p;
    const Mat4 g = st.metric(x);
    // Frame components n^i = -g(k, e_i) since g(e_i, e_i) = -1.
    Vec3 n(-k.dot(g * e[1]), -k.dot(g * e[2]), -k.dot(g * e[3]));
    return n.normalized();
}

}  // namespace lc
