// SPDX-License-Identifier: BSD-3-Clause
// Age labels of travellers (bodies on world lines by proper time): the observer reads each
// duplicate's age beside its image (docs/PHYSICS.md section 11).
#include "app/commands/commands.hpp"
#include "core/scene/frame_camera.hpp"

#include <algorithm>
#include <cstdio>

namespace lc::cli {

std::vector<io::ImageLabel> ageLabels(const Scene& scene, const std::vector<AgeImage>& ages) {
    int travellerCount = 0;
    for (const SphereObject& s : scene.spheres) travellerCount += s.motion.kind == Motion::Kind::ProperTime;
    if (travellerCount == 0) return {};  // other scenes' images stay exactly as they were
    std::vector<io::ImageLabel> labels;
    const Camera cam = frameCamera(scene);
    const double pixelsPerRadian = cam.height / (cam.fovYDeg * kPi / 180);
    char text[160];
    std::snprintf(text, sizeof text, "observer t = %.2f", scene.observer(0));
    labels.push_back({6, 16, text});
    for (const AgeImage& age : ages) {
        double x = 0, y = 0;
        if (!cam.project(age.direction, x, y) || x < 0 || y < 0 || x >= cam.width || y >= cam.height) continue;
        if (travellerCount > 1)
            std::snprintf(text, sizeof text, "%s: tau = %.2f", age.name.c_str(), age.properTime);
        else
            std::snprintf(text, sizeof text, "tau = %.2f", age.properTime);
        // Below the image's centre, so the label does not hide the body.
        // In double until clamped: a body filling 1e5 fields of view is beyond int pixels.
        const int below =
            static_cast<int>(std::min(double(cam.height - 4), y + age.angularRadius * pixelsPerRadian + 16));
        labels.push_back({static_cast<int>(x) - 28, std::min(cam.height - 4, below), text});
    }
    return labels;
}

}  // namespace lc::cli
