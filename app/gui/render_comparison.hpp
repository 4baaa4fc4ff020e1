// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// View > Compare: pin the image shown now, then see the scene's later images beside it (the
// current one on the left, where picks still land on their pixels), as their difference (|a - b|
// per channel, stretched so the largest shows white; the status bar gives the largest and how many
// pixels differ) or blinking between the two twice a second. Each new image of the scene
// (an edit's render, post-rendering) is compared as it comes.
#include <QObject>
#include <QString>
#include <QTimer>

#include <vector>

namespace lc::gui {

class EgocentricImageWidget;
class RenderController;
class StatusReporter;

class RenderComparison : public QObject {
    Q_OBJECT
public:
    enum Mode { Off, SideBySide, Difference, Blink };
    RenderComparison(RenderController* render, EgocentricImageWidget* image, StatusReporter* report,
                     QObject* parent = nullptr);

    // The image shown now becomes the reference; `label` says what it was (the status bar's).
    void pin(const QString& label);
    bool hasPinned() const { return !pinned_.empty(); }
    void setMode(Mode mode);
    Mode mode() const { return mode_; }
    // The largest channel difference and the differing pixels of the last Difference (NaN / -1
    // before one).
    double largestDifference() const { return largest_; }
    long differingPixels() const { return differing_; }
    bool blinkShowsPinned() const { return blinkPinned_; }

signals:
    void modeChanged(int mode);

private:
    void compose();
    void showCurrent();

    RenderController* render_;
    EgocentricImageWidget* image_;
    StatusReporter* report_;
    std::vector<float> pinned_;
    int pinnedWidth_ = 0, pinnedHeight_ = 0;
    QString pinnedLabel_;
    Mode mode_ = Off;
    QTimer blink_;
    bool blinkPinned_ = false;
    double largest_;
    long differing_ = -1;
};

}  // namespace lc::gui
