// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// View > Shadow outline: the black hole's shadow outline (lc::traceShadowOutline, docs/PHYSICS.md
// section 9b) drawn over the egocentric image, traced again off the GUI thread after every render
// of a scene that casts a shadow; its solid angle in the status bar. A scene without a shadow, or
// a camera that does not look at it, says why there and draws nothing.
#include "core/analysis/shadow.hpp"

#include <QObject>
#include <QString>

#include <memory>

class QAction;
class QThread;

namespace lc::gui {

class ActiveScene;
class EgocentricImageWidget;
class RenderController;
class StatusReporter;

class ShadowOutlineOverlay : public QObject {
    Q_OBJECT
public:
    // Points round the outline and the edges' relative tolerance: a curve smooth to a tenth of a
    // pixel at the image sizes the workbench shows, in about half a second on two cores.
    static constexpr int kPoints = 180;
    static constexpr double kTolerance = 1e-6;

    ShadowOutlineOverlay(ActiveScene* scene, RenderController* render, EgocentricImageWidget* image,
                         StatusReporter* report, QObject* parent = nullptr);
    ~ShadowOutlineOverlay() override;
    void setShown(bool on);
    bool shown() const { return shown_; }
    bool tracing() const { return thread_ != nullptr; }
    // The last outline drawn (nullptr when none) and what the status bar said about it.
    const lc::ShadowOutline* outline() const { return outline_.get(); }
    QString message() const { return message_; }

signals:
    void drawn();  // an outline is drawn, or the reason why none is said

private:
    void trace();
    void finish();
    void say(const QString& text);

    ActiveScene* scene_;
    EgocentricImageWidget* image_;
    StatusReporter* report_;
    bool shown_ = false, again_ = false;
    unsigned generation_ = 0, tracedGeneration_ = 0;
    QThread* thread_ = nullptr;
    std::shared_ptr<const lc::Scene> traced_;
    std::shared_ptr<lc::ShadowOutline> result_, outline_;
    std::shared_ptr<QString> error_;
    QString message_;
};

}  // namespace lc::gui
