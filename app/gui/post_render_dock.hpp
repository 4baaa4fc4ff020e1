// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The post-rendering dock (seed 000 section 5.2): the CPU render's per-pixel data coloured again
// on the GPU (vtkLightconePostRenderer) while sliders move: another texture for the objects,
// its u offset (turn a sphere) and scale, a black-body temperature seen through each pixel's
// frequency ratio, a window of emission times over a second texture, blinking lights. Every
// change is one draw; nothing is traced again. `lightcone shade` writes the same images.
#include "core/render/post_render.hpp"
#include "core/scene/scene.hpp"
#include "core/render/special_relativity.hpp"
#include "readers/io/session_file.hpp"

#include <vtkSmartPointer.h>

#include <QMetaType>
#include <QWidget>

#include <memory>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;
class vtkLightconePostRenderer;

namespace lc::gui {

class PostRenderDock : public QWidget {
    Q_OBJECT
public:
    explicit PostRenderDock(QWidget* parent = nullptr);
    ~PostRenderDock() override;

    // The scene and its CPU render (per-pixel records); the controls' ranges follow the data
    // (emission times). Null: nothing to post-render, the controls are disabled.
    void setInput(const lc::Scene& scene, std::shared_ptr<const lc::ColouredImage> image);
    // The settings the controls describe now.
    lc::PostRender settings() const;
    // The controls as a session keeps them, and put back from one (to the sliders' steps); the
    // image follows as soon as there is data.
    lc::io::PostRenderControls controls() const;
    void setControls(const lc::io::PostRenderControls& controls);
    bool active() const;  // "Post-render" is checked and there is data
    double lastSeconds() const { return lastSeconds_; }
    const std::vector<unsigned char>& lastSrgb() const { return lastSrgb_; }

    QCheckBox* enableBox() const { return enable_; }
    QComboBox* textureChoice() const { return texture_; }
    QSlider* uOffsetSlider() const { return uOffset_; }
    QSlider* uScaleSlider() const { return uScale_; }
    QCheckBox* temperatureBox() const { return hot_; }
    QSlider* temperatureSlider() const { return temperature_; }
    QCheckBox* windowBox() const { return window_; }
    QSlider* windowStartSlider() const { return windowStart_; }
    QSlider* windowWidthSlider() const { return windowWidth_; }
    QComboBox* outsideChoice() const { return outside_; }
    QCheckBox* blinkBox() const { return blink_; }
    QSlider* blinkPhaseSlider() const { return blinkPhase_; }
    // The value a slider stands at, in its unit, as the label beside it shows it.
    QString valueText(const QSlider* slider) const;

signals:
    // A post-rendered image, linear RGB, row 0 on top (drawn after a change of the controls).
    void imageReady(int width, int height, const std::vector<float>& linearRgb);
    // "Post-render" was switched off: show the render itself again.
    void switchedOff();

private:
    void redraw();
    void describe();

    lc::Scene scene_;
    std::shared_ptr<const lc::ColouredImage> image_;
    double tMin_ = 0, tMax_ = 1;
    vtkSmartPointer<vtkLightconePostRenderer> renderer_;
    std::vector<unsigned char> lastSrgb_;
    double lastSeconds_ = 0;
    lc::TexturePtr checker_, stripes_;

    QCheckBox* enable_ = nullptr;
    QComboBox* texture_ = nullptr;
    QSlider *uOffset_ = nullptr, *uScale_ = nullptr;
    QCheckBox* hot_ = nullptr;
    QSlider* temperature_ = nullptr;
    QCheckBox* window_ = nullptr;
    QSlider *windowStart_ = nullptr, *windowWidth_ = nullptr;
    QComboBox* outside_ = nullptr;
    QCheckBox* blink_ = nullptr;
    QSlider* blinkPhase_ = nullptr;
    QLabel* summary_ = nullptr;
    std::vector<std::pair<QSlider*, QLabel*>> values_;  // each slider's value label
};

}  // namespace lc::gui

Q_DECLARE_METATYPE(std::vector<float>)
