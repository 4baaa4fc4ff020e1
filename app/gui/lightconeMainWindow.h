#ifndef lightconeMainWindow_h
#define lightconeMainWindow_h
// The desktop session: egocentric image (left) and r-phi diagram (right), linked. Clicking a
// pixel that shows an object highlights that image's light path in the diagram and shows the
// pixel's data in the status bar. Yaw slider and windings spin box re-render.
#include "lightconeGodelSession.h"

#include <QMainWindow>

#include <memory>

class QSlider;
class QSpinBox;

namespace lcgui {

class EgocentricImageWidget;
class RPhiDiagramWidget;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // imageWidth/imageHeight > 0 override the scene camera's size (smaller: faster).
    explicit MainWindow(lc::Scene scene, int imageWidth = 0, int imageHeight = 0, QWidget* parent = nullptr);
    ~MainWindow() override;

    const GodelSession& session() const { return *session_; }
    EgocentricImageWidget* imageView() const { return image_; }
    RPhiDiagramWidget* diagramView() const { return diagram_; }
    QSlider* yawSlider() const { return yaw_; }
    QSpinBox* windingsBox() const { return windings_; }
    QString statusText() const;
    // The last picked pixel, (-1, -1) before any pick.
    int pickedI() const { return pickedI_; }
    int pickedJ() const { return pickedJ_; }

public slots:
    void pickPixel(int i, int j);
    void setYawDegrees(int yaw);
    void setWindings(int windings);

private:
    void renderImage();

    std::unique_ptr<GodelSession> session_;
    EgocentricImageWidget* image_ = nullptr;
    RPhiDiagramWidget* diagram_ = nullptr;
    QSlider* yaw_ = nullptr;
    QSpinBox* windings_ = nullptr;
    int pickedI_ = -1, pickedJ_ = -1;
};

}  // namespace lcgui

#endif
