#include "lightconeLightPath.h"

#include "core/spacetime/frame.hpp"
#include "core/godel/geodesic.hpp"
#include "core/godel/images.hpp"
#include "core/metrics/godel.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace lcgui {

bool hasClosedFormLightPaths(const lc::Scene& scene) {
    return dynamic_cast<const lc::GodelCartesian*>(scene.spacetime.get()) &&
           scene.observerVelocity.tail<3>().norm() == 0;
}

std::vector<lc::Vec4> lightPath(const lc::Scene& scene, int i, int j, double affine, int samples) {
    return lightPathAlong(scene, scene.camera.direction(i, j), affine, samples);
}

std::vector<lc::Vec4> lightPathAlong(const lc::Scene& scene, const lc::Vec3& n, double affine, int samples) {
    if (!hasClosedFormLightPaths(scene))
        throw std::invalid_argument("closed-form light paths need a Goedel scene and a static observer");
    const double a = dynamic_cast<const lc::GodelCartesian*>(scene.spacetime.get())->a();
    // The same ray as renderGodelClosedForm: the observer's static frame, moved to the origin.
    const auto axes = cameraAxes(scene);
    const lc::Vec3 d = (n(0) * axes[0] + n(1) * axes[1] + n(2) * axes[2]).normalized();
    const auto ray =
        lc::godel::OriginGeodesic::nullFromDirection(a, d(2), std::hypot(d(0), d(1)), std::atan2(d(1), d(0)), -1);
    std::vector<lc::Vec4> path;
    samples = std::max(samples, 1);
    path.reserve(static_cast<std::size_t>(samples) + 1);
    for (int k = 0; k <= samples; ++k) path.push_back(ray.cartesian(affine * k / samples));
    return path;
}

std::pair<int, int> pixelOfDirection(const lc::Camera& camera, const lc::Vec3& direction) {
    double x = 0, y = 0;
    const bool inView = camera.project(direction, x, y) && x >= 0 && y >= 0 && x < camera.width && y < camera.height;
    return inView ? std::pair{static_cast<int>(x), static_cast<int>(y)} : std::pair{-1, -1};
}

std::array<lc::Vec3, 3> cameraAxes(const lc::Scene& scene) {
    const double a = dynamic_cast<const lc::GodelCartesian&>(*scene.spacetime).a();
    const lc::godel::ObserverView view(a, scene.observer);
    const lc::LocalFrame frame = lc::LocalFrame::staticObserver(*scene.spacetime, scene.observer);
    std::array<lc::Vec3, 3> axes;
    for (int k = 0; k < 3; ++k)
        axes[static_cast<std::size_t>(k)] = view.vector(scene.observer, frame.e[k + 1]).tail<3>();
    return axes;
}

lc::Vec4 observerChartToWorld(const lc::Scene& scene, const lc::Vec4& x) {
    const double a = dynamic_cast<const lc::GodelCartesian&>(*scene.spacetime).a();
    return lc::godel::ObserverView(a, scene.observer).toWorld().apply(x);
}

std::string describePixel(const lc::Scene& scene, const lc::PixelRecord& p, int i, int j) {
    char line[320];
    switch (p.kind) {
        case lc::PixelRecord::Object: {
            const std::size_t k = static_cast<std::size_t>(p.object);
            const std::string name = p.object < 0               ? "?"
                                     : k < scene.spheres.size() ? scene.spheres[k].name
                                     : k - scene.spheres.size() < scene.meshes.size()
                                         ? scene.meshes[k - scene.spheres.size()].name
                                         : "?";
            // Goedel rays from a static observer return to it every 2 pi a of affine length (unit
            // energy), turning back at half of that: the winding and the branch of the light path.
            std::string path;
            if (hasClosedFormLightPaths(scene)) {
                const double period = 2 * lc::kPi * dynamic_cast<const lc::GodelCartesian&>(*scene.spacetime).a();
                const int winding = static_cast<int>(std::floor(p.affine / period));
                const bool outbound = p.affine - winding * period < 0.5 * period;
                path = " | winding " + std::to_string(winding) + (outbound ? ", outbound" : ", inbound");
            }
            std::snprintf(
                line, sizeof line,
                "pixel (%d, %d): object '%s'%s | emitted at t = %.4f | affine depth %.4f | nu_obs/nu_em = %.4f", i, j,
                name.c_str(), path.c_str(), p.emissionTime, p.affine, p.frequencyRatio);
            break;
        }
        case lc::PixelRecord::Sky:
            std::snprintf(line, sizeof line, "pixel (%d, %d): sky (u %.3f, v %.3f)", i, j, p.u, p.v);
            break;
        case lc::PixelRecord::Horizon: std::snprintf(line, sizeof line, "pixel (%d, %d): horizon", i, j); break;
        case lc::PixelRecord::Failed: std::snprintf(line, sizeof line, "pixel (%d, %d): ray failed", i, j); break;
        default:
            std::snprintf(line, sizeof line, "pixel (%d, %d): background (no object within %d windings)", i, j,
                          scene.settings.windings);
    }
    return line;
}

}  // namespace lcgui
