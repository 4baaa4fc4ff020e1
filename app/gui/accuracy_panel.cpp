// SPDX-License-Identifier: BSD-3-Clause
#include "accuracy_panel.hpp"

#include "app/commands/render_report.hpp"
#include "core/scene/frame_camera.hpp"
#include "core/scene/observer_ray.hpp"
#include "core/spacetime/scattering.hpp"

#include <QFileInfo>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

#include <cmath>

namespace lc::gui {

AccuracyPanel::AccuracyPanel(QWidget* parent) : QWidget(parent) {
    setObjectName("accuracyPanel");
    // In a scroll area: new figures never resize the dock (and so never move the other views).
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // the lines wrap to the dock's width
    outer->addWidget(scroll);
    auto* content = new QWidget(scroll);
    auto* layout = new QVBoxLayout(content);
    layout->setContentsMargins(6, 4, 6, 4);
    render_ = new QLabel(content);
    render_->setObjectName("renderFigures");
    pick_ = new QLabel(content);
    pick_->setObjectName("pickFigures");
    for (QLabel* l : {render_, pick_}) {
        l->setWordWrap(true);
        l->setTextInteractionFlags(Qt::TextSelectableByMouse);
        layout->addWidget(l);
    }
    layout->addStretch(1);
    scroll->setWidget(content);
    showNoRender("no scene: File > Open scene");
    clearPick();
}

namespace {
// What a stop reason of the report's "stops:" line means, for a reader who did not write the tracer.
const char* stopMeaning(lc::StopReason reason) {
    switch (reason) {
        case lc::StopReason::Escaped: return "the ray left for the sky (past the escape radius)";
        case lc::StopReason::Horizon: return "it fell through a horizon: the shadow";
        case lc::StopReason::MaxAffine:
            return "still travelling at the render's affine limit (render.max_affine): no sky at infinity here, or a "
                   "long orbit";
        case lc::StopReason::MaxSteps: return "it ran out of steps (render.max_steps) first";
        case lc::StopReason::ConstraintBlowUp:
            return "the null condition |H| grew past its bound: the integration failed (tighten the tolerance)";
        case lc::StopReason::Singularity: return "it reached the metric's singularity";
        case lc::StopReason::StepUnderflow: return "the step fell below its floor at a sharp feature";
        case lc::StopReason::Hit: return "it met an object or the disk";
        case lc::StopReason::OtherEnd: return "it reached the other asymptotic end (a wormhole's far side)";
    }
    return "";
}
}  // namespace

void AccuracyPanel::showRender(const lc::Scene& scene, const lc::RenderResult& result) {
    QString text = "CPU render\n";
    for (const std::string& line : lc::cli::renderReport(scene, result).lines())
        text += QString::fromStdString(line) + "\n";
    // The stops in words, those that occurred.
    for (std::size_t k = 0; k < result.stats.stopCounts.size(); ++k)
        if (result.stats.stopCounts[k] > 0) {
            const auto reason = static_cast<lc::StopReason>(k);
            text +=
                QString("  %1: %2\n").arg(QString::fromStdString(lc::stopReasonName(reason))).arg(stopMeaning(reason));
        }
    // The scene's file name is enough here (the title bar has it; paths do not wrap).
    text.replace(QString::fromStdString(scene.source), QFileInfo(QString::fromStdString(scene.source)).fileName());
    render_->setText(text.trimmed());
}

void AccuracyPanel::showNoRender(const QString& why) { render_->setText("CPU render\n" + why); }

void AccuracyPanel::showPick(const lc::Scene& scene, const lc::PixelRecord& pixel, int i, int j) {
    pick_->setText(pixelRayFigures(scene, pixel, i, j));
}

void AccuracyPanel::clearPick() { pick_->setText("Picked ray\nclick a pixel of the image for its ray's figures"); }

QString AccuracyPanel::renderText() const { return render_->text(); }
QString AccuracyPanel::pickText() const { return pick_->text(); }

QString pixelRayFigures(const lc::Scene& scene, const lc::PixelRecord& pixel, int i, int j) {
    QString text = QString("Picked ray, pixel (%1, %2)\n").arg(i).arg(j);
    if (pixel.steps > 0)
        text += QString("as rendered: %1 steps, |H| drift %2, affine length %3\n")
                    .arg(pixel.steps)
                    .arg(pixel.drift, 0, 'e', 2)
                    .arg(pixel.affine, 0, 'g', 6);
    else
        text += QString("as rendered: closed form or special relativity (exact, no integration), affine length %1\n")
                    .arg(pixel.affine, 0, 'g', 6);
    if (pixel.kind == lc::PixelRecord::Disk) {
        const int order = pixel.order;
        text += QString(
                    "the ray meets the accretion disk at r = %1 M (Boyer-Lindquist): the %2 image (it crossed the "
                    "equatorial plane %3 time%4 before), g = nu_obs/nu_em = %5\n")
                    .arg(pixel.diskRadius, 0, 'g', 6)
                    .arg(order == 0   ? "direct"
                         : order == 1 ? "secondary"
                                      : "higher-order")
                    .arg(order)
                    .arg(order == 1 ? "" : "s")
                    .arg(pixel.frequencyRatio, 0, 'g', 6);
    } else if (pixel.kind == lc::PixelRecord::Object) {
        text += QString("the ray meets object %1 at affine depth %2, g = nu_obs/nu_em = %3\n")
                    .arg(pixel.object)
                    .arg(pixel.affine, 0, 'g', 6)
                    .arg(pixel.frequencyRatio, 0, 'g', 6);
    }
    const lc::Spacetime& st = *scene.spacetime;
    if (!st.asymptoticallyFlat()) return text;
    // The same ray from the observer, followed to escape: what it went through on its way.
    lc::PhasePoint start;
    start.x = scene.observer;
    start.p = lc::observerFrame(scene).pastNullMomentum(st, lc::frameCamera(scene).direction(i, j));
    lc::TraceOptions options = scene.settings.trace;
    options.escapeRadius = lc::escapeRadiusForRayFrom(scene.observer);
    const bool hit = pixel.kind == lc::PixelRecord::Disk || pixel.kind == lc::PixelRecord::Object;
    try {
        const lc::DeflectionResult d = lc::measureDeflection(st, start, options);
        // d.impact is p_phi / p_t in the (+,-,-,-) signature the tracer computes in, the same for the
        // traced (past) momentum and the light's: the literature's L_z / E (-,+,+,+: L_z = p_phi,
        // E = -p_t) is its negative.
        text +=
            QString(
                "%1: %2, %3 steps, |H| drift %4, L_z/E = %5 M (the arriving light's impact parameter "
                "about the chart's z axis, L_z = p_phi and E = -p_t in the (-,+,+,+) convention: positive "
                "counter-clockwise about +z, prograde for a Kerr hole of a > 0)")
                .arg(hit ? "followed on past the hit, as if the objects and disk were not there" : "traced to the end")
                .arg(QString::fromStdString(lc::stopReasonName(d.trace.reason)))
                .arg(d.trace.steps)
                .arg(d.trace.maxHamiltonianDrift, 0, 'e', 2)
                .arg(-d.impact, 0, 'g', 8);
        if (d.trace.reason == lc::StopReason::Escaped)
            text += QString(", deflection %1 rad (%2 deg)")
                        .arg(d.deflection, 0, 'g', 8)
                        .arg(d.deflection * 180 / lc::kPi, 0, 'f', 3);
    } catch (const std::exception& e) {
        text += QString("traced to the end: not possible here (%1)").arg(e.what());
    }
    return text;
}

}  // namespace lc::gui
