// SPDX-License-Identifier: BSD-3-Clause
#include "core/scene/frame_camera.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lc {

Vec3 restSpaceComponents(const Spacetime& st, const LocalFrame& frame, const Vec3& v) {
    const Mat4 g = st.metric(frame.x);
    const Vec4 V(0, v(0), v(1), v(2));
    const Vec4 gV = g * V;
    return Vec3(-gV.dot(frame.e[1]), -gV.dot(frame.e[2]), -gV.dot(frame.e[3]));
}

Vec3 chartVectorOf(const Spacetime& /*st*/, const LocalFrame& frame, const Vec3& n) {
    // n^i e_i plus the multiple of u that cancels its time component: the projection of that
    // vector is n^i e_i again (u^0 > 0 for a future-directed observer).
    const Vec4 w = frame.spatialVector(n);
    const Vec4 v = w - (w(0) / frame.e[0](0)) * frame.e[0];
    return v.tail<3>();
}

Camera frameCamera(const Camera& chart, const Spacetime& st, const LocalFrame& frame) {
    Camera cam = chart;
    cam.lookAt.reset();
    cam.forward =
        restSpaceComponents(st, frame, chart.lookAt ? lookAtDirection(frame.x, *chart.lookAt) : chart.forward);
    cam.up = restSpaceComponents(st, frame, chart.up);
    // In the rest space the frame is orthonormal, so the Euclidean Gram-Schmidt of Camera on
    // these components is the metric's. A fast observer can squeeze two chart directions together.
    if (!(cam.forward.norm() > 0) || cam.forward.normalized().cross(cam.up.normalized()).norm() < 1e-9)
        throw std::invalid_argument(
            "camera: forward and up point the same way in the observer's rest space (give an up that is not "
            "parallel to forward)");
    return cam;
}

LocalFrame observerFrame(const Scene& scene) {
    return LocalFrame::withVelocity(*scene.spacetime, scene.observer, scene.observerVelocity);
}

Camera frameCamera(const Scene& scene) { return frameCamera(scene.camera, *scene.spacetime, observerFrame(scene)); }

Vec3 turnedForward(const Scene& scene, double yaw, double pitch) {
    const LocalFrame frame = observerFrame(scene);
    const Camera cam = frameCamera(scene.camera, *scene.spacetime, frame);  // resolves look_at
    const Vec3 up = cam.forward.normalized().cross(cam.up).normalized().cross(cam.forward.normalized());
    Vec3 f = Eigen::AngleAxisd(yaw, up) * cam.forward.normalized();
    const Vec3 pitched = Eigen::AngleAxisd(pitch, f.cross(up).normalized()) * f;
    if (std::abs(pitched.normalized().dot(up)) < std::cos(2 * kPi / 180)) f = pitched;
    return chartVectorOf(*scene.spacetime, frame, f.normalized()).normalized();
}

Vec3 lookAtDirection(const Vec4& observer, const Vec3& target) {
    const Vec3 d = target - observer.tail<3>();
    if (!(d.norm() > 1e-12 * std::max(1.0, target.norm())))
        throw std::invalid_argument("camera: look_at is the observer's own position; give a point to look at");
    return d;
}

}  // namespace lc
