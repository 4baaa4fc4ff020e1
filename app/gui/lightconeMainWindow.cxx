#include "lightconeMainWindow.h"

#include "lightconeAccuracyPanel.h"
#include "lightconeCameraEdits.h"
#include "lightconeEgocentricImageWidget.h"
#include "lightconeHelpDialogs.h"
#include "lightconeImagesTable.h"
#include "lightconeLightPath.h"
#include "lightconeObserverTimeSlider.h"
#include "lightconePostRenderDock.h"
#include "lightconePropertiesPanel.h"
#include "lightconeDiagramDock.h"
#include "lightconeSelectionModel.h"
#include "lightconeSpacetimeViewDock.h"

#include "app/commands.hpp"
#include "core/metrics/godel.hpp"
#include "core/scene/frame_camera.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/image_io.hpp"
#include "readers/io/structural_edits.hpp"

#include <OpenImageIO/oiioversion.h>
#include <vtkRenderWindow.h>
#include <vtkVersion.h>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QCursor>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QToolTip>
#include <QUndoCommand>

#include <cmath>
#include <cstdio>
#include <functional>
#include <fstream>

namespace lcgui {

// One entry of the undo stack: the fields' new values and the values they had.
class SceneEditCommand : public QUndoCommand {
public:
    SceneEditCommand(MainWindow* window, std::vector<lc::io::SceneEdit> after, std::vector<lc::io::SceneEdit> before,
                     const QString& text)
        : QUndoCommand(text), window_(window), after_(std::move(after)), before_(std::move(before)) {}
    void redo() override { window_->applyEditsNow(after_); }
    void undo() override { window_->applyEditsNow(before_); }

private:
    MainWindow* window_;
    std::vector<lc::io::SceneEdit> after_, before_;
};

namespace {

constexpr double kSlowShaderSeconds = 10;  // a shader image slower than this turns the shaders off

lc::io::SceneReadOptions readOptions() { return lc::cli::sceneReadOptions(); }

QString editText(const std::vector<lc::io::SceneEdit>& edits) {
    QStringList fields;
    for (const auto& e : edits) fields << QString::fromStdString(e.field);
    return "edit " + fields.join(", ");
}

bool isSessionText(const QString& path) {
    std::ifstream in(path.toStdString());
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head.find("\"lightcone_session\"") != std::string::npos;
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), selection_(new SelectionModel(this)) {
    setObjectName("lightconeMainWindow");
    image_ = new EgocentricImageWidget(this);
    image_->setObjectName("egocentricImage");
    image_->setMinimumSize(320, 160);
    setCentralWidget(image_);
    buildDocks();
    buildMenus();

    progress_ = new QProgressBar(this);
    progress_->setRange(0, 1000);
    progress_->setMaximumWidth(200);
    progress_->setVisible(false);
    cancel_ = new QPushButton("Cancel", this);
    cancel_->setObjectName("cancelRender");
    cancel_->setVisible(false);
    statusBar()->addPermanentWidget(progress_);
    statusBar()->addPermanentWidget(cancel_);
    connect(cancel_, &QPushButton::clicked, this, &MainWindow::cancelRender);

    connect(image_, &EgocentricImageWidget::pixelPicked, this, &MainWindow::pickPixel);
    linkViews();
    connect(image_, &EgocentricImageWidget::dragged, this, &MainWindow::lookAround);
    connect(image_, &EgocentricImageWidget::zoomed, this, &MainWindow::zoom);
    connect(image_, &EgocentricImageWidget::pixelHovered, this, [this](int i, int j) {
        if (!cpu_ || i >= cpu_->records.width || j >= cpu_->records.height) return;
        const auto& p = cpu_->records.pixels[static_cast<std::size_t>(j) * cpu_->records.width + i];
        QToolTip::showText(QCursor::pos(), QString::fromStdString(describePixel(scene_->scene(), p, i, j)), image_);
    });
    connect(&job_, &RenderJob::progressed, this, [this](double f) { progress_->setValue(static_cast<int>(1000 * f)); });
    connect(&job_, &RenderJob::finished, this, &MainWindow::onRenderFinished);
    connect(&job_, &RenderJob::photoSceneReady, this,
            [this](std::shared_ptr<const std::vector<lc::PhotoSceneObject>> photos) {
                if (useShaders_) showShaderImage(std::move(photos));
            });
    connect(&job_, &RenderJob::cancelled, this, [this] {
        progress_->setVisible(false);
        cancel_->setVisible(false);
        const QString why =
            "render cancelled: the per-pixel data of this scene is not traced (a pick, an edit or Ctrl+R traces it)";
        statusBar()->showMessage(why);
        if (imageSource_.isEmpty()) image_->setNotice(why, true);  // nothing of this scene shown yet
        accuracy_->showNoRender(why);
    });
    connect(&job_, &RenderJob::failed, this, [this](const QString& message) {
        progress_->setVisible(false);
        cancel_->setVisible(false);
        if (imageSource_.isEmpty()) image_->setNotice("render failed: " + message, true);
        showError("Render failed", message);
    });
    // Queued: the edit rebuilds the tree, which must not happen inside the tree's own signal.
    connect(
        properties_, &PropertiesPanel::editRequested, this,
        [this](const QString& field, const Json::Value& value) {
            if (field == "metric.name" && value.isString())  // a name typed in the tree: the chooser's edit
                changeMetric(QString::fromStdString(value.asString()));
            else
                editScene({{field.toStdString(), value}}, "edit " + field);
        },
        Qt::QueuedConnection);
    linkStructuralEdits();
    connect(&undo_, &QUndoStack::cleanChanged, this, [this] { updateTitle(); });

    defaultLayout_ = saveState();
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    if (!restoreState(settings.value("window/state").toByteArray()))
        QTimer::singleShot(0, this, &MainWindow::resetLayout);  // first run: once the window has its size
    refreshRecentMenu();
    updateTitle();
    statusBar()->showMessage("File > Open scene (Ctrl+O) or Open session");
}

MainWindow::~MainWindow() = default;

void MainWindow::buildDocks() {
    diagramDock_ = new DiagramDock(DiagramWidget::RPhi, this);
    diagram_ = diagramDock_->diagram();
    addDockWidget(Qt::RightDockWidgetArea, diagramDock_);

    spacetimeDock_ = new SpacetimeViewDock(this);
    addDockWidget(Qt::RightDockWidgetArea, spacetimeDock_);
    splitDockWidget(diagramDock_, spacetimeDock_, Qt::Vertical);
    trDock_ = new DiagramDock(DiagramWidget::TR, this);  // a tab beside the r-phi diagram
    addDockWidget(Qt::RightDockWidgetArea, trDock_);
    tabifyDockWidget(diagramDock_, trDock_);
    diagramDock_->raise();

    properties_ = new PropertiesPanel(this);
    propertiesDock_ = new QDockWidget("Properties", this);
    propertiesDock_->setObjectName("propertiesDock");
    propertiesDock_->setWidget(properties_);
    addDockWidget(Qt::LeftDockWidgetArea, propertiesDock_);

    imagesTable_ = new ImagesTable(this);
    imagesDock_ = new QDockWidget("Images of the selected object", this);
    imagesDock_->setObjectName("imagesDock");
    imagesDock_->setWidget(imagesTable_);
    addDockWidget(Qt::BottomDockWidgetArea, imagesDock_);
    connect(imagesTable_, &QTableWidget::itemSelectionChanged, this, [this] {
        const auto rows = imagesTable_->selectionModel()->selectedRows();
        selectImageRow(rows.isEmpty() ? -1 : rows.first().row());
    });
    // Post-rendering: the CPU data coloured again on the GPU while its sliders move.
    postRender_ = new PostRenderDock(this);
    postRender_->setObjectName("postRender");
    postRenderDock_ = new QDockWidget("Post-rendering (no tracing)", this);
    postRenderDock_->setObjectName("postRenderDock");
    postRenderDock_->setWidget(postRender_);
    addDockWidget(Qt::LeftDockWidgetArea, postRenderDock_);
    tabifyDockWidget(propertiesDock_, postRenderDock_);
    propertiesDock_->raise();
    connect(postRender_, &PostRenderDock::imageReady, this,
            [this](int width, int height, const std::vector<float>& rgb) {
                shown_ = rgb;
                imageSource_ = "post-render";
                image_->setImage(width, height, shown_);
                statusBar()->showMessage(QString("post-rendered on the GPU in %1 ms from the CPU's per-pixel data")
                                             .arg(postRender_->lastSeconds() * 1e3, 0, 'f', 1));
            });
    connect(postRender_, &PostRenderDock::switchedOff, this, [this] {
        if (!cpu_) return;
        shown_ = cpu_->rgb;
        imageSource_ = "cpu";
        image_->setImage(cpu_->records.width, cpu_->records.height, shown_);
    });
    // How far to trust the image: the render's figures and the picked ray's.
    accuracy_ = new AccuracyPanel(this);
    accuracyDock_ = new QDockWidget("Accuracy", this);
    accuracyDock_->setObjectName("accuracyDock");
    accuracyDock_->setWidget(accuracy_);
    addDockWidget(Qt::LeftDockWidgetArea, accuracyDock_);
    tabifyDockWidget(postRenderDock_, accuracyDock_);  // a third tab beside Properties and Post-rendering
    propertiesDock_->raise();
    // Further docks go here, each added to the View menu (buildMenus) and to resetLayout.
}

// Every link between the views goes through the selection model: a view tells it what was
// selected, and showRay / showObject draw that in every view.
void MainWindow::linkViews() {
    connect(selection_, &SelectionModel::raySelected, this, &MainWindow::showRay);
    connect(selection_, &SelectionModel::rayCleared, this, [this] {
        for (DiagramDock* dock : {diagramDock_, trDock_}) dock->diagram()->clearHighlight();
        spacetimeDock_->clearRay();
        marked_ = {-1, -1};
        image_->markPixel(-1, -1);
    });
    connect(selection_, &SelectionModel::objectSelected, this, &MainWindow::showObject);
    connect(spacetimeDock_, &SpacetimeViewDock::rayPicked, this, [this](const lc::Vec3& direction, int ray) {
        if (!scene_) return;
        const auto [i, j] = pixelOfDirection(lc::frameCamera(scene_->scene()), direction);
        selection_->selectRay(
            {direction, 0, i, j,
             ray < 0 ? "picked in the 3D view" : "picked in the 3D view: ray " + std::to_string(ray)});
        statusBar()->showMessage(i < 0
                                     ? QString("picked ray %1 in the 3D view: outside the image").arg(ray)
                                     : QString("picked ray %1 in the 3D view: pixel (%2, %3)").arg(ray).arg(i).arg(j));
    });
    connect(spacetimeDock_, &SpacetimeViewDock::objectPicked, selection_, &SelectionModel::selectObject);
    connect(diagram_, &DiagramWidget::pointClicked, this, &MainWindow::pickDiagramPoint);
}

void MainWindow::pickDiagramPoint(double x, double y) {
    if (!scene_ || !hasClosedFormLightPaths(scene_->scene())) return;
    const lc::Scene& scene = scene_->scene();
    const PlanarRayHit hit = nearestPlanarRay(scene, x, y);
    const auto [i, j] = pixelOfDirection(lc::frameCamera(scene), hit.direction);
    char label[96];
    std::snprintf(label, sizeof label, "picked in the r-phi diagram: ray at phi = %.1f deg", hit.phi0 * 180 / lc::kPi);
    selection_->selectRay({hit.direction, hit.affine, i, j, label});
    statusBar()->showMessage(QString("%1, affine %2: %3")
                                 .arg(label)
                                 .arg(hit.affine, 0, 'f', 3)
                                 .arg(i < 0 ? QString("outside the image") : QString("pixel (%1, %2)").arg(i).arg(j)));
}

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu("&File");
    QToolBar* tools = addToolBar("Main");
    tools->setObjectName("mainToolBar");
    auto action = [this](QMenu* menu, const QString& text, const QKeySequence& keys, auto slot) {
        QAction* a = menu->addAction(text);
        if (!keys.isEmpty()) a->setShortcut(keys);
        connect(a, &QAction::triggered, this, slot);
        return a;
    };
    QAction* open = action(file, "&Open scene...", QKeySequence::Open, [this] {
        if (!maybeSave()) return;
        const QString path =
            QFileDialog::getOpenFileName(this, "Open scene", QString(), "Scenes (*.json);;All files (*)");
        if (!path.isEmpty()) openScene(path);
    });
    recentMenu_ = file->addMenu("Open &recent");
    action(file, "Open &session...", QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O), [this] {
        if (!maybeSave()) return;
        const QString path =
            QFileDialog::getOpenFileName(this, "Open session", QString(), "Sessions (*.lcsession);;All files (*)");
        if (!path.isEmpty()) openSession(path);
    });
    file->addSeparator();
    QAction* save = action(file, "&Save session", QKeySequence::Save, [this] {
        if (sessionPath_.isEmpty())
            saveSessionAs();
        else
            saveSession(sessionPath_);
    });
    action(file, "Save session &as...", QKeySequence::SaveAs, [this] { saveSessionAs(); });
    file->addSeparator();
    action(file, "Export &image (PNG/EXR)...", QKeySequence(Qt::CTRL | Qt::Key_E), [this] {
        const QString path =
            QFileDialog::getSaveFileName(this, "Export image", besideScene("image.png"), "Images (*.png *.exr)");
        if (!path.isEmpty()) exportImage(path);
    });
    action(file, "Export &diagram (SVG/PDF/PNG)...", QKeySequence(), [this] {
        const QString path = QFileDialog::getSaveFileName(this, "Export diagram", besideScene("diagram.svg"),
                                                          "Diagrams (*.svg *.pdf *.png)");
        if (!path.isEmpty()) exportDiagram(path);
    });
    action(file, "Export &VTK data (.vtp/.vti/.vtm)...", QKeySequence(), [this] {
        const QString folder =
            QFileDialog::getSaveFileName(this, "Export VTK data to a folder", besideScene("lightcone-export"));
        if (!folder.isEmpty()) exportVtk(folder);
    });
    file->addSeparator();
    action(file, "&Quit", QKeySequence::Quit, [this] { close(); });

