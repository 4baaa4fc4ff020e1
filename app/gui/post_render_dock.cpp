// SPDX-License-Identifier: BSD-3-Clause
#include "post_render_dock.hpp"

#include "vtkLightconePostRenderer.h"

#include "core/colour/srgb.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace lc::gui {

namespace {
QSlider* slider(int maximum, int value) {
    auto* s = new QSlider(Qt::Horizontal);
    s->setRange(0, maximum);
    s->setValue(value);
    return s;
}
constexpr int kSliderSteps = 1000;  // slider resolution
// The temperature slider's value in K: 1000 K + 29 K a step, 1000 to 30000 K.
double sliderTemperature(int value) { return 1000.0 + 29.0 * value; }
}  // namespace

PostRenderDock::PostRenderDock(QWidget* parent)
    : QWidget(parent),
      checker_(std::make_shared<lc::CheckerTexture>(16, 8, lc::Vec3(0.95, 0.95, 0.9), lc::Vec3(0.1, 0.35, 0.8))),
      stripes_(std::make_shared<lc::CheckerTexture>(24, 1, lc::Vec3(1.0, 0.25, 0.1), lc::Vec3(0.1, 0.1, 0.1))) {
    auto* form = new QFormLayout;
    enable_ = new QCheckBox("Post-render the CPU data (no tracing)");
    texture_ = new QComboBox;
    texture_->addItems({"the scene's", "checker", "stripes"});
    uOffset_ = slider(kSliderSteps, 0);
    uScale_ = slider(8, 1);
    uScale_->setMinimum(1);
    hot_ = new QCheckBox("black body");
    temperature_ = slider(kSliderSteps, 300);  // 1000 K + 29 K a step: 1000 to 30000 K
    window_ = new QCheckBox("emission times");
    windowStart_ = slider(kSliderSteps, 0);
    windowWidth_ = slider(kSliderSteps, kSliderSteps / 4);
    outside_ = new QComboBox;
    outside_->addItems({"nothing (background)", "checker", "stripes"});
    blink_ = new QCheckBox("blinking, period = 1/4 of the emission times");
    blinkPhase_ = slider(kSliderSteps, 0);
    summary_ = new QLabel;
    summary_->setWordWrap(true);
    // Each slider with its value beside it, in its unit.
    auto withValue = [this](QSlider* s) {
        auto* row = new QWidget;
        auto* line = new QHBoxLayout(row);
        line->setContentsMargins(0, 0, 0, 0);
        auto* value = new QLabel;
        value->setMinimumWidth(value->fontMetrics().horizontalAdvance("window 0.000 to 0.000"));
        line->addWidget(s, 1);
        line->addWidget(value);
        values_.push_back({s, value});
        return row;
    };
    form->addRow(enable_);
    form->addRow("texture", texture_);
    form->addRow("u offset (turn)", withValue(uOffset_));
    form->addRow("u, v repeats", withValue(uScale_));
    form->addRow(hot_, withValue(temperature_));
    form->addRow(window_, withValue(windowStart_));
    form->addRow("window width", withValue(windowWidth_));
    form->addRow("outside the window", outside_);
    form->addRow(blink_);
    form->addRow("blink phase", withValue(blinkPhase_));
    form->addRow(summary_);
    setLayout(form);
    for (QSlider* s : {uOffset_, uScale_, temperature_, windowStart_, windowWidth_, blinkPhase_})
        connect(s, &QSlider::valueChanged, this, &PostRenderDock::redraw);
    for (QCheckBox* b : {hot_, window_, blink_}) connect(b, &QCheckBox::toggled, this, &PostRenderDock::redraw);
    for (QComboBox* c : {texture_, outside_})
        connect(c, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &PostRenderDock::redraw);
    connect(enable_, &QCheckBox::toggled, this, [this](bool on) {
        if (on)
            redraw();
        else
            emit switchedOff();
    });
    setInput(lc::Scene{}, nullptr);
}

PostRenderDock::~PostRenderDock() = default;

