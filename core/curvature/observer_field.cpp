#include "core/curvature/observer_field.hpp"

#include <cmath>

namespace lc {

std::optional<ObserverField> observerFieldNamed(const std::string& name) {
    if (name == "static") return ObserverField::Static;
    if (name == "normal") return ObserverField::Normal;
    if (name == "auto") return ObserverField::StaticElseNormal;
    return std::nullopt;
}

const char* observerFieldName(ObserverField field) {
    switch (field) {
        case ObserverField::Static: return "static";
        case ObserverField::Normal: return "normal";
        default: return "auto";
    }
}

std::optional<LocalFrame> frameWithVelocity(const Mat4& g, const Vec4& x, const Vec4& uIn) {
    const double uu = uIn.dot(g * uIn);
    if (!(uu > 0)) return std::nullopt;
    LocalFrame f;
    f.x = x;
    f.e[0] = uIn / std::sqrt(uu);
    for (int i = 1; i < 4; ++i) {
        Vec4 v = Vec4::Unit(i);
        v -= v.dot(g * f.e[0]) * f.e[0];
        for (int j = 1; j < i; ++j) v += v.dot(g * f.e[j]) * f.e[j];
        const double n = v.dot(g * v);
        if (!(n < 0)) return std::nullopt;
        f.e[i] = v / std::sqrt(-n);
    }
    return f;
}

std::optional<LocalFrame> observerFrameAt(const Mat4& g, const Mat4& gInverse, const Vec4& x, ObserverField field) {
    if (field != ObserverField::Normal && g(0, 0) > 0) return frameWithVelocity(g, x, Vec4::Unit(0));
    if (field == ObserverField::Static) return std::nullopt;
    // u_a = d_a t / sqrt(g^tt): future-directed (u^t = sqrt(g^tt) > 0) where g^tt > 0.
    if (!(gInverse(0, 0) > 0)) return std::nullopt;
    const Vec4 u = gInverse.col(0) / std::sqrt(gInverse(0, 0));
    return frameWithVelocity(g, x, u);
}

}  // namespace lc
