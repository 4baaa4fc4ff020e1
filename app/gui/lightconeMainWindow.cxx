#include "lightconeMainWindow.h"

#include "lightconeEgocentricImageWidget.h"
#include "lightconeRPhiDiagramWidget.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QSpinBox>
#include <QSplitter>
#include <QStatusBar>
#include <QVBoxLayout>

#include <cstdio>

namespace lcgui {

MainWindow::MainWindow(lc::Scene scene, int imageWidth, int imageHeight, QWidget* parent) : QMainWindow(parent) {
    if (imageWidth > 0) scene.camera.width = imageWidth;
    if (imageHeight > 0) scene.camera.height = imageHeight;
    session_ = std::make_unique<GodelSession>(std::move(scene));
    setWindowTitle(QString::fromStdString("Lightcone - " + session_->scene().source));

    auto* central = new QWidget(this);
    auto* layout = new QVBoxLayout(central);
    auto* splitter = new QSplitter(Qt::Horizontal, central);
    image_ = new EgocentricImageWidget(splitter);
    diagram_ = new RPhiDiagramWidget(splitter);
    splitter->addWidget(image_);
    splitter->addWidget(diagram_);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    layout->addWidget(splitter, 1);

    auto* controls = new QHBoxLayout;
    controls->addWidget(new QLabel("camera yaw (deg)", central));
    yaw_ = new QSlider(Qt::Horizontal, central);
    yaw_->setRange(-180, 180);
    yaw_->setValue(0);
    yaw_->setTracking(false);  // re-render when released, not on every step
    controls->addWidget(yaw_, 1);
    controls->addWidget(new QLabel("windings", central));
    windings_ = new QSpinBox(central);
    windings_->setRange(0, 6);
    windings_->setValue(session_->windings());
    controls->addWidget(windings_);
    layout->addLayout(controls);
    setCentralWidget(central);

    connect(image_, &EgocentricImageWidget::pixelPicked, this, &MainWindow::pickPixel);
    connect(yaw_, &QSlider::valueChanged, this, &MainWindow::setYawDegrees);
    connect(windings_, QOverload<int>::of(&QSpinBox::valueChanged), this, &MainWindow::setWindings);

    diagram_->setScene(session_->scene(), session_->windings());
    renderImage();
    statusBar()->showMessage("click a pixel of the image to see its light path in the diagram");
}

MainWindow::~MainWindow() = default;

QString MainWindow::statusText() const { return statusBar()->currentMessage(); }

void MainWindow::renderImage() {
    session_->render();
    const auto& r = session_->result();
    image_->setImage(r.width, r.height, session_->colours());
    diagram_->clearHighlight();
    pickedI_ = pickedJ_ = -1;
    char line[200];
    std::snprintf(line, sizeof line, "rendered %d x %d in %.2f s (closed form), %zu object pixels", r.width, r.height,
                  r.stats.seconds, r.stats.hits);
    statusBar()->showMessage(line);
}

void MainWindow::setYawDegrees(int yaw) {
    session_->setYawDegrees(yaw);
    renderImage();
}

void MainWindow::setWindings(int windings) {
    session_->setWindings(windings);
    diagram_->setWindings(windings);
    renderImage();
}

void MainWindow::pickPixel(int i, int j) {
    const auto& r = session_->result();
    if (i < 0 || j < 0 || i >= r.width || j >= r.height) return;
    pickedI_ = i;
    pickedJ_ = j;
    const lc::PixelRecord& p = session_->pixel(i, j);
    if (p.kind == lc::PixelRecord::Object) {
        const auto path = session_->lightPath(i, j, p.affine);
        const std::string& name = session_->scene().spheres.at(static_cast<std::size_t>(p.object)).name;
        diagram_->highlightPath(path, "picked: light path to '" + name + "'");
    } else {
        diagram_->clearHighlight();
    }
    statusBar()->showMessage(QString::fromStdString(session_->describe(i, j)));
}

}  // namespace lcgui