    QMenu* edit = menuBar()->addMenu("&Edit");
    QAction* undo = undo_.createUndoAction(this, "&Undo");
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = undo_.createRedoAction(this, "&Redo");
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    action(edit, "Add &sphere", QKeySequence(), [this] { addSphere(); });
    action(edit, "Add &light", QKeySequence(), [this] { addLight(); });
    action(edit, "&Duplicate object or light", QKeySequence(Qt::CTRL | Qt::Key_D), [this] {
        const auto [list, index] = properties_->currentElement();
        if (!list.isEmpty()) duplicateElement(list, index);
    });
    action(edit, "Re&move object or light", QKeySequence(), [this] {
        const auto [list, index] = properties_->currentElement();
        if (!list.isEmpty()) removeElement(list, index);
    });

    QMenu* view = menuBar()->addMenu("&View");
    view->addAction(propertiesDock_->toggleViewAction());
    view->addAction(diagramDock_->toggleViewAction());
    view->addAction(trDock_->toggleViewAction());
    view->addAction(spacetimeDock_->toggleViewAction());
    view->addAction(imagesDock_->toggleViewAction());
    view->addAction(postRenderDock_->toggleViewAction());
    view->addAction(accuracyDock_->toggleViewAction());
    view->addSeparator();
    QAction* reset = action(view, "Reset &view", QKeySequence(Qt::CTRL | Qt::Key_R), [this] { resetView(); });
    panoramaAction_ = view->addAction("&Panorama projection");
    panoramaAction_->setCheckable(true);
    connect(panoramaAction_, &QAction::triggered, this, [this](bool on) { setPanorama(on); });
    shadersAction_ = view->addAction("Image from &shaders (GPU) where available");
    shadersAction_->setCheckable(true);
    shadersAction_->setChecked(true);
    connect(shadersAction_, &QAction::triggered, this, [this](bool on) { setShadersEnabled(on); });
    view->addSeparator();
    action(view, "Reset &layout", QKeySequence(), [this] { resetLayout(); });