void PostRenderDock::setInput(const lc::Scene& scene, std::shared_ptr<const lc::ColouredImage> image) {
    scene_ = scene;
    image_ = std::move(image);
    tMin_ = 0;
    tMax_ = 1;
    if (image_) {
        bool any = false;
        for (const auto& p : image_->records.pixels)
            if (p.kind == lc::PixelRecord::Object) {
                tMin_ = any ? std::min(tMin_, double(p.emissionTime)) : p.emissionTime;
                tMax_ = any ? std::max(tMax_, double(p.emissionTime)) : p.emissionTime;
                any = true;
            }
        if (!(tMax_ > tMin_)) tMax_ = tMin_ + 1;
        if (!renderer_) renderer_ = vtkSmartPointer<vtkLightconePostRenderer>::New();
        try {
            renderer_->SetInput(scene_, image_->records);
        } catch (const std::exception& e) {
            image_.reset();
            summary_->setText(QString("cannot post-render: ") + e.what());
        }
    }
    for (QWidget* w : std::initializer_list<QWidget*>{enable_, texture_, uOffset_, uScale_, hot_, temperature_, window_,
                                                      windowStart_, windowWidth_, outside_, blink_, blinkPhase_})
        w->setEnabled(image_ != nullptr);
    if (!image_) summary_->setText("post-rendering needs the CPU render's per-pixel data (it follows each render)");
    if (active()) redraw();
}

bool PostRenderDock::active() const { return image_ && enable_->isChecked(); }

lc::PostRender PostRenderDock::settings() const {
    lc::PostRender p;
    const std::size_t objects = lc::objectCount(scene_);
    const lc::TexturePtr choices[3] = {nullptr, checker_, stripes_};
    if (texture_->currentIndex() > 0) p.objectTextures.assign(objects, choices[texture_->currentIndex()]);
    p.uOffset = double(uOffset_->value()) / kSliderSteps;
    p.uScale = p.vScale = uScale_->value();
    if (hot_->isChecked()) p.temperature = sliderTemperature(temperature_->value());
    const double span = tMax_ - tMin_;
    if (window_->isChecked()) {
        const double t0 = tMin_ + span * windowStart_->value() / kSliderSteps;
        p.timeWindow = std::make_pair(t0, t0 + span * windowWidth_->value() / kSliderSteps);
        p.outsideTexture = outside_->currentIndex() > 0 ? choices[outside_->currentIndex()] : nullptr;
    }
    if (blink_->isChecked()) {
        p.blinkPeriod = 0.25 * span;
        p.blinkPhase = tMin_ + p.blinkPeriod * blinkPhase_->value() / kSliderSteps;
    }
    return p;
}

namespace {
const char* const kTextureWords[] = {"scene", "checker", "stripes"};
const char* const kOutsideWords[] = {"background", "checker", "stripes"};
int indexOf(const char* const (&words)[3], const std::string& word) {
    for (int k = 0; k < 3; ++k)
        if (word == words[k]) return k;
    return 0;
}
int steps(double fraction) { return static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * kSliderSteps)); }
}  // namespace

lc::io::PostRenderControls PostRenderDock::controls() const {
    lc::io::PostRenderControls c;
    c.enabled = enable_->isChecked();
    c.texture = kTextureWords[std::clamp(texture_->currentIndex(), 0, 2)];
    c.uOffset = double(uOffset_->value()) / kSliderSteps;
    c.repeats = uScale_->value();
    if (hot_->isChecked()) c.temperature = sliderTemperature(temperature_->value());
    if (window_->isChecked()) {
        c.timeWindow = std::array<double, 2>{double(windowStart_->value()) / kSliderSteps,
                                             double(windowWidth_->value()) / kSliderSteps};
        c.outside = kOutsideWords[std::clamp(outside_->currentIndex(), 0, 2)];
    }
    if (blink_->isChecked()) c.blinkPhase = double(blinkPhase_->value()) / kSliderSteps;
    return c;
}

