// SPDX-License-Identifier: BSD-3-Clause
#include "egocentric_image_widget.hpp"

#include "core/colour/srgb.hpp"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkCoordinate.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageMapper3D.h>
#include <vtkInteractorStyleUser.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

namespace lc::gui {

EgocentricImageWidget::EgocentricImageWidget(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
    vtkNew<vtkGenericOpenGLRenderWindow> window;
    setRenderWindow(window);
    renderer_->SetBackground(0.1, 0.1, 0.12);
    renderer_->GetActiveCamera()->ParallelProjectionOn();
    renderer_->AddObserver(vtkCommand::StartEvent, this, &EgocentricImageWidget::fitCamera);
    actor_->GetMapper()->SetInputData(image_);
    actor_->InterpolateOff();  // one screen block per pixel: what you click is what was traced
    renderer_->AddActor(actor_);
    window->AddRenderer(renderer_);
    // No camera interaction: the image stays fitted, a left click picks.
    vtkNew<vtkInteractorStyleUser> style;
    interactor()->SetInteractorStyle(style);
    interactor()->AddObserver(vtkCommand::LeftButtonPressEvent, this, &EgocentricImageWidget::onLeftButtonPress);
    interactor()->AddObserver(vtkCommand::LeftButtonReleaseEvent, this, &EgocentricImageWidget::onLeftButtonRelease);
    interactor()->AddObserver(vtkCommand::MouseMoveEvent, this, &EgocentricImageWidget::onMouseMove);
    interactor()->AddObserver(vtkCommand::MouseWheelForwardEvent, this, &EgocentricImageWidget::onWheel);
    interactor()->AddObserver(vtkCommand::MouseWheelBackwardEvent, this, &EgocentricImageWidget::onWheel);
    // The marker of a selected image: a ring of 2.5 px radius in front of the image.
    vtkNew<vtkRegularPolygonSource> ring;
    ring->SetNumberOfSides(24);
    ring->SetRadius(2.5);
    ring->GeneratePolygonOff();
    vtkNew<vtkPolyDataMapper> ringMapper;
    ringMapper->SetInputConnection(ring->GetOutputPort());
    marker_->SetMapper(ringMapper);
    marker_->GetProperty()->SetColor(1, 0, 1);
    marker_->GetProperty()->SetLineWidth(2);
    marker_->VisibilityOff();
    renderer_->AddActor(marker_);
    vtkNew<vtkPolyDataMapper> curvesMapper;
    curvesActor_->SetMapper(curvesMapper);
    curvesActor_->GetProperty()->SetColor(1, 0.55, 0);
    curvesActor_->GetProperty()->SetLineWidth(2);
    curvesActor_->VisibilityOff();
    renderer_->AddActor(curvesActor_);
    // The notice: centred, wrapped by hand (VTK does not wrap), over everything.
    vtkTextProperty* text = noticeActor_->GetTextProperty();
    text->SetFontSize(18);
    text->SetColor(1, 1, 1);
    text->SetBackgroundColor(0.1, 0.1, 0.12);
    text->SetBackgroundOpacity(0.75);
    text->SetJustificationToCentered();
    text->SetVerticalJustificationToCentered();
    noticeActor_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    noticeActor_->SetPosition(0.5, 0.5);
    noticeActor_->VisibilityOff();
    renderer_->AddActor2D(noticeActor_);
}

void EgocentricImageWidget::setNotice(const QString& text, bool dim) {
    notice_ = text;
    // Lines of at most ~70 characters at spaces.
    QString wrapped, line;
    for (const QString& word : text.split(' ', Qt::SkipEmptyParts)) {
        if (!line.isEmpty() && line.size() + 1 + word.size() > 70) {
            wrapped += line + "\n";
            line.clear();
        }
        line += (line.isEmpty() ? "" : " ") + word;
    }
    wrapped += line;
    noticeActor_->SetInput(wrapped.toStdString().c_str());
    noticeActor_->SetVisibility(!text.isEmpty());
    actor_->SetOpacity(dim && !text.isEmpty() ? 0.3 : 1.0);
    renderWindow()->Render();
    update();
}

bool EgocentricImageWidget::dimmed() const { return actor_->GetOpacity() < 1.0; }

void EgocentricImageWidget::markPixel(int i, int j) {
    marker_->SetVisibility(i >= 0 && j >= 0);
    marker_->SetPosition(i, height_ - 1 - j, 1);
    renderWindow()->Render();
    update();
}

void EgocentricImageWidget::setCurves(const std::vector<std::vector<std::array<double, 2>>>& curves) {
    curves_ = curves;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    for (const auto& curve : curves) {
        if (curve.size() < 2) continue;
        lines->InsertNextCell(static_cast<vtkIdType>(curve.size()));
        // Image coordinates to the actor's: pixel centres at integers, rows going up.
        for (const auto& p : curve)
            lines->InsertCellPoint(points->InsertNextPoint(p[0] - 0.5, height_ - p[1] - 0.5, 1));
    }
    vtkNew<vtkPolyData> polylines;
    polylines->SetPoints(points);
    polylines->SetLines(lines);
    vtkPolyDataMapper::SafeDownCast(curvesActor_->GetMapper())->SetInputData(polylines);
    curvesActor_->SetVisibility(lines->GetNumberOfCells() > 0);
    renderWindow()->Render();
    update();
}

EgocentricImageWidget::~EgocentricImageWidget() = default;

std::array<unsigned char, 3> EgocentricImageWidget::shownColour(int i, int j) const {
    std::array<unsigned char, 3> rgb{0, 0, 0};
    if (i < 0 || j < 0 || i >= width_ || j >= height_) return rgb;
    const auto* colours = static_cast<const unsigned char*>(image_->GetScalarPointer(i, height_ - 1 - j, 0));
    std::copy_n(colours, 3, rgb.begin());
    return rgb;
}

void EgocentricImageWidget::setImage(int width, int height, const std::vector<float>& linearRgb) {
    width_ = width;
    height_ = height;
    image_->SetDimensions(width, height, 1);
    image_->SetOrigin(0, 0, 0);
    image_->SetSpacing(1, 1, 1);
    vtkNew<vtkUnsignedCharArray> rgb;
    rgb->SetName("colour");
    rgb->SetNumberOfComponents(3);
    rgb->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
    for (int j = 0; j < height; ++j) {
        const int y = height - 1 - j;  // VTK rows go up
        for (int i = 0; i < width; ++i) {
            const std::size_t src = 3 * (static_cast<std::size_t>(j) * width + i);
            const vtkIdType dst = static_cast<vtkIdType>(y) * width + i;
            for (int c = 0; c < 3; ++c) {
                const double v = src + c < linearRgb.size()
                                     ? lc::colour::srgbEncode(std::clamp(double(linearRgb[src + c]), 0.0, 1.0))
                                     : 0.0;
                rgb->SetTypedComponent(dst, c, static_cast<unsigned char>(std::lround(255 * v)));
            }
        }
    }
    image_->GetPointData()->SetScalars(rgb);
    image_->Modified();
    actor_->SetPosition(0, 0, 0);  // a drag's preview shift ends with the image of the turned camera
    actor_->Modified();
    renderWindow()->Render();
    update();
}

void EgocentricImageWidget::fitCamera(vtkObject*, unsigned long, void*) {
    if (width_ <= 0 || height_ <= 0) return;
    vtkCamera* cam = renderer_->GetActiveCamera();
    const double cx = 0.5 * (width_ - 1), cy = 0.5 * (height_ - 1);
    cam->SetFocalPoint(cx, cy, 0);
    cam->SetPosition(cx, cy, 10);
    cam->SetViewUp(0, 1, 0);
    cam->SetClippingRange(1, 100);
    const int* size = renderer_->GetSize();
    const double aspect = size[1] > 0 ? static_cast<double>(size[0]) / size[1] : 1.0;
    cam->SetParallelScale(std::max(0.5 * height_, 0.5 * width_ / aspect));
}

bool EgocentricImageWidget::pixelAtDisplay(double x, double y, int& i, int& j) const {
    if (width_ <= 0) return false;
    vtkNew<vtkCoordinate> c;
    c->SetCoordinateSystemToDisplay();
    c->SetValue(x, y, 0);
    const double* w = c->GetComputedWorldValue(renderer_);
    const double* shift = actor_->GetPosition();  // the pixel shown there, during a drag's preview too
    // Pixel (i, y) covers [i - 1/2, i + 1/2) x [y - 1/2, y + 1/2) in world units.
    i = static_cast<int>(std::floor(w[0] - shift[0] + 0.5));
    const int row = static_cast<int>(std::floor(w[1] - shift[1] + 0.5));
    j = height_ - 1 - row;
    return i >= 0 && i < width_ && j >= 0 && j < height_;
}

QPoint EgocentricImageWidget::widgetPointOfPixel(int i, int j) const {
    vtkNew<vtkCoordinate> c;
    c->SetCoordinateSystemToWorld();
    c->SetValue(i, height_ - 1 - j, 0);
    const double* d = c->GetComputedDoubleDisplayValue(renderer_);
    const double ratio = devicePixelRatioF();
    const int* size = renderer_->GetRenderWindow()->GetSize();
    // QVTKInteractorAdapter flips y as size - 1 - y (in device pixels).
    return QPoint(static_cast<int>(std::lround(d[0] / ratio)),
                  static_cast<int>(std::lround((size[1] - 1 - d[1]) / ratio)));
}

bool EgocentricImageWidget::imagePointAtDisplay(double x, double y, double& u, double& v) const {
    if (width_ <= 0) return false;
    vtkNew<vtkCoordinate> c;
    c->SetCoordinateSystemToDisplay();
    c->SetValue(x, y, 0);
    const double* w = c->GetComputedWorldValue(renderer_);
    u = w[0];
    v = w[1];
    return true;
}

void EgocentricImageWidget::onLeftButtonPress(vtkObject*, unsigned long, void*) {
    const int* p = interactor()->GetEventPosition();
    pressed_ = imagePointAtDisplay(p[0], p[1], pressU_, pressV_);
    dragging_ = false;
    pressX_ = p[0];
    pressY_ = p[1];
}

void EgocentricImageWidget::onMouseMove(vtkObject*, unsigned long, void*) {
    const int* p = interactor()->GetEventPosition();
    // A press that moves more than 4 screen pixels is a drag, not a click.
    if (pressed_ && std::abs(p[0] - pressX_) + std::abs(p[1] - pressY_) > 4) dragging_ = true;
    if (dragging_) {
        // The live preview: the image follows the hand at once, as the camera will turn (one
        // redraw of a textured quad; the render of the turned camera replaces it).
        double u = 0, v = 0;
        imagePointAtDisplay(p[0], p[1], u, v);
        actor_->SetPosition(u - pressU_, v - pressV_, 0);
        marker_->VisibilityOff();
        curvesActor_->VisibilityOff();
        renderWindow()->Render();
        update();
        return;
    }
    int i = 0, j = 0;
    if (!pressed_ && pixelAtDisplay(p[0], p[1], i, j)) emit pixelHovered(i, j);
}

void EgocentricImageWidget::onLeftButtonRelease(vtkObject*, unsigned long, void*) {
    if (!pressed_) return;
    pressed_ = false;
    const int* p = interactor()->GetEventPosition();
    if (dragging_) {
        double u = 0, v = 0;
        imagePointAtDisplay(p[0], p[1], u, v);
        emit dragged(u - pressU_, -(v - pressV_));  // image rows grow downwards
        return;
    }
    int i = 0, j = 0;
    if (pixelAtDisplay(p[0], p[1], i, j)) emit pixelPicked(i, j);
}

void EgocentricImageWidget::clearDragPreview() {
    actor_->SetPosition(0, 0, 0);
    renderWindow()->Render();
    update();
}

QPointF EgocentricImageWidget::dragPreviewShift() const {
    const double* at = actor_->GetPosition();
    return {at[0], -at[1]};
}

void EgocentricImageWidget::onWheel(vtkObject*, unsigned long event, void*) {
    emit zoomed(event == vtkCommand::MouseWheelForwardEvent ? 1 : -1);
}

}  // namespace lc::gui