    QMenu* help = menuBar()->addMenu("&Help");
    action(help, "&Contents (docs/GUI.md)", QKeySequence::HelpContents, [this] { showGuideDialog(this); });
    action(help, "Keyboard &shortcuts", QKeySequence(), [this] { showShortcutsDialog(this, menuBar()); });
    action(help, "&About Lightcone", QKeySequence(),
           [this] { QMessageBox::about(this, "About Lightcone", aboutText()); });

    tools->addAction(open);
    tools->addAction(save);
    tools->addAction(undo);
    tools->addAction(redo);
    tools->addAction(reset);
    tools->addAction(panoramaAction_);
    // The observer's proper time: one edit of observer.position per choice.
    timeSlider_ = new ObserverTimeSlider(this);
    tools->addSeparator();
    tools->addWidget(timeSlider_);
    connect(timeSlider_, &ObserverTimeSlider::timeChosen, this, [this](double t) {
        if (!scene_) return;
        const lc::Vec4& x = scene_->scene().observer;
        Json::Value position(Json::arrayValue);
        for (double c : {t, x(1), x(2), x(3)}) position.append(c);
        editScene({{"observer.position", position}}, "observer time");
    });
}

void MainWindow::resetLayout() {
    restoreState(defaultLayout_);
    for (QDockWidget* d : {propertiesDock_, static_cast<QDockWidget*>(diagramDock_), static_cast<QDockWidget*>(trDock_),
                           static_cast<QDockWidget*>(spacetimeDock_), imagesDock_, postRenderDock_, accuracyDock_})
        d->show();
    propertiesDock_->raise();
    diagramDock_->raise();
    resizeDocks({propertiesDock_, diagramDock_}, {width() / 5, width() / 3}, Qt::Horizontal);
    resizeDocks({imagesDock_}, {height() / 5}, Qt::Vertical);
}

