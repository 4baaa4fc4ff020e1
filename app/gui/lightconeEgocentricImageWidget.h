#ifndef lightconeEgocentricImageWidget_h
#define lightconeEgocentricImageWidget_h
// The egocentric image as a vtkImageData in a vtkImageActor (one pixel = one unit, so picked
// positions map exactly to pixels), with a parallel camera that fits the image. A left click
// emits pixelPicked(i, j) with row j = 0 at the top, as in lc::RenderResult.
#include <QPoint>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderer.h>

#include <vector>

class vtkObject;

namespace lcgui {

class EgocentricImageWidget : public QVTKOpenGLNativeWidget {
    Q_OBJECT
public:
    explicit EgocentricImageWidget(QWidget* parent = nullptr);
    ~EgocentricImageWidget() override;

    // Linear RGB, row 0 on top (lc::shadePixels); shown sRGB-encoded.
    void setImage(int width, int height, const std::vector<float>& linearRgb);
    int imageWidth() const { return width_; }
    int imageHeight() const { return height_; }

    // VTK display coordinates (origin bottom left) -> pixel; false outside the image.
    bool pixelAtDisplay(double x, double y, int& i, int& j) const;
    // Centre of pixel (i, j) in Qt widget coordinates (origin top left), e.g. for QTest clicks.
    // Valid once the widget has been rendered at its current size.
    QPoint widgetPointOfPixel(int i, int j) const;

signals:
    void pixelPicked(int i, int j);

private:
    void onLeftButtonPress(vtkObject* caller, unsigned long event, void* data);
    void fitCamera(vtkObject* caller, unsigned long event, void* data);

    vtkNew<vtkRenderer> renderer_;
    vtkNew<vtkImageData> image_;
    vtkNew<vtkImageActor> actor_;
    int width_ = 0, height_ = 0;
};

}  // namespace lcgui

#endif
