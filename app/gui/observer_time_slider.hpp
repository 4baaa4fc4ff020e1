// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The observer's proper time as a slider in the workbench's tool bar: it moves a static observer
// along its own world line (the orbit of d/dt: tau = sqrt(g_tt) (t - t_file)), 20 units either
// side of the scene file's event, and says where it is. Choosing a time is one undoable edit of
// observer.position (MainWindow::editScene), so sessions keep it. A moving observer's time is
// animate's --proper-time: the slider is off for it, saying why.
#include "core/scene/scene.hpp"

#include <QWidget>

class QLabel;
class QSlider;
class QTimer;

namespace lc::gui {

class ObserverTimeSlider : public QWidget {
    Q_OBJECT
public:
    explicit ObserverTimeSlider(QWidget* parent = nullptr);
    // The scene as edited and the observer event of its file (where tau = 0).
    void setScene(const lc::Scene& scene, const lc::Vec4& fileObserver);
    QSlider* slider() const { return slider_; }
    double properTime() const;  // of the slider's position

signals:
    // The coordinate time of the observer's event at the chosen proper time (after the slider
    // has rested 250 ms, so a drag is one edit).
    void timeChosen(double t);

private:
    void showValue();
    QSlider* slider_;
    QLabel* label_;
    QTimer* settle_;
    lc::Vec4 file_ = lc::Vec4::Zero();
    double rate_ = 1;  // sqrt(g_tt) at the observer: dtau / dt
    bool updating_ = false;
};

}  // namespace lc::gui
