#include "lightconeGodelSession.h"

#include "core/frame.hpp"
#include "core/godel/geodesic.hpp"
#include "core/godel/images.hpp"
#include "core/metrics/godel.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace lcgui {

GodelSession::GodelSession(lc::Scene scene) : scene_(std::move(scene)) {
    const auto* godel = dynamic_cast<const lc::GodelCartesian*>(scene_.spacetime.get());
    if (!godel) throw std::invalid_argument("lightcone-gui needs a scene with the 'godel' metric");
    lc::requireStaticSpheres(scene_, "lightcone-gui");
    a_ = godel->a();
    forward0_ = scene_.camera.forward;
    scene_.settings.progress = false;
}

void GodelSession::setYawDegrees(double yaw) {
    yaw_ = yaw;
    const lc::Vec3 up = scene_.camera.up.normalized();
    scene_.camera.forward = Eigen::AngleAxisd(yaw * lc::kPi / 180, up) * forward0_;
}

void GodelSession::setWindings(int windings) {
    if (windings < 0) throw std::invalid_argument("windings must be >= 0");
    scene_.settings.windings = windings;
    scene_.settings.trace.maxAffine = (windings + 1) * 2 * lc::kPi * a_;
}

void GodelSession::render() {
    result_ = lc::renderGodelClosedForm(scene_);
    colours_ = lc::shadePixels(scene_, result_);
}

const lc::PixelRecord& GodelSession::pixel(int i, int j) const {
    if (i < 0 || j < 0 || i >= result_.width || j >= result_.height)
        throw std::out_of_range("pixel outside the image");
    return result_.pixels[static_cast<std::size_t>(j) * result_.width + i];
}

std::vector<lc::Vec4> GodelSession::lightPath(int i, int j, double affine, int samples) const {
    // The same ray as renderGodelClosedForm: the observer's static frame, moved to the origin.
    const lc::godel::ObserverView view(a_, scene_.observer);
    const lc::LocalFrame frame = lc::LocalFrame::staticObserver(*scene_.spacetime, scene_.observer);
    lc::Vec3 axes[3];
    for (int k = 0; k < 3; ++k) axes[k] = view.vector(scene_.observer, frame.e[k + 1]).tail<3>();
    const lc::Vec3 n = scene_.camera.direction(i, j);
    const lc::Vec3 d = (n(0) * axes[0] + n(1) * axes[1] + n(2) * axes[2]).normalized();
    const auto ray = lc::godel::OriginGeodesic::nullFromDirection(a_, d(2), std::hypot(d(0), d(1)),
                                                                  std::atan2(d(1), d(0)), -1);
    std::vector<lc::Vec4> path;
    samples = std::max(samples, 1);
    path.reserve(static_cast<std::size_t>(samples) + 1);
    for (int k = 0; k <= samples; ++k) path.push_back(ray.cartesian(affine * k / samples));
    return path;
}

lc::Vec4 GodelSession::toWorld(const lc::Vec4& x) const {
    return lc::godel::ObserverView(a_, scene_.observer).toWorld().apply(x);
}

std::string GodelSession::describe(int i, int j) const {
    const lc::PixelRecord& p = pixel(i, j);
    char line[256];
    switch (p.kind) {
    case lc::PixelRecord::Object: {
        const std::string name = p.object >= 0 && p.object < static_cast<int>(scene_.spheres.size())
                                     ? scene_.spheres[static_cast<std::size_t>(p.object)].name
                                     : "?";
        std::snprintf(line, sizeof line,
                      "pixel (%d, %d): object '%s' | emitted at t = %.4f | affine depth %.4f | nu_obs/nu_em = %.4f",
                      i, j, name.c_str(), p.emissionTime, p.affine, p.frequencyRatio);
        break;
    }
    case lc::PixelRecord::Sky: std::snprintf(line, sizeof line, "pixel (%d, %d): sky", i, j); break;
    case lc::PixelRecord::Horizon: std::snprintf(line, sizeof line, "pixel (%d, %d): horizon", i, j); break;
    case lc::PixelRecord::Failed: std::snprintf(line, sizeof line, "pixel (%d, %d): ray failed", i, j); break;
    default:
        std::snprintf(line, sizeof line, "pixel (%d, %d): background (no object within %d windings)", i, j,
                      scene_.settings.windings);
    }
    return line;
}

}  // namespace lcgui
