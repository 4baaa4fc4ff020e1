// SPDX-License-Identifier: BSD-3-Clause
#include "core/sr/photo_object.hpp"

namespace lc::sr {
namespace {
Vec4 emissionFromRestObserver(const Vec3& xRest, const Vec4& obsRest) {
    Vec4 e;
    e[0] = obsRest[0] - (xRest - obsRest.tail<3>()).norm();
    e.tail<3>() = xRest;
    return e;
}
}  // namespace

Vec4 emissionEventRest(const MovingFrame& frame, const Vec3& xRest, const Vec4& observer) {
    return emissionFromRestObserver(xRest, frame.eventToRest(observer));
}

Vec4 emissionEvent(const MovingFrame& frame, const Vec3& xRest, const Vec4& observer) {
    return frame.eventToObserver(emissionEventRest(frame, xRest, observer));
}

std::vector<Vec3> apparentPositions(const MovingFrame& frame, const std::vector<Vec3>& restVertices,
                                    const Vec4& observer) {
    const Vec4 obsRest = frame.eventToRest(observer);
    std::vector<Vec3> out(restVertices.size());
    for (size_t i = 0; i < restVertices.size(); ++i)
        out[i] = frame.eventToObserver(emissionFromRestObserver(restVertices[i], obsRest)).tail<3>();
    return out;
}

}  // namespace lc::sr
