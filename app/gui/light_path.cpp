// SPDX-License-Identifier: BSD-3-Clause
#include "light_path.hpp"

#include "core/render/post_render.hpp"
#include "core/scene/frame_camera.hpp"
#include "core/godel/geodesic.hpp"
#include "core/godel/images.hpp"

#include <algorithm>
#include <cmath>
#include <vector>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>

namespace lc::gui {

bool hasClosedFormLightPaths(const lc::Scene& scene) {
    return scene.spacetime->godelRadius() && scene.observerVelocity.tail<3>().norm() == 0;
}

std::vector<lc::Vec4> lightPath(const lc::Scene& scene, int i, int j, double affine, int samples) {
    return lightPathAlong(scene, lc::frameCamera(scene).direction(i, j), affine, samples);
}

std::vector<lc::Vec4> lightPathAlong(const lc::Scene& scene, const lc::Vec3& n, double affine, int samples) {
    if (!hasClosedFormLightPaths(scene))
        throw std::invalid_argument("closed-form light paths need a Goedel scene and a static observer");
    const double a = *scene.spacetime->godelRadius();
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

PlanarRayHit nearestPlanarRay(const lc::Scene& scene, double x, double y) {
    if (!hasClosedFormLightPaths(scene))
        throw std::invalid_argument("closed-form light paths need a Goedel scene and a static observer");
    const double a = *scene.spacetime->godelRadius();
    const double period = 2 * lc::kPi * a;  // one closed loop; later windings retrace it
    auto distance = [&](double phi0, double l) {
        const lc::Vec4 p = lc::godel::OriginGeodesic::null(a, lc::kPi / 2, phi0, -1).cartesian(l);
        return std::hypot(p(1) - x, p(2) - y);
    };
    // A dense scan finds the stretches of rays near the point, a pattern search refines each. A
    // point inside the horizon lies on two fan rays (one meets it going out, the other coming
    // back): of the rays through it the one that reaches it first (least affine length) is taken.
    const int azimuths = 360, steps = 200;
    std::vector<PlanarRayHit> nearestPerAzimuth(azimuths);
    for (int k = 0; k < azimuths; ++k) {
        PlanarRayHit& best = nearestPerAzimuth[static_cast<std::size_t>(k)];
        best.distance = std::numeric_limits<double>::infinity();
        for (int s = 0; s < steps; ++s) {
            const double phi0 = 2 * lc::kPi * k / azimuths, l = period * s / steps, d = distance(phi0, l);
            if (d < best.distance) best = {lc::Vec3::UnitX(), phi0, l, d};
        }
    }
    auto refine = [&](PlanarRayHit hit) {
        for (double dp = 2 * lc::kPi / azimuths, dl = period / steps; dp > 1e-13;) {
            bool moved = false;
            for (int u = -1; u <= 1; ++u)
                for (int v = -1; v <= 1; ++v) {
                    const double phi0 = hit.phi0 + u * dp, l = std::clamp(hit.affine + v * dl, 0.0, period);
                    const double d = distance(phi0, l);
                    if (d < hit.distance) hit = {lc::Vec3::UnitX(), phi0, l, d}, moved = true;
                }
            if (!moved) dp *= 0.5, dl *= 0.5;
        }
        return hit;
    };
    // The azimuths of local minima of the scan (the basins), nearest first; the best few refined.
    std::vector<int> basins;
    for (int k = 0; k < azimuths; ++k) {
        const double d = nearestPerAzimuth[static_cast<std::size_t>(k)].distance;
        if (d <= nearestPerAzimuth[static_cast<std::size_t>((k + 1) % azimuths)].distance &&
            d <= nearestPerAzimuth[static_cast<std::size_t>((k + azimuths - 1) % azimuths)].distance)
            basins.push_back(k);
    }
    std::sort(basins.begin(), basins.end(), [&](int i, int j) {
        return nearestPerAzimuth[static_cast<std::size_t>(i)].distance <
               nearestPerAzimuth[static_cast<std::size_t>(j)].distance;
    });
    std::vector<PlanarRayHit> refined;
    for (std::size_t b = 0; b < std::min<std::size_t>(basins.size(), 4); ++b)
        refined.push_back(refine(nearestPerAzimuth[static_cast<std::size_t>(basins[b])]));
    double nearest = std::numeric_limits<double>::infinity();
    for (const PlanarRayHit& h : refined) nearest = std::min(nearest, h.distance);
    PlanarRayHit hit = refined.front();
    for (const PlanarRayHit& h : refined)  // through the point as nearly as the nearest: the first to get there
        if (h.distance <= nearest + 1e-9 * a && (hit.distance > nearest + 1e-9 * a || h.affine < hit.affine)) hit = h;
    hit.phi0 = std::remainder(hit.phi0, 2 * lc::kPi);
    // The observer's chart -> the camera's frame (lightPathAlong maps it back).
    const auto axes = cameraAxes(scene);
    Eigen::Matrix3d toChart;
    for (int k = 0; k < 3; ++k) toChart.col(k) = axes[static_cast<std::size_t>(k)];
    hit.direction = toChart.inverse() * lc::Vec3(std::cos(hit.phi0), std::sin(hit.phi0), 0);
    hit.direction.normalize();
    return hit;
}

std::pair<int, int> pixelOfDirection(const lc::Camera& camera, const lc::Vec3& direction) {
    double x = 0, y = 0;
    const bool inView = camera.project(direction, x, y) && x >= 0 && y >= 0 && x < camera.width && y < camera.height;
    return inView ? std::pair{static_cast<int>(x), static_cast<int>(y)} : std::pair{-1, -1};
}

std::array<lc::Vec3, 3> cameraAxes(const lc::Scene& scene) {
    const double a = scene.spacetime->godelRadius().value();
    return lc::godel::ObserverView(a, scene.observer).frameAxes();
}

lc::Vec4 observerChartToWorld(const lc::Scene& scene, const lc::Vec4& x) {
    const double a = scene.spacetime->godelRadius().value();
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
                const double period = 2 * lc::kPi * *scene.spacetime->godelRadius();
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
            std::snprintf(line, sizeof line, "pixel (%d, %d): %s (u %.3f, v %.3f)", i, j,
                          p.end ? "the far side's sky" : "sky", p.u, p.v);
            break;
        case lc::PixelRecord::Disk: {
            // The emission's radius, g, image order and temperatures: what the colour is made of.
            const bool known = p.object >= 0 && static_cast<std::size_t>(p.object) < scene.disks.size();
            const lc::DiskObject* d = known ? &scene.disks[static_cast<std::size_t>(p.object)] : nullptr;
            static const char* const kOrders[] = {"direct", "secondary", "tertiary"};
            const std::string order = p.order < 3 ? kOrders[p.order] : "order " + std::to_string(p.order);
            const double local =
                d ? lc::diskLocalTemperature<double>(d->temperature, p.intensity, p.frequencyRatio) : 0;
            std::snprintf(line, sizeof line,
                          "pixel (%d, %d): disk '%s', %s image | emitted at r = %.4f M, t = %.4f | nu_obs/nu_em = "
                          "%.4f | g^4 F/F_max = %.4g | T = %.0f K seen at %.0f K",
                          i, j, d ? d->name.c_str() : "?", order.c_str(), p.diskRadius, p.emissionTime,
                          p.frequencyRatio, p.intensity, local, local * p.frequencyRatio);
            break;
        }
        case lc::PixelRecord::Horizon: std::snprintf(line, sizeof line, "pixel (%d, %d): horizon", i, j); break;
        case lc::PixelRecord::Failed: std::snprintf(line, sizeof line, "pixel (%d, %d): ray failed", i, j); break;
        default:
            std::snprintf(line, sizeof line, "pixel (%d, %d): background (no object within %d windings)", i, j,
                          scene.settings.windings);
    }
    std::string text = line;
    // A render with ray bundles: the image element's lensing (0 where the ray met no source).
    if (scene.settings.magnification && p.magnification != 0) {
        std::snprintf(line, sizeof line, " | magnification %.4g, shear %.3g, rotation %.2f deg", p.magnification,
                      p.shear, p.rotation * 180 / lc::kPi);
        text += line;
    }
    return text;
}

std::string whyNoObjectIsSeen(const lc::Scene& scene, const lc::RenderResult& result) {
    const std::size_t objects = scene.spheres.size() + scene.meshes.size() + scene.disks.size();
    if (objects == 0) return "";
    for (const lc::PixelRecord& p : result.pixels)
        if (p.kind == lc::PixelRecord::Object || p.kind == lc::PixelRecord::Disk) return "";
    const std::optional<double> godelA = scene.spacetime->godelRadius();
    if (godelA && scene.meshes.empty() && scene.observerVelocity.tail<3>().norm() == 0) {
        const lc::godel::ObserverView view(*godelA, scene.observer);
        bool allBeyond = true;
        for (const lc::SphereObject& s : scene.spheres)
            allBeyond = allBeyond && view.images(s.centre.tail<3>(), std::max(scene.settings.windings, 0)).status ==
                                         lc::godel::ImageStatus::BeyondHorizon;
        if (allBeyond)
            return "No object is seen: every object lies beyond the observer's Goedel horizon (r >= 2a from the "
                   "observer), so no light from it reaches the observer. Move it or the observer closer.";
    }
    // Light from inside a black hole's horizon never reaches an observer outside it.
    const auto hidden = [&](const lc::Vec4& centre) {
        const lc::Boundary b = scene.spacetime->boundary(centre);
        return b == lc::Boundary::Horizon || b == lc::Boundary::Singularity;
    };
    bool allInside = scene.disks.empty() && scene.spacetime->boundary(scene.observer) == lc::Boundary::None;
    for (const lc::SphereObject& s : scene.spheres) allInside = allInside && hidden(s.centre);
    for (const lc::MeshObject& m : scene.meshes) allInside = allInside && hidden(m.centre);
    if (allInside)
        return "No object is seen: every object lies inside the metric's horizon, from where no light reaches the "
               "observer outside it. Move it out (a black hole's horizon: r <= M + sqrt(M^2 - a^2 - Q^2)).";
    return "No object is seen: none of the scene's " + std::to_string(objects) +
           " objects is in the camera's field of view (turn the camera, widen the field of view or use the "
           "panorama projection).";
}

}  // namespace lc::gui
