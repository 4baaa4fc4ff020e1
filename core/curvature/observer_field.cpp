// SPDX-License-Identifier: BSD-3-Clause
#include "core/curvature/observer_field.hpp"

#include <cmath>

namespace lc {

std::optional<ObserverField> observerFieldNamed(const std::string& name) {
    if (name == "static") return ObserverField::Static;
    if (name == "normal") return ObserverField::Normal;
    if (name == "auto") return ObserverField::StaticElseNormal;
    return std::nullopt;
}

std::optional<LocalFrame> observerFrameAt(const Mat4& g, const Mat4& gInverse, const Vec4& x, ObserverField field) {
    if (field != ObserverField::Normal && g(0, 0) > 0) return LocalFrame::fromMetric(g, x, Vec4::Unit(0));
    if (field == ObserverField::Static) return std::nullopt;
    // u_a = d_a t / sqrt(g^tt): future-directed (u^t = sqrt(g^tt) > 0) where g^tt > 0.
    if (!(gInverse(0, 0) > 0)) return std::nullopt;
    const Vec4 u = gInverse.col(0) / std::sqrt(gInverse(0, 0));
    return LocalFrame::fromMetric(g, x, u);
}

}  // namespace lc
