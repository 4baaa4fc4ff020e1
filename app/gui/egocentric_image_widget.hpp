// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The egocentric image as a vtkImageData in a vtkImageActor (one pixel = one unit, so picked
// positions map exactly to pixels), with a parallel camera that fits the image. A left click
// emits pixelPicked(i, j) with row j = 0 at the top, as in lc::RenderResult; a left drag moves
// the image with the hand while it lasts (the live preview) and emits dragged(dx, dy) in image
// pixels when released (the window turns the camera by it), the wheel
// zoomed(+1 in / -1 out), and the pointer over the image pixelHovered(i, j).
#include <QPoint>
#include <QPointF>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkActor.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <QString>

#include <array>
#include <vector>

class vtkObject;

namespace lc::gui {

class EgocentricImageWidget : public QVTKOpenGLNativeWidget {
    Q_OBJECT
public:
    explicit EgocentricImageWidget(QWidget* parent = nullptr);
    ~EgocentricImageWidget() override;

    // Linear RGB, row 0 on top (lc::shadePixels); shown sRGB-encoded.
    void setImage(int width, int height, const std::vector<float>& linearRgb);
    int imageWidth() const { return width_; }
    int imageHeight() const { return height_; }
    // The 8-bit colour drawn at pixel (i, j) (row 0 on top) of the image shown.
    std::array<unsigned char, 3> shownColour(int i, int j) const;

    // VTK display coordinates (origin bottom left) -> pixel; false outside the image.
    bool pixelAtDisplay(double x, double y, int& i, int& j) const;
    // Centre of pixel (i, j) in Qt widget coordinates (origin top left), e.g. for QTest clicks.
    // Valid once the widget has been rendered at its current size.
    QPoint widgetPointOfPixel(int i, int j) const;

    // Draws a marker (a small ring) on pixel (i, j); (-1, -1) removes it.
    void markPixel(int i, int j);
    // Draws curves over the image (the shadow's outline): each a polyline of continuous image
    // coordinates (x right, y down, pixel (i, j) covering [i, i+1) x [j, j+1)); empty removes them.
    void setCurves(const std::vector<std::vector<std::array<double, 2>>>& curves);
    const std::vector<std::vector<std::array<double, 2>>>& curves() const { return curves_; }

    // A sentence over the image ("rendering...", why nothing is seen); `dim` greys the image below
    // it (an image that is no longer the scene's). An empty text removes both.
    void setNotice(const QString& text, bool dim);
    QString notice() const { return notice_; }
    bool dimmed() const;
    // How far the image is shifted by a drag's live preview (image pixels, rows down); (0, 0)
    // once an image is set.
    QPointF dragPreviewShift() const;
    // The image back in its place (a drag whose turn was refused renders nothing new).
    void clearDragPreview();

signals:
    void pixelPicked(int i, int j);
    void pixelHovered(int i, int j);
    void dragged(double dx, double dy);
    void zoomed(int steps);

private:
    void onLeftButtonPress(vtkObject* caller, unsigned long event, void* data);
    void onLeftButtonRelease(vtkObject* caller, unsigned long event, void* data);
    void onMouseMove(vtkObject* caller, unsigned long event, void* data);
    void onWheel(vtkObject* caller, unsigned long event, void* data);
    bool imagePointAtDisplay(double x, double y, double& u, double& v) const;
    void fitCamera(vtkObject* caller, unsigned long event, void* data);

    vtkNew<vtkRenderer> renderer_;
    vtkNew<vtkImageData> image_;
    vtkNew<vtkImageActor> actor_;
    vtkNew<vtkActor> marker_;
    vtkNew<vtkActor> curvesActor_;
    std::vector<std::vector<std::array<double, 2>>> curves_;
    vtkNew<vtkTextActor> noticeActor_;
    QString notice_;
    int width_ = 0, height_ = 0;
    bool pressed_ = false, dragging_ = false;
    double pressU_ = 0, pressV_ = 0;
    int pressX_ = 0, pressY_ = 0;
};

}  // namespace lc::gui
