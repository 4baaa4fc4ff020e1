// SPDX-License-Identifier: BSD-3-Clause
#include "camera_edits.hpp"

#include "core/scene/frame_camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace lc::gui {
namespace {

Json::Value numbers(std::initializer_list<double> values) {
    Json::Value out(Json::arrayValue);
    for (double v : values) out.append(v);
    return out;
}

constexpr double kDeg = lc::kPi / 180;

}  // namespace

double readableNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.12g", value);
    return std::strtod(text, nullptr);
}

std::vector<lc::io::SceneEdit> lookAroundEdits(const lc::Scene& scene, double dx, double dy) {
    const lc::Camera& cam = scene.camera;
    const double yaw = dx * cam.fovXDeg / cam.width * kDeg, pitch = dy * cam.fovYDeg / cam.height * kDeg;
    const lc::Vec3 f = lc::turnedForward(scene, yaw, pitch).normalized();
    std::vector<lc::io::SceneEdit> edits;
    if (cam.lookAt) edits.push_back({"camera.look_at", Json::Value()});
    edits.push_back({"camera.forward", numbers({readableNumber(f(0)), readableNumber(f(1)), readableNumber(f(2))})});
    return edits;
}

lc::io::SceneEdit zoomEdit(const lc::Camera& cam, int steps) {
    const double s = std::pow(1.1, -steps);
    const bool pinhole = cam.projection == lc::Camera::Projection::Pinhole;
    const double fx = std::clamp(readableNumber(cam.fovXDeg * s), 1.0, pinhole ? 170.0 : 360.0);
    const double fy = std::clamp(readableNumber(cam.fovYDeg * s), 1.0, pinhole ? 170.0 : 180.0);
    return {"camera.fov", numbers({fx, fy})};
}

std::vector<lc::io::SceneEdit> projectionEdits(const lc::Camera& cam, bool panorama) {
    // Pinhole: 90 degrees across, the height's angle from the image's aspect ratio.
    const double fovY =
        readableNumber(std::min(170.0, 2 * std::atan(std::tan(45 * kDeg) * cam.height / cam.width) / kDeg));
    return {{"camera.projection", Json::Value(panorama ? "panorama" : "pinhole")},
            {"camera.fov", panorama ? numbers({360, 120}) : numbers({90, fovY})}};
}

std::vector<lc::io::SceneEdit> resetViewEdits(const lc::io::EditableScene& scene) {
    std::vector<lc::io::SceneEdit> edits;
    for (const char* field : {"camera.look_at", "camera.forward", "camera.up", "camera.fov", "camera.projection"}) {
        const Json::Value was = scene.originalValue(field);
        if (!(scene.value(field) == was)) edits.push_back({field, was});
    }
    return edits;
}

}  // namespace lc::gui
