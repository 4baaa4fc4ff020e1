// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// How far to trust what the window shows: the CPU render's method, tolerance, time, worst
// null-condition drift |H| and stop reasons (the lines `lightcone render` prints, from
// app/commands/render_report.hpp), and the picked pixel's own ray: steps, drift, affine length and, for
// asymptotically flat metrics, its deflection and L_z/E (the ray traced again to
// escape, as `lightcone trace` does).
#include "core/render/render.hpp"
#include "core/scene/scene.hpp"

#include <QWidget>

class QLabel;

namespace lc::gui {

class AccuracyPanel : public QWidget {
    Q_OBJECT
public:
    explicit AccuracyPanel(QWidget* parent = nullptr);

    void showRender(const lc::Scene& scene, const lc::RenderResult& result);
    // Why there are no figures (rendering, cancelled, no scene).
    void showNoRender(const QString& why);
    void showPick(const lc::Scene& scene, const lc::PixelRecord& pixel, int i, int j);
    void clearPick();

    QString renderText() const;
    QString pickText() const;

private:
    QLabel* render_ = nullptr;
    QLabel* pick_ = nullptr;
};

// The picked pixel's ray in words: record figures, then (asymptotically flat metrics) the ray
// from the observer traced to escape with the scene's stepper and tolerance.
QString pixelRayFigures(const lc::Scene& scene, const lc::PixelRecord& pixel, int i, int j);

}  // namespace lc::gui
