// SPDX-License-Identifier: BSD-3-Clause
#include "observer_time_slider.hpp"

#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QTimer>

#include <cmath>

namespace lc::gui {
namespace {
constexpr double kSpan = 20;     // proper time either side of the file's event
constexpr int kTimeSteps = 400;  // 0.1 per step
}  // namespace

ObserverTimeSlider::ObserverTimeSlider(QWidget* parent)
    : QWidget(parent), slider_(new QSlider(Qt::Horizontal, this)), label_(new QLabel(this)), settle_(new QTimer(this)) {
    setObjectName("observerTimeSlider");
    slider_->setObjectName("observerTimeSliderBar");
    slider_->setRange(-kTimeSteps / 2, kTimeSteps / 2);
    slider_->setPageStep(10);
    slider_->setMinimumWidth(160);
    label_->setMinimumWidth(150);
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(6, 0, 6, 0);
    row->addWidget(new QLabel("observer time", this));
    row->addWidget(slider_);
    row->addWidget(label_);
    settle_->setSingleShot(true);
    settle_->setInterval(250);
    connect(slider_, &QSlider::valueChanged, this, [this] {
        showValue();
        if (!updating_) settle_->start();
    });
    connect(settle_, &QTimer::timeout, this, [this] { emit timeChosen(file_(0) + properTime() / rate_); });
    setEnabled(false);
    showValue();
}

double ObserverTimeSlider::properTime() const { return slider_->value() * (2 * kSpan / kTimeSteps); }

void ObserverTimeSlider::setScene(const lc::Scene& scene, const lc::Vec4& fileObserver) {
    file_ = fileObserver;
    const double gtt = scene.spacetime->metric(scene.observer)(0, 0);
    const bool usable = scene.observerVelocity.tail<3>().norm() == 0 && gtt > 0 &&
                        (scene.observer.tail<3>() - fileObserver.tail<3>()).norm() == 0;
    setEnabled(usable);
    setToolTip(usable ? QString("The static observer's proper time from the scene file's event: tau = sqrt(g_tt) "
                                "(t - t_file), %1 to %2 in steps of %3; one undoable edit of observer.position")
                            .arg(-kSpan)
                            .arg(kSpan)
                            .arg(2 * kSpan / kTimeSteps)
                      : QString("Off: the observer moves or has left the file's place (its proper time is "
                                "lightcone animate --proper-time)"));
    rate_ = usable ? std::sqrt(gtt) : 1;
    updating_ = true;  // showing the scene's time is no new choice
    slider_->setValue(static_cast<int>(std::lround((scene.observer(0) - file_(0)) * rate_ / (2 * kSpan / kTimeSteps))));
    updating_ = false;
    showValue();
}

void ObserverTimeSlider::showValue() {
    label_->setText(
        QString("tau = %1 (t = %2)").arg(properTime(), 0, 'f', 1).arg(file_(0) + properTime() / rate_, 0, 'f', 2));
}

}  // namespace lc::gui
