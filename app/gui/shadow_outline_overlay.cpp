// SPDX-License-Identifier: BSD-3-Clause
#include "shadow_outline_overlay.hpp"

#include "active_scene.hpp"
#include "egocentric_image_widget.hpp"
#include "render_controller.hpp"
#include "status_reporter.hpp"

#include "core/scene/frame_camera.hpp"

#include <QThread>

#include <cmath>

namespace lc::gui {
namespace {

// The outline's points as image coordinates, split where a point cannot be projected (behind a
// pinhole) or where the curve jumps across the image (a panorama's seam).
std::vector<std::vector<std::array<double, 2>>> imageCurves(const lc::Scene& scene, const lc::ShadowOutline& o) {
    const lc::Camera cam = lc::frameCamera(scene);
    std::vector<std::vector<std::array<double, 2>>> curves(1);
    const std::size_t n = o.points.size();
    for (std::size_t k = 0; k <= n; ++k) {  // the first point again: a closed loop
        double x = 0, y = 0;
        const bool seen = cam.project(o.points[k % n], x, y);
        auto& curve = curves.back();
        const bool jump = !curve.empty() && std::abs(x - curve.back()[0]) > 0.5 * cam.width;
        if (!seen || jump) {
            if (!curve.empty()) curves.emplace_back();
            if (!seen) continue;
        }
        curves.back().push_back({x, y});
    }
    return curves;
}

}  // namespace

ShadowOutlineOverlay::ShadowOutlineOverlay(ActiveScene* scene, RenderController* render, EgocentricImageWidget* image,
                                           StatusReporter* report, QObject* parent)
    : QObject(parent), scene_(scene), image_(image), report_(report) {
    // A new or edited scene: the old curve no longer belongs to the image; the next render's end
    // traces the new one.
    connect(scene_, &ActiveScene::changed, this, [this] {
        ++generation_;
        outline_.reset();
        image_->setCurves({});
    });
    connect(render, &RenderController::finished, this, [this] { trace(); });
}

ShadowOutlineOverlay::~ShadowOutlineOverlay() {
    if (thread_) thread_->wait();
}

void ShadowOutlineOverlay::setShown(bool on) {
    shown_ = on;
    if (on)
        trace();
    else {
        image_->setCurves({});
        outline_.reset();
    }
}

void ShadowOutlineOverlay::say(const QString& text) {
    message_ = text;
    report_->status(text);
}

void ShadowOutlineOverlay::trace() {
    if (!shown_ || !scene_->hasScene()) return;
    if (thread_) {  // one at a time; the newest scene is traced when this one ends
        again_ = true;
        return;
    }
    const lc::Scene& scene = scene_->scene().scene();
    if (!(scene.spacetime->asymptoticallyFlat() && scene.spacetime->hasHorizon())) {
        image_->setCurves({});
        outline_.reset();
        say("Shadow outline: " + QString::fromStdString(scene.spacetime->name()) +
            " casts no shadow (asymptotically flat metrics with a horizon do)");
        emit drawn();
        return;
    }
    traced_ = std::make_shared<const lc::Scene>(scene);
    tracedGeneration_ = generation_;
    result_ = std::make_shared<lc::ShadowOutline>();
    error_ = std::make_shared<QString>();
    auto s = traced_;
    auto result = result_;
    auto error = error_;
    thread_ = QThread::create([s, result, error] {
        try {
            *result = lc::traceShadowOutline(*s, kPoints, kTolerance);
        } catch (const std::exception& e) {
            *error = QString::fromStdString(e.what());
        }
    });
    connect(thread_, &QThread::finished, this, &ShadowOutlineOverlay::finish);
    say("Shadow outline: tracing...");
    thread_->start();
}

void ShadowOutlineOverlay::finish() {
    thread_->deleteLater();
    thread_ = nullptr;
    const bool stale = tracedGeneration_ != generation_;
    if (shown_ && !stale) {
        if (!error_->isEmpty()) {
            image_->setCurves({});
            outline_.reset();
            say("Shadow outline: " + *error_);
        } else {
            outline_ = result_;
            image_->setCurves(imageCurves(*traced_, *outline_));
            say(QString("Shadow outline: %1 points, solid angle %2 sr (%3 % of the sky)%4")
                    .arg(outline_->points.size())
                    .arg(outline_->solidAngle, 0, 'g', 6)
                    .arg(100 * outline_->solidAngle / (4 * lc::kPi), 0, 'f', 2)
                    .arg(outline_->fromSky ? ", traced from the sky's side" : ""));
        }
        emit drawn();
    }
    if (again_) {  // a render ended while this trace ran: trace its scene
        again_ = false;
        trace();
    }
}

}  // namespace lc::gui
