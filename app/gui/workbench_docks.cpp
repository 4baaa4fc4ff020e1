// SPDX-License-Identifier: BSD-3-Clause
#include "workbench_docks.hpp"

#include "accuracy_panel.hpp"
#include "active_scene.hpp"
#include "diagram_dock.hpp"
#include "egocentric_image_widget.hpp"
#include "images_table.hpp"
#include "metric_editor.hpp"
#include "observer_time_slider.hpp"
#include "post_render_dock.hpp"
#include "properties_panel.hpp"
#include "spacetime_view_dock.hpp"

#include <QApplication>
#include <QDockWidget>
#include <QStyle>
#include <QTreeWidget>
#include <QMainWindow>

namespace lc::gui {
namespace {

QDockWidget* dockAround(QMainWindow* window, QWidget* content, const QString& title, const char* name) {
    auto* dock = new QDockWidget(title, window);
    dock->setObjectName(name);
    dock->setWidget(content);
    return dock;
}

}  // namespace

WorkbenchDocks::WorkbenchDocks(QMainWindow* window) : QObject(window), window_(window) {
    image_ = new EgocentricImageWidget(window);
    image_->setObjectName("egocentricImage");
    image_->setMinimumSize(320, 160);
    window->setCentralWidget(image_);

    rPhiDock_ = new DiagramDock(DiagramWidget::RPhi, window);
    window->addDockWidget(Qt::RightDockWidgetArea, rPhiDock_);
    spacetimeDock_ = new SpacetimeViewDock(window);
    window->addDockWidget(Qt::RightDockWidgetArea, spacetimeDock_);
    window->splitDockWidget(rPhiDock_, spacetimeDock_, Qt::Vertical);
    trDock_ = new DiagramDock(DiagramWidget::TR, window);  // a tab beside the r-phi diagram
    window->addDockWidget(Qt::RightDockWidgetArea, trDock_);
    window->tabifyDockWidget(rPhiDock_, trDock_);
    rPhiDock_->raise();

    properties_ = new PropertiesPanel(window);
    propertiesDock_ = dockAround(window, properties_, "Properties", "propertiesDock");
    window->addDockWidget(Qt::LeftDockWidgetArea, propertiesDock_);
    imagesTable_ = new ImagesTable(window);
    imagesDock_ = dockAround(window, imagesTable_, "Images of the selected object", "imagesDock");
    window->addDockWidget(Qt::BottomDockWidgetArea, imagesDock_);
    // Post-rendering: the CPU data coloured again on the GPU while its sliders move.
    postRender_ = new PostRenderDock(window);
    postRender_->setObjectName("postRender");
    postRenderDock_ = dockAround(window, postRender_, "Post-rendering", "postRenderDock");
    window->addDockWidget(Qt::LeftDockWidgetArea, postRenderDock_);
    window->tabifyDockWidget(propertiesDock_, postRenderDock_);
    // How far to trust the image: the render's figures and the picked ray's.
    accuracy_ = new AccuracyPanel(window);
    accuracyDock_ = dockAround(window, accuracy_, "Accuracy", "accuracyDock");
    window->addDockWidget(Qt::LeftDockWidgetArea, accuracyDock_);
    window->tabifyDockWidget(postRenderDock_, accuracyDock_);  // a third tab beside Properties and Post-rendering
    // The metric written as text, edited and applied in place.
    metricEditor_ = new MetricEditor(window);
    metricEditorDock_ = dockAround(window, metricEditor_, "Metric editor", "metricEditorDock");
    window->addDockWidget(Qt::LeftDockWidgetArea, metricEditorDock_);
    window->tabifyDockWidget(accuracyDock_, metricEditorDock_);
    propertiesDock_->raise();
    // Four tabs across the left dock leave their titles a pixel to spare at 1280 px (they were
    // cut with a longer one): on the dock's edge each reads whole, whatever the font.
    window->setTabPosition(Qt::LeftDockWidgetArea, QTabWidget::West);
    timeSlider_ = new ObserverTimeSlider(window);
    // Further docks go here: docks() lists them for the View menu and resetLayout.
}

void WorkbenchDocks::rememberDefaultLayout() { defaultLayout_ = window_->saveState(); }

DiagramWidget* WorkbenchDocks::diagramView() const { return rPhiDock_->diagram(); }

std::vector<QDockWidget*> WorkbenchDocks::docks() const {
    return {propertiesDock_, rPhiDock_,       trDock_,       spacetimeDock_,
            imagesDock_,     postRenderDock_, accuracyDock_, metricEditorDock_};
}

QString WorkbenchDocks::diagramNote() const { return rPhiDock_->note(); }

void WorkbenchDocks::resetLayout() {
    window_->restoreState(defaultLayout_);
    for (QDockWidget* d : docks()) d->show();
    propertiesDock_->raise();
    rPhiDock_->raise();
    window_->resizeDocks({propertiesDock_, rPhiDock_}, {window_->width() / 5, window_->width() / 3}, Qt::Horizontal);
    // Four images whole (a Goedel scene's first two windings), more where the window is tall.
    const int titleBar = imagesDock_->style()->pixelMetric(QStyle::PM_TitleBarHeight);
    window_->resizeDocks({imagesDock_}, {std::max(window_->height() / 5, imagesTable_->heightForRows(4) + titleBar)},
                         Qt::Vertical);
}

lc::io::ChartGuide WorkbenchDocks::chartGuide(const ActiveScene& active) {
    const lc::io::EditableScene& edited = active.scene();
    return edited.scene().spacetime ? lc::io::chartGuideOf(edited.document()["metric"], *edited.scene().spacetime)
                                    : lc::io::defaultChartGuide();
}

std::pair<QString, QString> WorkbenchDocks::guideTarget() const {
    // The tree, or a value's editor open in it.
    const QWidget* focus = QApplication::focusWidget();
    if (focus && (focus == properties_->tree() || properties_->tree()->isAncestorOf(focus)))
        return properties_->helpTarget();
    return {properties_->scenePage(), QString()};
}

QString WorkbenchDocks::showScene(const ActiveScene& active, int selectedObject) {
    const lc::io::EditableScene& edited = active.scene();
    const lc::Scene& scene = edited.scene();
    properties_->setDocument(
        edited.document(), [&edited](const std::string& field) { return edited.rangeOf(field); },
        QString::fromStdString(edited.baseDir()), chartGuide(active));
    metricEditor_->showMetric(edited.document()["metric"], QString::fromStdString(edited.baseDir()));
    {  // the file's observer event is where the slider's proper time starts
        const Json::Value p = edited.originalValue("observer.position");
        lc::Vec4 file = lc::Vec4::Zero();
        if (p.isArray() && p.size() == 4)
            for (Json::ArrayIndex k = 0; k < 4; ++k) file(k) = p[k].asDouble();
        timeSlider_->setScene(scene, file);
    }
    QString why;
    for (DiagramDock* dock : {rPhiDock_, trDock_})
        if (!dock->setScene(scene)) why = dock->note();
    // Any metric: its null geodesics; the Goedel-only layers are disabled with the reason.
    spacetimeDock_->setScene(scene);
    spacetimeDock_->showObject(selectedObject);
    return why;
}

void WorkbenchDocks::showRefusal(const ActiveScene& active, const QString& field, const QString& reason) {
    // The tree as the scene is, at once (a refused metric or list edit changed more than a cell).
    const lc::io::EditableScene& edited = active.scene();
    properties_->setDocument(
        edited.document(), [&edited](const std::string& f) { return edited.rangeOf(f); },
        QString::fromStdString(edited.baseDir()), chartGuide(active));
    properties_->showRefusal(field, reason);
}

}  // namespace lc::gui
