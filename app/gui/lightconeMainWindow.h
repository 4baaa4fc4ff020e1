#ifndef lightconeMainWindow_h
#define lightconeMainWindow_h
// The Lightcone workbench (docs/GUI.md): the egocentric image in the centre (from the views/
// shader renderers where a scene has one, the CPU renderer off the GUI thread otherwise and for
// the per-pixel data), docks for the linked r-phi diagram and spacetime view (3D), the scene's
// properties and the images of the selected object; one selection model links the views;
// sessions, undo/redo, exports through the CLI's own code.
#include "lightconeRenderJob.h"

#include "readers/io/session_file.hpp"

#include <QMainWindow>
#include <QUndoStack>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;

namespace lcgui {

class EgocentricImageWidget;
class ImagesTable;
class ObserverTimeSlider;
class PropertiesPanel;
class DiagramDock;
class DiagramWidget;
class SelectionModel;
class SpacetimeViewDock;
class PostRenderDock;
class AccuracyPanel;
struct SelectedRay;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Each returns false after showing the reason in an error dialog; the current scene, session
    // and edits are then unchanged. openFile tells sessions (a JSON object with
    // "lightcone_session") from scenes.
    bool openFile(const QString& path);
    bool openScene(const QString& path);
    bool openSession(const QString& path);
    bool saveSession(const QString& path);    // atomic; the session becomes the window's
    bool exportImage(const QString& path);    // PNG/EXR of the CPU render, as `lightcone render`
    bool exportDiagram(const QString& path);  // SVG/PDF/PNG, as `lightcone diagram`
    bool exportVtk(const QString& folder);    // .vtp/.vti/.vtm, as `lightcone export`

    // One undoable edit of one or more fields, checked by the scene reader. A refusal returns
    // false and shows the reader's reason at the field in the properties dock.
    bool editScene(const std::vector<lc::io::SceneEdit>& edits, const QString& description);
    // Edits that change what the scene holds (readers/io/structural_edits), each one undoable
    // edit; false, with the reason at the properties dock, when the reader refuses it.
    bool changeMetric(const QString& name);
    bool addSphere();
    bool addLight();
    bool duplicateElement(const QString& list, int index);  // list: "objects" or "lights"
    bool removeElement(const QString& list, int index);

    bool hasScene() const { return scene_.has_value(); }
    const lc::io::EditableScene& scene() const { return *scene_; }
    QUndoStack* undoStack() { return &undo_; }
    RenderJob* renderJob() { return &job_; }
    bool rendering() const { return job_.running(); }
    // The CPU render of the current scene once it is done (null before): per-pixel records.
    const lc::ColouredImage* cpuImage() const { return cpu_.get(); }
    // What the egocentric view shows: "shaders", "cpu" or "post-render".
    QString imageSource() const { return imageSource_; }
    const std::vector<float>& shownImage() const { return shown_; }
    double lastShaderSeconds() const { return shaderSeconds_; }
    bool shadersEnabled() const { return useShaders_; }
    void setShadersEnabled(bool on);