void PostRenderDock::setControls(const lc::io::PostRenderControls& c) {
    {
        const QSignalBlocker blockers[] = {
            QSignalBlocker(enable_),  QSignalBlocker(texture_),     QSignalBlocker(uOffset_),
            QSignalBlocker(uScale_),  QSignalBlocker(hot_),         QSignalBlocker(temperature_),
            QSignalBlocker(window_),  QSignalBlocker(windowStart_), QSignalBlocker(windowWidth_),
            QSignalBlocker(outside_), QSignalBlocker(blink_),       QSignalBlocker(blinkPhase_)};
        texture_->setCurrentIndex(indexOf(kTextureWords, c.texture));
        uOffset_->setValue(steps(c.uOffset));
        uScale_->setValue(c.repeats);
        hot_->setChecked(c.temperature.has_value());
        if (c.temperature) temperature_->setValue(static_cast<int>(std::lround((*c.temperature - 1000.0) / 29.0)));
        window_->setChecked(c.timeWindow.has_value());
        if (c.timeWindow) {
            windowStart_->setValue(steps((*c.timeWindow)[0]));
            windowWidth_->setValue(steps((*c.timeWindow)[1]));
        }
        outside_->setCurrentIndex(indexOf(kOutsideWords, c.outside));
        blink_->setChecked(c.blinkPhase.has_value());
        if (c.blinkPhase) blinkPhase_->setValue(steps(*c.blinkPhase));
    }
    enable_->setChecked(c.enabled);  // draws (or shows the render again) through its signal
    describe();
}

void PostRenderDock::redraw() {
    describe();
    if (!active()) return;
    QElapsedTimer timer;
    timer.start();
    try {
        renderer_->SetPostRender(settings());
        lastSrgb_ = renderer_->RenderSrgb();
    } catch (const std::exception& e) {
        summary_->setText(QString("cannot post-render: ") + e.what());
        return;
    }
    lastSeconds_ = timer.nsecsElapsed() * 1e-9;
    std::vector<float> linear(lastSrgb_.size());
    for (std::size_t k = 0; k < linear.size(); ++k) linear[k] = float(lc::colour::srgbDecode(lastSrgb_[k] / 255.0));
    summary_->setText(summary_->text() + QString("\ndrawn on the GPU in %1 ms").arg(lastSeconds_ * 1e3, 0, 'f', 1));
    emit imageReady(image_->records.width, image_->records.height, linear);
}

QString PostRenderDock::valueText(const QSlider* slider) const {
    const double f = double(slider->value()) / kSliderSteps;
    if (slider == uOffset_) return QString("%1 turn").arg(f, 0, 'f', 3);
    if (slider == uScale_) return QString("%1 x").arg(slider->value());
    if (slider == temperature_) return QString("%1 K").arg(sliderTemperature(slider->value()), 0, 'f', 0);
    // Fractions of the rendered objects' emission times, as coordinate times.
    const double t = tMin_ + f * (tMax_ - tMin_);
    if (slider == windowStart_) return QString("from t = %1").arg(t, 0, 'g', 4);
    if (slider == windowWidth_) return QString("%1 of t").arg(f * (tMax_ - tMin_), 0, 'g', 4);
    if (slider == blinkPhase_) return QString("%1 period").arg(f, 0, 'f', 3);
    return QString();
}

// What the controls mean in physical units, beside the sliders and under them.
void PostRenderDock::describe() {
    for (const auto& [slider, label] : values_) label->setText(valueText(slider));
    if (!image_) return;
    const lc::PostRender p = settings();
    QString text = QString("u offset %1 turn, %2 repeats").arg(p.uOffset, 0, 'f', 3).arg(p.uScale);
    if (p.temperature) text += QString("; T = %1 K seen at D T").arg(*p.temperature, 0, 'f', 0);
    if (p.timeWindow)
        text += QString("; light emitted at t in [%1, %2] (data: %3 to %4)")
                    .arg(p.timeWindow->first, 0, 'g', 4)
                    .arg(p.timeWindow->second, 0, 'g', 4)
                    .arg(tMin_, 0, 'g', 4)
                    .arg(tMax_, 0, 'g', 4);
    if (p.blinkPeriod > 0)
        text += QString("; blinking every %1 from t = %2").arg(p.blinkPeriod, 0, 'g', 4).arg(p.blinkPhase, 0, 'g', 4);
    summary_->setText(text);
}

}  // namespace lc::gui