QString MainWindow::aboutText() const {
    QString gl = "unknown";
    const std::string caps = image_->renderWindow() ? image_->renderWindow()->ReportCapabilities() : "";
    const auto at = caps.find("OpenGL renderer string:");
    if (at != std::string::npos) {
        const auto end = caps.find('\n', at);
        gl = QString::fromStdString(caps.substr(at + 23, end - at - 23)).trimmed();
    }
    return QString(
               "<b>Lightcone %1</b><br>what an observer sees in a relativistic spacetime<br><br>"
               "VTK %2<br>Qt %3<br>OpenImageIO %4<br>OpenGL renderer: %5")
        .arg(LIGHTCONE_VERSION, vtkVersion::GetVTKVersion(), qVersion(), OIIO_VERSION_STRING, gl);
}

int MainWindow::selectedObject() const { return selection_->object(); }

QString MainWindow::diagramNote() const { return diagramDock_->note(); }

QString MainWindow::besideScene(const QString& name) const {
    const QString beside = !sessionPath_.isEmpty() ? sessionPath_ : sceneFile_;
    if (beside.isEmpty()) return name;
    const QString base = QFileInfo(beside).completeBaseName();
    const QString suffix = QFileInfo(name).suffix();
    // "kerr.png" beside kerr.json: the scene's name, the export's kind.
    return QFileInfo(beside).dir().filePath(suffix.isEmpty() ? base + "-" + name : base + "." + suffix);
}

QString MainWindow::statusText() const { return statusBar()->currentMessage(); }

