// SPDX-License-Identifier: BSD-3-Clause
#include "render_controller.hpp"

#include "accuracy_panel.hpp"
#include "active_scene.hpp"
#include "egocentric_image_widget.hpp"
#include "light_path.hpp"
#include "post_render_dock.hpp"
#include "status_reporter.hpp"
#include "workbench_docks.hpp"

#include "app/commands/commands.hpp"
#include "core/render/photo_scene.hpp"

#include <QAction>
#include <QElapsedTimer>
#include <QLocale>
#include <QStringList>

namespace lc::gui {
namespace {
constexpr double kSlowShaderSeconds = 10;  // a shader image slower than this turns the shaders off
// The shader preview's photo-objects are an extra where the CPU image needs none (closed form):
// above this the workbench draws the CPU image only, and keeps to the command line's memory.
constexpr double kShaderPreviewBytes = 256e6;

// Why a Goedel scene gets no shader preview, or empty: its photo-objects would be too big, and the
// CPU render (closed form) does not need them. Estimated before anything is built.
QString photoObjectsTooBig(const lc::Scene& scene) {
    if (lc::resolveMethod(scene) == lc::RenderSettings::Method::PerVertex) return {};  // built for the CPU image anyway
    const double bytes = lc::photoSceneBytes(scene, lc::photoSceneOptions(scene));
    if (bytes <= kShaderPreviewBytes) return {};
    return QString(
               "no shader preview: its photo-objects (%1 objects) would take %2 MB, more than the %3 MB "
               "the workbench allows them")
        .arg(scene.spheres.size() + scene.meshes.size())
        .arg(bytes / 1e6, 0, 'f', 0)
        .arg(kShaderPreviewBytes / 1e6, 0, 'f', 0);
}
}  // namespace

RenderController::RenderController(ActiveScene* scene, WorkbenchDocks* docks, StatusReporter* report, QObject* parent)
    : QObject(parent), scene_(scene), docks_(docks), report_(report) {
    connect(&job_, &RenderJob::progressed, this, &RenderController::progressed);
    connect(&job_, &RenderJob::finished, this, &RenderController::onFinished);
    connect(&job_, &RenderJob::photoSceneReady, this,
            [this](std::shared_ptr<const std::vector<lc::PhotoSceneObject>> photos) {
                if (useShaders_) showShaderImage(std::move(photos));
            });
    connect(&job_, &RenderJob::cancelled, this, [this] {
        const QString why =
            "render cancelled: the per-pixel data of this scene is not traced (a pick, an edit or Ctrl+R traces it)";
        report_->status(why);
        if (imageSource_.isEmpty()) docks_->imageView()->setNotice(why, true);  // nothing of this scene shown yet
        docks_->accuracyPanel()->showNoRender(why);
        emit stopped();
    });
    connect(&job_, &RenderJob::failed, this, [this](const QString& message) {
        if (imageSource_.isEmpty()) docks_->imageView()->setNotice("render failed: " + message, true);
        report_->problem("Render failed", message);  // no dialog: an undo or a pick may have started it
        emit stopped();
    });
    PostRenderDock* post = docks_->postRenderView();
    connect(post, &PostRenderDock::imageReady, this,
            [this, post](int width, int height, const std::vector<float>& rgb) {
                shown_ = rgb;
                imageSource_ = "post-render";
                show(width, height);
                report_->status(QString("post-rendered on the GPU in %1 ms from the CPU's per-pixel data")
                                    .arg(post->lastSeconds() * 1e3, 0, 'f', 1));
            });
    connect(post, &PostRenderDock::switchedOff, this, [this] {
        if (!cpu_) return;
        shown_ = cpu_->rgb;
        imageSource_ = "cpu";
        show(cpu_->records.width, cpu_->records.height);
    });
}

void RenderController::cancel() { job_.cancel(); }

void RenderController::show(int width, int height) {
    shownWidth_ = width;
    shownHeight_ = height;
    docks_->imageView()->setImage(width, height, shown_);
    emit imageShown();
}

void RenderController::setShadersEnabled(bool on, bool renderAgain) {
    useShaders_ = on;
    if (shadersAction_) shadersAction_->setChecked(on);
    if (renderAgain && scene_->hasScene()) start();
}

void RenderController::start() {
    const lc::Scene& scene = scene_->scene().scene();
    imageSource_.clear();
    cpu_.reset();
    docks_->postRenderView()->setInput(scene, nullptr);    // the old data is not this scene's: none until traced
    docks_->imageView()->setNotice("rendering...", true);  // at once: the image below is the previous scene's
    lc::cli::ShaderPath path = useShaders_ ? lc::cli::shaderPathFor(scene) : lc::cli::ShaderPath::None;
    const QString noPreview = path == lc::cli::ShaderPath::Godel ? photoObjectsTooBig(scene) : QString();
    if (!noPreview.isEmpty()) path = lc::cli::ShaderPath::None;
    // Goedel: the photo-objects (CPU work) come from the worker; the GUI thread only draws them.
    if (path != lc::cli::ShaderPath::None && path != lc::cli::ShaderPath::Godel) showShaderImage(nullptr);
    // The CPU render always runs (off this thread): it is the image where no shader draws the
    // scene, and the per-pixel data behind picking everywhere.
    job_.start(scene, path == lc::cli::ShaderPath::Godel);
    emit progressed(0);
    docks_->accuracyPanel()->showNoRender("rendering on the CPU...");
    docks_->accuracyPanel()->clearPick();
    if (!noPreview.isEmpty())
        report_->status("rendering on the CPU... (" + noPreview + ")");
    else if (imageSource_.isEmpty())
        report_->status(path == lc::cli::ShaderPath::Godel ? "building the photo-objects..."
                                                           : "rendering on the CPU...");
}

void RenderController::showShaderImage(std::shared_ptr<const std::vector<lc::PhotoSceneObject>> photos) {
    const lc::Scene& scene = scene_->scene().scene();
    QElapsedTimer timer;
    timer.start();
    try {
        shown_ = lc::cli::renderShaderImage(scene, std::move(photos));
    } catch (const std::exception& e) {
        report_->status(QString("shader renderer: ") + e.what() + "; the CPU renderer draws the image");
        return;
    }
    shaderSeconds_ = timer.elapsed() / 1000.0;
    imageSource_ = "shaders";
    show(scene.camera.width, scene.camera.height);
    docks_->imageView()->setNotice("", false);
    emit shaderImageShown();
    report_->status(
        QString("shader image drawn in %1 s; tracing the per-pixel data on the CPU...").arg(shaderSeconds_, 0, 'f', 3));
    // The shaders draw on this thread: where OpenGL is software (llvmpipe) a heavy scene would
    // freeze the window at every edit. The CPU renderer, off this thread, takes over.
    if (shaderSeconds_ > kSlowShaderSeconds) {
        useShaders_ = false;
        if (shadersAction_) shadersAction_->setChecked(false);
        report_->status(QString("the shader image took %1 s on this OpenGL: images now come from the CPU renderer "
                                "(View > Image from shaders turns the shaders on again)")
                            .arg(shaderSeconds_, 0, 'f', 1));
    }
}

namespace {
// What the pixels show, in words: "1 234 pixels of objects, 66 992 of the disk".
QString pixelsSeen(const lc::RenderResult& r) {
    std::size_t objects = 0, disk = 0;
    for (const lc::PixelRecord& p : r.pixels) {
        objects += p.kind == lc::PixelRecord::Object;
        disk += p.kind == lc::PixelRecord::Disk;
    }
    const QLocale readable(QLocale::English);
    auto count = [&](std::size_t n) { return readable.toString(static_cast<qulonglong>(n)).replace(',', ' '); };
    if (objects == 0 && disk == 0) return "no object or disk seen";
    QStringList parts;
    if (objects > 0) parts << count(objects) + " pixels of objects";
    if (disk > 0) parts << count(disk) + (objects > 0 ? " of the disk" : " pixels of the disk");
    return parts.join(", ");
}
}  // namespace

void RenderController::onFinished(std::shared_ptr<const lc::ColouredImage> image) {
    cpu_ = std::move(image);
    const lc::RenderResult& r = cpu_->records;
    const lc::Scene& scene = scene_->scene().scene();
    if (imageSource_ != "shaders") {
        shown_ = cpu_->rgb;
        imageSource_ = "cpu";
        show(r.width, r.height);
    }
    docks_->imageView()->setNotice(QString::fromStdString(whyNoObjectIsSeen(scene, r)), false);
    docks_->postRenderView()->setInput(scene, cpu_);  // draws at once when post-rendering is on
    docks_->accuracyPanel()->showRender(scene, r);
    report_->status(QString("rendered %1 x %2 on the CPU in %3 s (%4): %5; image from %6")
                        .arg(r.width)
                        .arg(r.height)
                        .arg(r.stats.seconds, 0, 'f', 2)
                        .arg(QString::fromStdString(lc::renderMethodName(lc::resolveMethod(scene))))
                        .arg(pixelsSeen(r))
                        .arg(imageSource_));
    emit stopped();
    emit finished();
}

}  // namespace lc::gui
