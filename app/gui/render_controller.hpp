// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the egocentric image shows and how it got there: for each scene, the shader renderers'
// image at once where one draws the scene (views/), and the CPU render off the GUI thread
// (RenderJob) for the image elsewhere and the per-pixel data everywhere; the post-rendering dock's
// image while it is on. It greys the old image with "rendering..." at once, says why nothing is
// seen, and feeds the accuracy and post-rendering docks.
#include "render_job.hpp"

#include <QObject>
#include <QString>

#include <memory>
#include <vector>

class QAction;

namespace lc::gui {

class ActiveScene;
class StatusReporter;
class WorkbenchDocks;

class RenderController : public QObject {
    Q_OBJECT
public:
    RenderController(ActiveScene* scene, WorkbenchDocks* docks, StatusReporter* report, QObject* parent);

    void start();   // the active scene, again
    void cancel();  // the CPU render; what is shown stays
    bool rendering() const { return job_.running(); }
    RenderJob* renderJob() { return &job_; }
    // The CPU render of the current scene once it is done (null before): per-pixel records.
    const lc::ColouredImage* cpuImage() const { return cpu_.get(); }
    std::shared_ptr<const lc::ColouredImage> cpuImageShared() const { return cpu_; }
    // What the egocentric view shows: "shaders", "cpu" or "post-render".
    QString imageSource() const { return imageSource_; }
    const std::vector<float>& shownImage() const { return shown_; }
    int shownWidth() const { return shownWidth_; }
    int shownHeight() const { return shownHeight_; }
    double lastShaderSeconds() const { return shaderSeconds_; }
    bool shadersEnabled() const { return useShaders_; }
    void setShadersEnabled(bool on, bool renderAgain = true);
    // View > Image from shaders: kept checked as the controller decides.
    void setShadersAction(QAction* action) { shadersAction_ = action; }

signals:
    void shaderImageShown();
    void imageShown();  // a new image of the scene is in the egocentric view (shaders, CPU, post-render)
    void finished();    // the per-pixel data of the active scene is there
    void progressed(double fraction);
    void stopped();  // finished, cancelled or failed: no render runs

private:
    void showShaderImage(std::shared_ptr<const std::vector<lc::PhotoSceneObject>> photos);
    void onFinished(std::shared_ptr<const lc::ColouredImage> image);
    void show(int width, int height);  // shown_ into the egocentric view

    ActiveScene* scene_;
    WorkbenchDocks* docks_;
    StatusReporter* report_;
    RenderJob job_;
    std::shared_ptr<const lc::ColouredImage> cpu_;
    std::vector<float> shown_;
    int shownWidth_ = 0, shownHeight_ = 0;
    QString imageSource_;
    double shaderSeconds_ = 0;
    bool useShaders_ = true;
    QAction* shadersAction_ = nullptr;
};

}  // namespace lc::gui
