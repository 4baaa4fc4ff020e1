// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The workbench's views, placed in the main window: the egocentric image in the centre, the r-phi
// and t-r diagrams and the spacetime view (3D) on the right, properties, post-rendering, accuracy
// and the metric editor tabbed on the left, the images of the selected object below, the observer's time
// slider for the toolbar. showScene() puts a scene in every one of them; resetLayout() puts the
// docks back where they start.
#include "readers/io/field_guide.hpp"

#include <QObject>
#include <QString>

#include <utility>
#include <vector>

class QDockWidget;
class QMainWindow;

namespace lc::gui {

class AccuracyPanel;
class ActiveScene;
class DiagramDock;
class DiagramWidget;
class EgocentricImageWidget;
class ImagesTable;
class MetricEditor;
class ObserverTimeSlider;
class PostRenderDock;
class PropertiesPanel;
class SpacetimeViewDock;

class WorkbenchDocks : public QObject {
    Q_OBJECT
public:
    explicit WorkbenchDocks(QMainWindow* window);

    EgocentricImageWidget* imageView() const { return image_; }
    DiagramWidget* diagramView() const;
    DiagramDock* rPhiDiagramDock() const { return rPhiDock_; }
    DiagramDock* trDiagramDock() const { return trDock_; }
    SpacetimeViewDock* spacetimeView() const { return spacetimeDock_; }
    PropertiesPanel* properties() const { return properties_; }
    ImagesTable* imagesTable() const { return imagesTable_; }
    QDockWidget* imagesDock() const { return imagesDock_; }
    PostRenderDock* postRenderView() const { return postRender_; }
    AccuracyPanel* accuracyPanel() const { return accuracy_; }
    MetricEditor* metricEditor() const { return metricEditor_; }
    QDockWidget* metricEditorDock() const { return metricEditorDock_; }
    ObserverTimeSlider* observerTimeSlider() const { return timeSlider_; }
    // Every dock, in the order View lists them.
    std::vector<QDockWidget*> docks() const;
    // Why the r-phi dock shows no diagram for this scene (empty when it shows one).
    QString diagramNote() const;

    // The scene in the properties tree, the time slider, the diagrams and the 3D view; the text
    // returned says why a diagram dock is empty (empty when both have a diagram).
    QString showScene(const ActiveScene& scene, int selectedObject);
    // The scene's chart and guide page (tooltips, F1).
    static lc::io::ChartGuide chartGuide(const ActiveScene& scene);
    // Where F1 opens the guide: on a field of the properties tree (it has the focus) that field's
    // section, else the page of the scene's kind.
    std::pair<QString, QString> guideTarget() const;
    // The properties tree as the scene is, and the reader's reason at the field.
    void showRefusal(const ActiveScene& scene, const QString& field, const QString& reason);

    // The layout resetLayout() returns to: the window's once its menus and toolbar are built.
    void rememberDefaultLayout();

public slots:
    // Every dock shown, at its default place and size (View > Reset layout).
    void resetLayout();

private:
    QMainWindow* window_;
    EgocentricImageWidget* image_ = nullptr;
    DiagramDock *rPhiDock_ = nullptr, *trDock_ = nullptr;
    SpacetimeViewDock* spacetimeDock_ = nullptr;
    PropertiesPanel* properties_ = nullptr;
    QDockWidget *propertiesDock_ = nullptr, *imagesDock_ = nullptr, *postRenderDock_ = nullptr,
                *accuracyDock_ = nullptr, *metricEditorDock_ = nullptr;
    ImagesTable* imagesTable_ = nullptr;
    PostRenderDock* postRender_ = nullptr;
    AccuracyPanel* accuracy_ = nullptr;
    MetricEditor* metricEditor_ = nullptr;
    ObserverTimeSlider* timeSlider_ = nullptr;
    QByteArray defaultLayout_;
};

}  // namespace lc::gui
