// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The properties dock: every field of the scene as a tree (metric, observer, camera, objects,
// lights, sky, render), values edited in place. Metric parameters and render settings the file
// leaves out are listed with their defaults, so they can be set too. The panel only proposes
// edits (editRequested); the window applies them through the scene reader, and a refusal comes
// back through showRefusal: the field turns red, its tooltip and the line below the tree give
// the reader's reason, and the value shown returns to the scene's. Above the tree, the metric
// chooser (built-ins and formula files) and Add sphere / Add light; an object's or light's context menu duplicates or
// removes it (the window turns these into io/structural_edits).
#include "core/input/ranges.hpp"
#include "readers/io/field_guide.hpp"

#include <json/json.h>

#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

class QComboBox;
class QLabel;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

Q_DECLARE_METATYPE(Json::Value)

namespace lc::gui {

class PropertiesPanel : public QWidget {
    Q_OBJECT
public:
    explicit PropertiesPanel(QWidget* parent = nullptr);

    // `rangeOf` gives the accepted range of a number field as the scene reader checked it
    // (io::EditableScene::rangeOf): each such field's tooltip says it, with the unit and why.
    using RangeOf = std::function<const lc::input::Range*(const std::string& field)>;
    // sceneFolder: what the metric's file is relative to (a catalogue file is shown as its item).
    // `chart`: the scene's chart and guide page, for the tooltips' units and F1 (io/field_guide).
    void setDocument(const Json::Value& scene, RangeOf rangeOf = {}, const QString& sceneFolder = {},
                     lc::io::ChartGuide chart = lc::io::defaultChartGuide());
    void showRefusal(const QString& field, const QString& reason);
    QString refusalText() const;

    QTreeWidget* tree() const { return tree_; }
    // The value cell of a field ("metric.a", "objects[0].radius"); null when not listed.
    QTreeWidgetItem* itemOf(const QString& field) const;

    // Built-in metrics by name, the catalogue's metric files (metricCatalogueEntries: each with its
    // summary as tooltip and its thumbnail; chosen: metricFileChosen), the scene's typed metric when
    // it has one, and kFormulaFileText, which asks for a metric file (formulaFileRequested).
    QComboBox* metricChooser() const { return metric_; }
    static const QString kFormulaFileText;
    QToolButton* addSphereButton() const { return addSphere_; }
    QToolButton* addLightButton() const { return addLight_; }
    // The object or light the item belongs to, as "objects" or "lights" and its index; an empty
    // list name when the item is in neither.
    static std::pair<QString, int> elementOf(const QTreeWidgetItem* item);
    // The current item's element (Edit > Duplicate, Edit > Remove).
    std::pair<QString, int> currentElement() const;

    // The guide's page and section for the current item (F1): the field's, else the scene's kind.
    std::pair<QString, QString> helpTarget() const;
    QString scenePage() const { return QString::fromStdString(chart_.page); }
    // The words a field takes (io::fieldGuide's choices that are single words), for its editor.
    QStringList wordChoices(const QString& field) const;

    // Text shown for a value: numbers in their shortest exact form, lists as "[1, 0, 0]".
    static QString format(const Json::Value& v);
    // A typed text for a field whose current value is `like`: JSON, with "[...]" optional for
    // lists and quotes optional for text. False when it is neither.
    static bool parse(const QString& text, const Json::Value& like, Json::Value& out);

signals:
    void editRequested(const QString& field, const Json::Value& value);
    void metricChosen(const QString& name);
    void metricFileChosen(const QString& path);
    void formulaFileRequested();
    void sphereAddRequested();
    void lightAddRequested();
    void duplicateRequested(const QString& list, int index);
    void removeRequested(const QString& list, int index);

private:
    void addValue(QTreeWidgetItem* parent, const QString& label, const QString& field, const Json::Value& v);
    // The children of a container item (its members or elements), with an object's defaults.
    void addChildren(QTreeWidgetItem* item, const QString& field, const Json::Value& v);
    void addDiskDefaults(QTreeWidgetItem* item, const QString& field, const Json::Value& disk);
    // A value the file leaves out, shown in grey with the reader's default; `range`: what an edit
    // may set it to (from the same tables the reader checks with).
    void addDefault(QTreeWidgetItem* parent, const QString& key, const QString& field, const Json::Value& fallback,
                    std::optional<lc::input::Range> range = std::nullopt);
    void onItemChanged(QTreeWidgetItem* item, int column);
    void showMetricInChooser(const Json::Value& metric, const QString& sceneFolder);
    // The chooser's item of that catalogue file (the same file, links resolved); -1 if none.
    int catalogueItemOf(const QString& metricFile, const QString& sceneFolder) const;
    void showElementMenu(const QPoint& at);
    // The tooltip of an item: what the field means, its unit and chart, its choices, the range
    // the reader accepts (a number's), and where the guide explains it.
    void describe(QTreeWidgetItem* item, const QString& field, bool isDefault, const lc::input::Range* range = nullptr);

    QTreeWidget* tree_ = nullptr;
    QLabel* refusal_ = nullptr;
    QComboBox* metric_ = nullptr;
    int shownMetric_ = -1;  // the chooser's item of the scene's metric
    QToolButton *addSphere_ = nullptr, *addLight_ = nullptr;
    bool filling_ = false;
    // Long lists (more than kListedAtOnce elements: 4096 objects, a world line's points) are
    // filled when first expanded, from the document by their field path: listing every number of
    // a 40 MB scene froze the window 10 s. The document is the scene's (ActiveScene keeps it at
    // one address and calls setDocument on every change).
    std::unordered_map<QTreeWidgetItem*, QString> unlisted_;
    const Json::Value* document_ = nullptr;
    RangeOf rangeOf_;
    lc::io::ChartGuide chart_ = lc::io::defaultChartGuide();
};

}  // namespace lc::gui