    EgocentricImageWidget* imageView() const { return image_; }
    DiagramWidget* diagramView() const { return diagram_; }
    DiagramDock* trDiagramDock() const { return trDock_; }
    SpacetimeViewDock* spacetimeView() const { return spacetimeDock_; }
    PostRenderDock* postRenderView() const { return postRender_; }
    SelectionModel* selectionModel() const { return selection_; }
    PropertiesPanel* properties() const { return properties_; }
    ImagesTable* imagesTable() const { return imagesTable_; }
    ObserverTimeSlider* observerTimeSlider() const { return timeSlider_; }
    QPushButton* cancelButton() const { return cancel_; }
    QString statusText() const;
    QString lastError() const { return lastError_; }
    QString lastNotice() const { return lastNotice_; }
    QString sessionPath() const { return sessionPath_; }
    // Where File > Export and Save session start: `name` beside the session, or else the scene file
    // ("image.png" -> "<folder>/<scene>.png"; a folder name -> "<folder>/<scene>-<name>").
    QString besideScene(const QString& name) const;
    AccuracyPanel* accuracyPanel() const { return accuracy_; }
    // Why the r-phi dock shows no diagram for this scene (empty when it shows one).
    QString diagramNote() const;
    QString aboutText() const;
    int pickedI() const { return pickedI_; }
    int pickedJ() const { return pickedJ_; }
    int selectedObject() const;
    // The pixel marked for the selected row of the images table ((-1, -1): none).
    std::pair<int, int> markedPixel() const { return marked_; }

public slots:
    void pickPixel(int i, int j);
    void cancelRender();
    // Turns the camera by a drag of (dx, dy) image pixels: the view follows the hand.
    void lookAround(double dx, double dy);
    void zoom(int steps);  // wheel: +1 narrows the field of view by 10 %
    void resetView();      // the scene file's camera direction, field of view and projection
    void setPanorama(bool panorama);
    void selectImageRow(int row);
    // The fan ray (plane z = 0) passing closest to the r-phi diagram's point (x, y), selected.
    void pickDiagramPoint(double x, double y);
    // Every dock shown, at its default place and size (View > Reset layout).
    void resetLayout();

signals:
    void shaderImageShown();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    friend class SceneEditCommand;
    void buildMenus();
    void buildDocks();
    void linkStructuralEdits();
    // The edit `make` builds from the current scene, applied as editScene does; a list index that
    // is gone is shown as a refusal too.
    bool editStructure(const std::function<lc::io::SceneEdit()>& make, const QString& description);
    void applyEditsNow(const std::vector<lc::io::SceneEdit>& edits);
    void adopt(lc::io::EditableScene scene, const QString& sceneFile, const QString& sessionFile);
    void sceneChanged();
    void startRender();
    void showShaderImage(std::shared_ptr<const std::vector<lc::PhotoSceneObject>> photos);
    void onRenderFinished(std::shared_ptr<const lc::ColouredImage> image);
    void fillImagesTable();
    void linkViews();
    // The selection model's ray and object, drawn in every view.
    void showRay(const SelectedRay& ray);
    void showObject(int object);
    void updateTitle();
    void showError(const QString& title, const QString& text);
    // Runs one export; a failure is shown as "Cannot export the <what>" with the reason.
    bool exportWith(const QString& what, const QString& path, const std::function<void()>& write);
    bool maybeSave();  // before losing unsaved edits: save, discard or cancel (false)
    bool saveSessionAs();
    void addRecent(const QString& path);
    void refreshRecentMenu();
    lc::io::SessionFile currentSession(const QString& sessionFile) const;

    std::optional<lc::io::EditableScene> scene_;
    QString sceneFile_, sessionPath_;
    QUndoStack undo_;
    RenderJob job_;
    std::shared_ptr<const lc::ColouredImage> cpu_;
    std::vector<float> shown_;
    QString imageSource_;
    double shaderSeconds_ = 0;
    bool useShaders_ = true;
    int pickedI_ = -1, pickedJ_ = -1;
    int pendingPickI_ = -1, pendingPickJ_ = -1;
    std::pair<int, int> marked_{-1, -1};
    QString lastError_, lastNotice_;
    QByteArray defaultLayout_;

    EgocentricImageWidget* image_ = nullptr;
    SelectionModel* selection_ = nullptr;  // the one selection all views share
    DiagramWidget* diagram_ = nullptr;
    SpacetimeViewDock* spacetimeDock_ = nullptr;
    PostRenderDock* postRender_ = nullptr;
    QDockWidget* postRenderDock_ = nullptr;
    PropertiesPanel* properties_ = nullptr;
    ImagesTable* imagesTable_ = nullptr;
    DiagramDock* diagramDock_ = nullptr;
    QDockWidget *propertiesDock_ = nullptr, *imagesDock_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QAction* panoramaAction_ = nullptr;
    ObserverTimeSlider* timeSlider_ = nullptr;
    QAction* shadersAction_ = nullptr;
    AccuracyPanel* accuracy_ = nullptr;
    DiagramDock* trDock_ = nullptr;  // the t-r spacetime diagram, a tab beside the r-phi one
    QDockWidget* accuracyDock_ = nullptr;
};

}  // namespace lcgui

#endif