void MainWindow::showError(const QString& title, const QString& text) {
    lastError_ = text;
    // Window-modal but not blocking: the event loop (and a running render) go on.
    auto* box = new QMessageBox(QMessageBox::Critical, title, text, QMessageBox::Ok, this);
    box->setObjectName("errorDialog");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

void MainWindow::updateTitle() {
    QString name = "no scene";
    if (!sessionPath_.isEmpty())
        name = QFileInfo(sessionPath_).fileName();
    else if (!sceneFile_.isEmpty())
        name = QFileInfo(sceneFile_).fileName();
    setWindowTitle(name + "[*] - Lightcone");
    setWindowModified(!undo_.isClean());
}

// ---- opening and saving -------------------------------------------------------------------------

bool MainWindow::openFile(const QString& path) { return isSessionText(path) ? openSession(path) : openScene(path); }

bool MainWindow::openScene(const QString& path) {
    try {
        adopt(lc::io::EditableScene::load(path.toStdString(), readOptions()), path, QString());
    } catch (const std::exception& e) {
        showError("Cannot open the scene", e.what());
        return false;
    }
    addRecent(path);
    return true;
}

bool MainWindow::openSession(const QString& path) {
    lc::io::SessionFile session;
    lc::io::OpenedSession opened;
    try {
        session = lc::io::readSession(path.toStdString());
        opened = lc::io::openSessionScene(session, path.toStdString(), readOptions());
    } catch (const std::exception& e) {
        showError("Cannot open the session", e.what());
        return false;
    }
    QString sceneFile = QString::fromStdString(session.scenePath);
    if (QFileInfo(sceneFile).isRelative()) sceneFile = QFileInfo(path).dir().filePath(sceneFile);
    useShaders_ = session.imageFromShaders;
    shadersAction_->setChecked(useShaders_);
    postRender_->setControls(session.postRender);  // drawn once the data is traced
    if (!session.windowGeometry.empty())
        restoreGeometry(QByteArray::fromBase64(QByteArray::fromStdString(session.windowGeometry)));
    if (!session.windowState.empty())
        restoreState(QByteArray::fromBase64(QByteArray::fromStdString(session.windowState)));
    adopt(std::move(opened.scene), sceneFile, path);
    if (session.selectedObject < static_cast<int>(scene_->scene().spheres.size()))
        selection_->selectObject(session.selectedObject);
    fillImagesTable();
    pendingPickI_ = session.pickedI;  // picked again when the per-pixel data is traced
    pendingPickJ_ = session.pickedJ;
    if (!opened.notice.empty()) {
        lastNotice_ = QString::fromStdString(opened.notice);
        auto* box = new QMessageBox(QMessageBox::Information, "Session opened from its saved copy", lastNotice_,
                                    QMessageBox::Ok, this);
        box->setObjectName("noticeDialog");
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
        undo_.resetClean();  // the session on disk no longer matches what a save would write
    }
    addRecent(path);
    return true;
}

lc::io::SessionFile MainWindow::currentSession(const QString& sessionFile) const {
    lc::io::SessionFile s;
    s.scenePath = lc::io::scenePathForSession(sceneFile_.toStdString(), sessionFile.toStdString());
    s.edits = scene_->edits();
    s.sceneDocument = scene_->document();
    // A pick still waiting for its data is the one to keep.
    s.pickedI = pendingPickI_ >= 0 ? pendingPickI_ : pickedI_;
    s.pickedJ = pendingPickI_ >= 0 ? pendingPickJ_ : pickedJ_;
    s.selectedObject = selection_->object();
    s.imageFromShaders = useShaders_;
    s.postRender = postRender_->controls();
    s.windowState = saveState().toBase64().toStdString();
    s.windowGeometry = saveGeometry().toBase64().toStdString();
    return s;
}

bool MainWindow::saveSession(const QString& path) {
    if (!scene_) {
        showError("Nothing to save", "open a scene first");
        return false;
    }
    try {
        lc::io::writeSession(path.toStdString(), currentSession(path));
    } catch (const std::exception& e) {
        showError("Cannot save the session", e.what());
        return false;
    }
    sessionPath_ = path;
    undo_.setClean();
    updateTitle();
    addRecent(path);
    statusBar()->showMessage("saved " + path);
    return true;
}

bool MainWindow::saveSessionAs() {
    const QString path =
        QFileDialog::getSaveFileName(this, "Save session", besideScene("session.lcsession"), "Sessions (*.lcsession)");
    return !path.isEmpty() && saveSession(path);
}

bool MainWindow::maybeSave() {
    if (!isWindowModified()) return true;
    const auto answer = QMessageBox::question(
        this, "Unsaved changes", "The scene has edits that are not saved in a session. Save them?",
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel) return false;
    if (answer == QMessageBox::Discard) return true;
    return sessionPath_.isEmpty() ? saveSessionAs() : saveSession(sessionPath_);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    job_.cancel();
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    event->accept();
}

void MainWindow::addRecent(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value("recentFiles").toStringList();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    recent.removeAll(absolute);
    recent.prepend(absolute);
    while (recent.size() > 10) recent.removeLast();
    settings.setValue("recentFiles", recent);
    refreshRecentMenu();
}

void MainWindow::refreshRecentMenu() {
    recentMenu_->clear();
    const QStringList recent = QSettings().value("recentFiles").toStringList();
    for (const QString& path : recent)
        connect(recentMenu_->addAction(path), &QAction::triggered, this, [this, path] {
            if (maybeSave()) openFile(path);
        });
    recentMenu_->setEnabled(!recent.isEmpty());
}

void MainWindow::adopt(lc::io::EditableScene scene, const QString& sceneFile, const QString& sessionFile) {
    job_.cancel();
    scene_ = std::move(scene);
    sceneFile_ = sceneFile;
    sessionPath_ = sessionFile;
    undo_.clear();
    undo_.setClean();
    cpu_.reset();
    selection_->clearRay();
    selection_->selectObject(scene_->scene().spheres.empty() ? -1 : 0);  // the images table starts with the first
    pickedI_ = pickedJ_ = -1;
    pendingPickI_ = pendingPickJ_ = -1;
    sceneChanged();
}

// ---- exports: the CLI's own code on the edited scene ----------------------------------------------

bool MainWindow::exportWith(const QString& what, const QString& path, const std::function<void()>& write) {
    try {
        write();
    } catch (const std::exception& e) {
        showError("Cannot export the " + what, e.what());
        return false;
    }
    statusBar()->showMessage("wrote " + path);
    return true;
}

bool MainWindow::exportImage(const QString& path) {
    return exportWith("image", path, [&] {
        if (!cpu_) throw std::invalid_argument("the CPU render of this scene is not finished (or was cancelled)");
        lc::io::checkOutputPath(path.toStdString(), lc::io::imageExtensions(), "image file");
        if (!postRender_->active()) {
            lc::cli::writeRenderOutputs(*cpu_, path.toStdString());
            return;
        }
        // What the post-rendering dock shows, coloured by the CPU reference (as `lightcone shade`).
        lc::ColouredImage shaded{cpu_->records,
                                 lc::shadePixels(scene_->scene(), cpu_->records, postRender_->settings())};
        lc::cli::writeRenderOutputs(shaded, path.toStdString());
    });
}

bool MainWindow::exportDiagram(const QString& path) {
    return exportWith("diagram", path, [&] {
        if (!scene_) throw std::invalid_argument("open a scene first");
        lc::io::checkOutputPath(path.toStdString(), {".svg", ".pdf", ".png"}, "diagram file");
        const lc::Scene& scene = scene_->scene();
        lc::cli::writeDiagrams(scene, {path.toStdString()}, std::min(scene.settings.windings, 50));
    });
}

bool MainWindow::exportVtk(const QString& folder) {
    return exportWith("VTK data", folder, [&] {
        if (!scene_) throw std::invalid_argument("open a scene first");
        lc::cli::exportScene(scene_->scene(), folder.toStdString());
    });
}

// ---- edits --------------------------------------------------------------------------------------

bool MainWindow::editScene(const std::vector<lc::io::SceneEdit>& edits, const QString& description) {
    if (!scene_ || edits.empty()) return false;
    std::vector<lc::io::SceneEdit> before;
    try {
        for (const auto& e : edits) before.push_back({e.field, scene_->value(e.field)});
        lc::io::EditableScene trial = *scene_;  // the reader decides before anything changes
        trial.apply(edits);
    } catch (const lc::io::InputError& e) {
        // The tree as the scene is, at once (a refused metric or list edit changed more than a cell).
        properties_->setDocument(scene_->document(), [this](const std::string& f) { return scene_->rangeOf(f); });
        properties_->showRefusal(QString::fromStdString(e.field()), QString::fromStdString(e.reason()));
        statusBar()->showMessage("refused: " + QString::fromStdString(e.field()) + ": " +
                                 QString::fromStdString(e.reason()));
        return false;
    } catch (const std::exception& e) {
        const QString field = QString::fromStdString(edits.front().field);
        properties_->setDocument(scene_->document(), [this](const std::string& f) { return scene_->rangeOf(f); });
        properties_->showRefusal(field, e.what());
        statusBar()->showMessage("refused: " + field + ": " + e.what());
        return false;
    }
    undo_.push(new SceneEditCommand(this, edits, before, description.isEmpty() ? editText(edits) : description));
    return true;
}

void MainWindow::linkStructuralEdits() {
    // Queued, as edits of values are: each rebuilds the tree that sent it.
    const auto queued = Qt::QueuedConnection;
    connect(properties_, &PropertiesPanel::metricChosen, this, &MainWindow::changeMetric, queued);
    connect(properties_, &PropertiesPanel::sphereAddRequested, this, &MainWindow::addSphere, queued);
    connect(properties_, &PropertiesPanel::lightAddRequested, this, &MainWindow::addLight, queued);
    connect(properties_, &PropertiesPanel::duplicateRequested, this, &MainWindow::duplicateElement, queued);
    connect(properties_, &PropertiesPanel::removeRequested, this, &MainWindow::removeElement, queued);
}

bool MainWindow::editStructure(const std::function<lc::io::SceneEdit()>& make, const QString& description) {
    if (!scene_) return false;
    lc::io::SceneEdit edit;
    try {
        edit = make();
    } catch (const std::invalid_argument& e) {
        properties_->showRefusal(description, e.what());
        statusBar()->showMessage("refused: " + description + ": " + e.what());
        return false;
    }
    return editScene({edit}, description);
}

namespace {
lc::io::SceneList listNamed(const QString& list) {
    if (list == "objects") return lc::io::SceneList::Objects;
    if (list == "lights") return lc::io::SceneList::Lights;
    throw std::invalid_argument("'" + list.toStdString() + "' is not a list of the scene (objects or lights)");
}
}  // namespace

bool MainWindow::changeMetric(const QString& name) {
    if (scene_ && QString::fromStdString(scene_->scene().spacetime->name()) == name &&
        scene_->value("metric").isMember("name"))
        return true;  // the metric it has: nothing to change
    return editStructure([&] { return lc::io::metricChange(name.toStdString()); }, "metric " + name);
}

bool MainWindow::addSphere() {
    return editStructure([&] { return lc::io::sphereAdded(scene_->document(), scene_->scene()); }, "add sphere");
}

bool MainWindow::addLight() {
    return editStructure([&] { return lc::io::lightAdded(scene_->document(), scene_->scene()); }, "add light");
}

bool MainWindow::duplicateElement(const QString& list, int index) {
    return editStructure([&] { return lc::io::elementDuplicated(scene_->document(), listNamed(list), index); },
                         QString("duplicate %1[%2]").arg(list).arg(index));
}

bool MainWindow::removeElement(const QString& list, int index) {
    return editStructure([&] { return lc::io::elementRemoved(scene_->document(), listNamed(list), index); },
                         QString("remove %1[%2]").arg(list).arg(index));
}

void MainWindow::applyEditsNow(const std::vector<lc::io::SceneEdit>& edits) {
    // Checked before the command was pushed, but the reader reads textures and meshes again: a
    // file moved since then is reported, never thrown out of Qt's event loop.
    try {
        scene_->apply(edits);
    } catch (const std::exception& e) {
        showError("Cannot apply the edit", e.what());
        return;
    }
    if (scene_->scene().spheres.size() <= static_cast<std::size_t>(std::max(selection_->object(), 0)))
        selection_->selectObject(scene_->scene().spheres.empty() ? -1 : 0);
    selection_->clearRay();
    pickedI_ = pickedJ_ = -1;
    pendingPickI_ = pendingPickJ_ = -1;  // a pick waiting for the old scene's data is void
    sceneChanged();
}

void MainWindow::lookAround(double dx, double dy) {
    if (!scene_ || !editScene(lookAroundEdits(scene_->scene(), dx, dy), "look around")) image_->clearDragPreview();
}

void MainWindow::zoom(int steps) {
    if (scene_ && steps != 0) editScene({zoomEdit(scene_->scene().camera, steps)}, steps > 0 ? "zoom in" : "zoom out");
}

void MainWindow::resetView() {
    if (!scene_) return;
    const auto edits = resetViewEdits(*scene_);
    if (!edits.empty())
        editScene(edits, "reset view");
    else if (!cpu_ && !job_.running())
        startRender();  // the view is the file's already: Ctrl+R traces what a cancel left untraced
}

void MainWindow::setPanorama(bool panorama) {
    if (!scene_) return;
    const bool is = scene_->scene().camera.projection == lc::Camera::Projection::Panorama;
    if (is != panorama &&
        !editScene(projectionEdits(scene_->scene().camera, panorama), panorama ? "panorama" : "pinhole"))
        panoramaAction_->setChecked(is);
}

void MainWindow::setShadersEnabled(bool on) {
    useShaders_ = on;
    shadersAction_->setChecked(on);
    if (scene_) startRender();
}

// ---- rendering and the linked views -------------------------------------------------------------

void MainWindow::sceneChanged() {
    updateTitle();
    const lc::Scene& scene = scene_->scene();
    properties_->setDocument(scene_->document(), [this](const std::string& field) { return scene_->rangeOf(field); });
    panoramaAction_->setChecked(scene.camera.projection == lc::Camera::Projection::Panorama);
    {  // the file's observer event is where the slider's proper time starts
        const Json::Value& p = scene_->original()["observer"]["position"];
        lc::Vec4 file = lc::Vec4::Zero();
        if (p.isArray() && p.size() == 4)
            for (Json::ArrayIndex k = 0; k < 4; ++k) file(k) = p[k].asDouble();
        timeSlider_->setScene(scene, file);
    }
    for (DiagramDock* dock : {diagramDock_, trDock_})
        if (!dock->setScene(scene)) statusBar()->showMessage(dock->note());
    // Any metric: its null geodesics; the Goedel-only layers are disabled with the reason.
    spacetimeDock_->setScene(scene);
    spacetimeDock_->showObject(selection_->object());
    image_->markPixel(-1, -1);
    marked_ = {-1, -1};
    fillImagesTable();
    startRender();
}

void MainWindow::startRender() {
    const lc::Scene& scene = scene_->scene();
    imageSource_.clear();
    cpu_.reset();
    postRender_->setInput(scene, nullptr);    // the old data is not this scene's: none until it is traced
    image_->setNotice("rendering...", true);  // at once: the image below is the previous scene's
    const lc::cli::ShaderPath path = useShaders_ ? lc::cli::shaderPathFor(scene) : lc::cli::ShaderPath::None;
    // Goedel: the photo-objects (CPU work) come from the worker; the GUI thread only draws them.
    if (path != lc::cli::ShaderPath::None && path != lc::cli::ShaderPath::Godel) showShaderImage(nullptr);
    // The CPU render always runs (off this thread): it is the image where no shader draws the
    // scene, and the per-pixel data behind picking everywhere.
    progress_->setValue(0);
    progress_->setVisible(true);
    cancel_->setVisible(true);
    job_.start(scene, path == lc::cli::ShaderPath::Godel);
    accuracy_->showNoRender("rendering on the CPU...");
    accuracy_->clearPick();
    if (imageSource_.isEmpty())
        statusBar()->showMessage(path == lc::cli::ShaderPath::Godel ? "building the photo-objects..."
                                                                    : "rendering on the CPU...");
}

void MainWindow::showShaderImage(std::shared_ptr<const std::vector<lc::PhotoSceneObject>> photos) {
    const lc::Scene& scene = scene_->scene();
    QElapsedTimer timer;
    timer.start();
    try {
        shown_ = lc::cli::renderShaderImage(scene, std::move(photos));
        shaderSeconds_ = timer.elapsed() / 1000.0;
        imageSource_ = "shaders";
        image_->setImage(scene.camera.width, scene.camera.height, shown_);
        image_->setNotice("", false);
        emit shaderImageShown();
        statusBar()->showMessage(QString("shader image drawn in %1 s; tracing the per-pixel data on the CPU...")
                                     .arg(shaderSeconds_, 0, 'f', 3));
        // The shaders draw on this thread: where OpenGL is software (llvmpipe) a heavy scene
        // would freeze the window at every edit. The CPU renderer, off this thread, takes over.
        if (shaderSeconds_ > kSlowShaderSeconds) {
            useShaders_ = false;
            shadersAction_->setChecked(false);
            statusBar()->showMessage(QString("the shader image took %1 s on this OpenGL: images now come from the CPU "
                                             "renderer (View > Image from shaders turns the shaders on again)")
                                         .arg(shaderSeconds_, 0, 'f', 1));
        }
    } catch (const std::exception& e) {
        statusBar()->showMessage(QString("shader renderer: ") + e.what() + "; the CPU renderer draws the image");
    }
}

void MainWindow::cancelRender() { job_.cancel(); }

void MainWindow::onRenderFinished(std::shared_ptr<const lc::ColouredImage> image) {
    progress_->setVisible(false);
    cancel_->setVisible(false);
    cpu_ = std::move(image);
    const lc::RenderResult& r = cpu_->records;
    if (imageSource_ != "shaders") {
        shown_ = cpu_->rgb;
        imageSource_ = "cpu";
        image_->setImage(r.width, r.height, shown_);
    }
    image_->setNotice(QString::fromStdString(whyNoObjectIsSeen(scene_->scene(), r)), false);
    postRender_->setInput(scene_->scene(), cpu_);  // draws at once when post-rendering is on
    accuracy_->showRender(scene_->scene(), r);
    statusBar()->showMessage(QString("rendered %1 x %2 on the CPU in %3 s (%4), %5 object pixels; image from %6")
                                 .arg(r.width)
                                 .arg(r.height)
                                 .arg(r.stats.seconds, 0, 'f', 2)
                                 .arg(QString::fromStdString(lc::renderMethodName(lc::resolveMethod(scene_->scene()))))
                                 .arg(r.stats.hits)
                                 .arg(imageSource_));
    fillImagesTable();
    if (pendingPickI_ >= 0) {
        const int i = pendingPickI_, j = pendingPickJ_;
        pendingPickI_ = pendingPickJ_ = -1;
        pickPixel(i, j);
    }
}

void MainWindow::pickPixel(int i, int j) {
    if (!scene_) return;
    if (!cpu_) {  // picked while tracing (or after a cancel): answered when the data is there
        pendingPickI_ = i;
        pendingPickJ_ = j;
        if (!job_.running()) startRender();  // no way into a state that waits for nothing
        statusBar()->showMessage("tracing the per-pixel data; the pick follows when it is done");
        return;
    }
    const lc::RenderResult& r = cpu_->records;
    if (i < 0 || j < 0 || i >= r.width || j >= r.height) return;
    pickedI_ = i;
    pickedJ_ = j;
    const lc::Scene& scene = scene_->scene();
    const lc::PixelRecord& p = r.pixels[static_cast<std::size_t>(j) * r.width + i];
    const std::string text = describePixel(scene, p, i, j);
    accuracy_->showPick(scene, p, i, j);
    const bool onObject = p.kind == lc::PixelRecord::Object;
    if (onObject) selection_->selectObject(p.object);  // first: it refills the images table
    // The pixel's ray leaves along its camera direction, in the static frame of an observer at rest.
    if (scene.observerVelocity.tail<3>().norm() == 0) {
        const auto at = text.find('\'');
        const std::string name =
            at == std::string::npos ? std::string("object") : text.substr(at, text.find('\'', at + 1) - at + 1);
        selection_->selectRay({lc::frameCamera(scene).direction(i, j), onObject ? p.affine : 0.0, i, j,
                               onObject ? "picked: light path to " + name : "picked: pixel ray"});
    } else {
        selection_->clearRay();
    }
    statusBar()->showMessage(QString::fromStdString(text));
}

void MainWindow::showRay(const SelectedRay& ray) {
    const lc::Scene& scene = scene_->scene();
    // The diagram draws light paths that end on an object (closed form, Goedel).
    // The t-r diagram draws the same path against time, ending at its emission event.
    const bool drawn = ray.affine > 0 && hasClosedFormLightPaths(scene) && diagram_->hasDiagram();
    const std::vector<lc::Vec4> path =
        drawn ? lightPathAlong(scene, ray.direction, ray.affine) : std::vector<lc::Vec4>{};
    for (DiagramDock* dock : {diagramDock_, trDock_})
        if (drawn)
            dock->diagram()->highlightPath(path, ray.label);
        else
            dock->diagram()->clearHighlight();
    spacetimeDock_->showRay(ray);
    marked_ = {ray.i, ray.j};
    image_->markPixel(ray.i, ray.j);
}

void MainWindow::showObject(int object) {
    fillImagesTable();
    for (DiagramDock* dock : {diagramDock_, trDock_}) dock->diagram()->setHighlightedObject(object);
    spacetimeDock_->showObject(object);
}

void MainWindow::fillImagesTable() {
    if (!scene_) return;
    imagesTable_->showImagesOf(scene_->scene(), selection_->object());
    imagesDock_->setWindowTitle(imagesTable_->title());
}

void MainWindow::selectImageRow(int row) {
    if (const auto ray = imagesTable_->rayOfRow(row)) selection_->selectRay(*ray);
}

}  // namespace lcgui
