// SPDX-License-Identifier: BSD-3-Clause
#include "render_comparison.hpp"

#include "egocentric_image_widget.hpp"
#include "render_controller.hpp"
#include "status_reporter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lc::gui {
namespace {
constexpr int kGap = 4;               // pixels of grey between the two images side by side
constexpr float kGapGrey = 0.5f;      // linear
constexpr double kSameWithin = 1e-6;  // a channel difference below this is no difference
constexpr int kBlinkMilliseconds = 500;
constexpr const char* kNothingPinned = "Nothing to compare with";
constexpr const char* kPinFirst = "pin an image first (View > Compare > Pin this image)";
}  // namespace

RenderComparison::RenderComparison(RenderController* render, EgocentricImageWidget* image, StatusReporter* report,
                                   QObject* parent)
    : QObject(parent),
      render_(render),
      image_(image),
      report_(report),
      largest_(std::numeric_limits<double>::quiet_NaN()) {
    blink_.setInterval(kBlinkMilliseconds);
    connect(&blink_, &QTimer::timeout, this, [this] {
        blinkPinned_ = !blinkPinned_;
        if (blinkPinned_)
            image_->setImage(pinnedWidth_, pinnedHeight_, pinned_);
        else
            showCurrent();
    });
    // After the controller drew a new image of the scene: compare it in its turn.
    connect(render_, &RenderController::imageShown, this, [this] {
        if (mode_ != Off) compose();
    });
}

void RenderComparison::pin(const QString& label) {
    if (render_->shownImage().empty()) {
        report_->problem("Nothing to pin", "no image of the scene is shown yet");
        return;
    }
    report_->dismiss(QString(kNothingPinned) + ": " + kPinFirst);  // mended by this pin
    pinned_ = render_->shownImage();
    pinnedWidth_ = render_->shownWidth();
    pinnedHeight_ = render_->shownHeight();
    pinnedLabel_ = label;
    report_->status(QString("pinned %1 (%2 x %3) for View > Compare").arg(label).arg(pinnedWidth_).arg(pinnedHeight_));
    if (mode_ != Off) compose();
}

void RenderComparison::setMode(Mode mode) {
    if (mode != Off && pinned_.empty()) {
        report_->problem(kNothingPinned, kPinFirst);
        mode = Off;
    }
    mode_ = mode;
    blink_.stop();
    blinkPinned_ = false;
    if (mode_ == Off)
        showCurrent();
    else
        compose();
    emit modeChanged(mode_);
}

void RenderComparison::showCurrent() {
    if (render_->shownImage().empty()) return;
    image_->setImage(render_->shownWidth(), render_->shownHeight(), render_->shownImage());
}

void RenderComparison::compose() {
    const std::vector<float>& now = render_->shownImage();
    const int w = render_->shownWidth(), h = render_->shownHeight();
    if (now.empty()) return;
    if (mode_ == Blink) {
        if (!blink_.isActive()) blink_.start();
        if (!blinkPinned_) showCurrent();
        report_->status("blinking between this image and the pinned " + pinnedLabel_);
        return;
    }
    if (mode_ == SideBySide) {
        // This image on the left (picks land on its pixels), the pinned one on the right.
        const int width = w + kGap + pinnedWidth_, height = std::max(h, pinnedHeight_);
        std::vector<float> both(3 * static_cast<std::size_t>(width) * height, kGapGrey);
        auto copy = [&](const std::vector<float>& from, int fw, int fh, int x0) {
            for (int j = 0; j < fh; ++j)
                std::copy_n(from.begin() + 3 * static_cast<std::ptrdiff_t>(j) * fw, 3 * fw,
                            both.begin() + 3 * (static_cast<std::ptrdiff_t>(j) * width + x0));
        };
        copy(now, w, h, 0);
        copy(pinned_, pinnedWidth_, pinnedHeight_, w + kGap);
        image_->setImage(width, height, both);
        report_->status("left: this image; right: the pinned " + pinnedLabel_);
        return;
    }
    // Difference.
    if (w != pinnedWidth_ || h != pinnedHeight_) {
        report_->problem("No difference", QString("the pinned image is %1 x %2 pixels, this one %3 x %4")
                                              .arg(pinnedWidth_)
                                              .arg(pinnedHeight_)
                                              .arg(w)
                                              .arg(h));
        showCurrent();
        return;
    }
    std::vector<float> diff(now.size());
    largest_ = 0;
    differing_ = 0;
    for (std::size_t p = 0; p < now.size() / 3; ++p) {
        bool differs = false;
        for (int c = 0; c < 3; ++c) {
            const double d = std::abs(double(now[3 * p + c]) - double(pinned_[3 * p + c]));
            diff[3 * p + c] = static_cast<float>(d);
            largest_ = std::max(largest_, d);
            differs = differs || d > kSameWithin;
        }
        differing_ += differs;
    }
    if (largest_ > 0)
        for (float& d : diff) d = static_cast<float>(d / largest_);  // the largest shows white
    image_->setImage(w, h, diff);
    // In the message bar: the render's own status line comes right after a new image.
    report_->information(QString("|this image - pinned %1|: largest %2 (linear RGB), %3 of %4 pixels differ")
                             .arg(pinnedLabel_)
                             .arg(largest_, 0, 'g', 3)
                             .arg(differing_)
                             .arg(now.size() / 3));
}

}  // namespace lc::gui
