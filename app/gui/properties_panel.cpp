// SPDX-License-Identifier: BSD-3-Clause
#include "properties_panel.hpp"

#include "core/metrics/factory.hpp"
#include "metric_catalogue_entries.hpp"

#include <QBrush>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QStyledItemDelegate>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <cstdio>
#include <cstdlib>

namespace lc::gui {
namespace {

constexpr int kFieldRole = Qt::UserRole;        // the field path
constexpr int kValueRole = Qt::UserRole + 1;    // the current value as JSON text (empty: default)
constexpr int kElementRole = Qt::UserRole + 2;  // on an object's or light's own item: "objects[2]"
constexpr int kPathRole0 = Qt::UserRole + 3;    // on column 0 of every item: its field path
constexpr Json::ArrayIndex kListedAtOnce = 64;  // longer lists are filled when expanded

// Fields with a few words to choose from get a list to pick from (still editable: a number or a
// file name where the field also takes one).
class ChoiceDelegate : public QStyledItemDelegate {
public:
    ChoiceDelegate(const lc::gui::PropertiesPanel* panel, QObject* parent)
        : QStyledItemDelegate(parent), panel_(panel) {}
    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                          const QModelIndex& index) const override {
        const QStringList words = panel_->wordChoices(index.data(kFieldRole).toString());
        if (words.isEmpty()) return QStyledItemDelegate::createEditor(parent, option, index);
        auto* combo = new QComboBox(parent);
        combo->setObjectName("choiceEditor");
        combo->setEditable(true);
        combo->addItems(words);
        return combo;
    }
    void setEditorData(QWidget* editor, const QModelIndex& index) const override {
        if (auto* combo = qobject_cast<QComboBox*>(editor))
            combo->setCurrentText(index.data(Qt::DisplayRole).toString());
        else
            QStyledItemDelegate::setEditorData(editor, index);
    }
    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override {
        if (auto* combo = qobject_cast<QComboBox*>(editor))
            model->setData(index, combo->currentText(), Qt::EditRole);
        else
            QStyledItemDelegate::setModelData(editor, model, index);
    }

private:
    const lc::gui::PropertiesPanel* panel_;
};

QString jsonText(const Json::Value& v) {
    Json::StreamWriterBuilder w;
    w["indentation"] = "";
    w["precision"] = 17;
    return QString::fromStdString(Json::writeString(w, v));
}

Json::Value fromJsonText(const QString& text) {
    Json::CharReaderBuilder b;
    std::unique_ptr<Json::CharReader> reader(b.newCharReader());
    const std::string s = text.toStdString();
    Json::Value v;
    std::string errors;
    if (!reader->parse(s.data(), s.data() + s.size(), &v, &errors)) return Json::Value();
    return v;
}

// The value at a field path ("objects[3].motion.points") in a document; null where there is none.
const Json::Value* valueAtField(const Json::Value& root, const QString& field) {
    const Json::Value* v = &root;
    const QString spaced = QString(field).replace('[', ".[");
    for (const QString& part : spaced.split('.', Qt::SkipEmptyParts)) {
        if (part.startsWith('[')) {
            bool ok = false;
            const int k = part.mid(1, part.size() - 2).toInt(&ok);
            if (!ok || !v->isArray() || k < 0 || static_cast<Json::ArrayIndex>(k) >= v->size()) return nullptr;
            v = &(*v)[static_cast<Json::ArrayIndex>(k)];
        } else {
            if (!v->isObject() || !v->isMember(part.toStdString())) return nullptr;
            v = &(*v)[part.toStdString()];
        }
    }
    return v;
}

// Render settings the file may leave out, with what the reader then uses and the range it accepts.
struct Default {
    const char* name;
    const char* fallback;
    const lc::input::Range* range;
};
const Default kRenderDefaults[] = {{"method", "auto", nullptr},
                                   {"stepper", "auto", nullptr},
                                   {"tolerance", "1e-10", &lc::input::kTolerance},
                                   {"windings", "2", &lc::input::kWindings},
                                   {"magnification", "false", nullptr}};

// A disk's settings the file may leave out, with what the reader then uses (readDisk).
const Default kDiskDefaults[] = {{"inner_radius", "isco", &lc::input::kDiskRadius},
                                 {"outer_radius", "20", &lc::input::kDiskRadius},
                                 {"sense", "prograde", nullptr},
                                 {"emission", "blackbody", nullptr},
                                 {"temperature", "10000", &lc::input::kTemperature}};

std::optional<lc::input::Range> defaultRange(const Default& d) {
    return d.range ? std::optional<lc::input::Range>(*d.range) : std::nullopt;
}

// What an item of the metric chooser is (its Qt::UserRole data); a catalogue item's file is its
// kPathRole data.
constexpr int kBuiltinItem = 0, kTypedItem = 1, kFormulaFileItem = 2, kCatalogueItem = 3;
constexpr int kPathRole = Qt::UserRole + 1;

}  // namespace

const QString PropertiesPanel::kFormulaFileText = "formula file...";

PropertiesPanel::PropertiesPanel(QWidget* parent) : QWidget(parent) {
    qRegisterMetaType<Json::Value>("Json::Value");  // editRequested may be queued
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* kinds = new QHBoxLayout;
    kinds->addWidget(new QLabel("metric", this));
    metric_ = new QComboBox(this);
    metric_->setObjectName("metricChooser");
    for (const auto& m : lc::knownMetrics()) {
        metric_->addItem(QString::fromStdString(m.name), kBuiltinItem);
        metric_->setItemData(metric_->count() - 1, QString::fromStdString(m.summary), Qt::ToolTipRole);
    }
    // The catalogue's files, each with its summary and the gallery's thumbnail.
    const std::vector<MetricCatalogueEntry> catalogue = metricCatalogueEntries();
    if (!catalogue.empty()) metric_->insertSeparator(metric_->count());
    for (const MetricCatalogueEntry& e : catalogue) {
        metric_->addItem(e.thumbnail, e.label, kCatalogueItem);
        metric_->setItemData(metric_->count() - 1, e.path, kPathRole);
        metric_->setItemData(metric_->count() - 1, e.path + "\n" + e.summary, Qt::ToolTipRole);
    }
    metric_->setIconSize(QSize(64, 32));  // the gallery's 2:1 images
    // Long catalogue names must not widen the dock past a 1280 px window; the list shows them whole.
    metric_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    metric_->setMinimumContentsLength(12);
    metric_->addItem(kFormulaFileText, kFormulaFileItem);
    metric_->setItemData(metric_->count() - 1, "A metric written as text (docs/METRICS.md), from its file",
                         Qt::ToolTipRole);
    metric_->setToolTip(
        "Another metric, its parameters at their defaults, or a formula file (one undoable edit); "
        "View > Metric editor edits the formula");
    kinds->addWidget(metric_, 1);
    addSphere_ = new QToolButton(this);
    addSphere_->setObjectName("addSphere");
    addSphere_->setText("+ sphere");
    addSphere_->setToolTip("Add a sphere ahead of the camera");
    addLight_ = new QToolButton(this);
    addLight_->setObjectName("addLight");
    addLight_->setText("+ light");
    addLight_->setToolTip("Add a 6500 K light above the observer");
    kinds->addWidget(addSphere_);
    kinds->addWidget(addLight_);
    layout->addLayout(kinds);
    connect(metric_, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
        const int kind = metric_->itemData(index).toInt();
        if (kind == kBuiltinItem) emit metricChosen(metric_->itemText(index));
        if (kind == kCatalogueItem) emit metricFileChosen(metric_->itemData(index, kPathRole).toString());
        if (kind != kFormulaFileItem) return;
        metric_->setCurrentIndex(shownMetric_);  // the scene's metric until a file is chosen
        emit formulaFileRequested();
    });
    connect(addSphere_, &QToolButton::clicked, this, &PropertiesPanel::sphereAddRequested);
    connect(addLight_, &QToolButton::clicked, this, &PropertiesPanel::lightAddRequested);
    tree_ = new QTreeWidget(this);
    tree_->setObjectName("propertiesTree");
    tree_->setColumnCount(2);
    tree_->setHeaderLabels({"field", "value"});
    tree_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    tree_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                           QAbstractItemView::SelectedClicked);
    tree_->setItemDelegateForColumn(1, new ChoiceDelegate(this, tree_));
    layout->addWidget(tree_, 1);
    refusal_ = new QLabel(this);
    refusal_->setObjectName("refusalLabel");
    refusal_->setWordWrap(true);
    refusal_->setStyleSheet("color: #b00020");
    layout->addWidget(refusal_);
    connect(tree_, &QTreeWidget::itemChanged, this, &PropertiesPanel::onItemChanged);
    connect(tree_, &QTreeWidget::itemExpanded, this, [this](QTreeWidgetItem* item) {
        const auto waiting = unlisted_.find(item);
        if (waiting == unlisted_.end()) return;
        const QString field = waiting->second;
        unlisted_.erase(waiting);
        const Json::Value* value = document_ ? valueAtField(*document_, field) : nullptr;
        if (!value) return;
        const bool wasFilling = filling_;
        filling_ = true;
        item->setText(1, QString());
        addChildren(item, field, *value);
        filling_ = wasFilling;
    });
    tree_->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(tree_, &QTreeWidget::customContextMenuRequested, this, &PropertiesPanel::showElementMenu);
}

std::pair<QString, int> PropertiesPanel::elementOf(const QTreeWidgetItem* item) {
    for (; item; item = item->parent()) {
        const QString element = item->data(0, kElementRole).toString();
        if (element.isEmpty()) continue;
        const int open = element.indexOf('[');
        return {element.left(open), element.mid(open + 1, element.size() - open - 2).toInt()};
    }
    return {QString(), -1};
}

std::pair<QString, int> PropertiesPanel::currentElement() const { return elementOf(tree_->currentItem()); }

void PropertiesPanel::showElementMenu(const QPoint& at) {
    QTreeWidgetItem* item = tree_->itemAt(at);
    const auto [list, index] = elementOf(item);
    if (list.isEmpty()) return;
    tree_->setCurrentItem(item);
    QMenu menu(this);
    menu.setObjectName("elementMenu");
    const QString what = QString("%1[%2]").arg(list).arg(index);
    menu.addAction("Duplicate " + what, this,
                   [this, list = list, index = index] { emit duplicateRequested(list, index); });
    menu.addAction("Remove " + what, this, [this, list = list, index = index] { emit removeRequested(list, index); });
    menu.exec(tree_->viewport()->mapToGlobal(at));
}

QString PropertiesPanel::format(const Json::Value& v) {
    if (v.isIntegral()) return QString::number(v.asLargestInt());
    if (v.isDouble()) {
        // The shortest text that reads back as the same double.
        char buf[40];
        for (int digits = 1; digits <= 17; ++digits) {
            std::snprintf(buf, sizeof buf, "%.*g", digits, v.asDouble());
            if (std::strtod(buf, nullptr) == v.asDouble()) break;
        }
        return buf;
    }
    if (v.isString()) return QString::fromStdString(v.asString());
    if (v.isArray()) {
        QStringList parts;
        for (const auto& e : v) parts << format(e);
        return "[" + parts.join(", ") + "]";
    }
    if (v.isObject()) return "{" + QString::number(v.size()) + " fields}";
    return jsonText(v).trimmed();
}

bool PropertiesPanel::parse(const QString& text, const Json::Value& like, Json::Value& out) {
    const QString t = text.trimmed();
    if (like.isString()) {
        out = Json::Value(t.toStdString());
        return true;
    }
    QString json = t;
    if (like.isArray() && !t.startsWith('[')) json = "[" + t + "]";
    Json::CharReaderBuilder b;
    b["failIfExtra"] = true;
    std::unique_ptr<Json::CharReader> reader(b.newCharReader());
    const std::string s = json.toStdString();
    std::string errors;
    if (!reader->parse(s.data(), s.data() + s.size(), &out, &errors)) {
        // A word: a default shown as text (a stepper), or a name where the field had numbers (an
        // observer's "zamo" for its 4-velocity, a disk's "isco"); the reader judges it.
        if (!t.isEmpty() && t[0].isLetter()) {
            out = Json::Value(t.toStdString());
            return true;
        }
        return false;
    }
    return true;
}

void PropertiesPanel::addValue(QTreeWidgetItem* parent, const QString& label, const QString& field,
                               const Json::Value& v) {
    auto* item = new QTreeWidgetItem(parent, {label});
    const bool numberList = v.isArray() && v.size() > 0 && v[0].isNumeric();
    if (v.isObject() || (v.isArray() && !numberList)) {
        describe(item, field, false);
        if (v.isArray() && v.size() > kListedAtOnce) {
            item->setText(1, QString("%1 elements (expand to list them)").arg(v.size()));
            item->setChildIndicatorPolicy(QTreeWidgetItem::ShowIndicator);
            unlisted_[item] = field;
            return;
        }
        addChildren(item, field, v);
        return;
    }
    item->setText(1, format(v));
    item->setData(1, kFieldRole, field);
    item->setData(1, kValueRole, jsonText(v));
    item->setFlags(item->flags() | Qt::ItemIsEditable);
    if (field == "description") item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    describe(item, field, false);
}

void PropertiesPanel::describe(QTreeWidgetItem* item, const QString& field, bool isDefault,
                               const lc::input::Range* range) {
    item->setData(0, kPathRole0, field);
    const lc::io::FieldGuide help =
        lc::io::fieldGuide(field.toStdString(), chart_, document_ ? *document_ : Json::Value::nullSingleton());
    // A value's range as the reader checked it; a default's from the table it was listed with.
    if (!range && !item->data(1, kFieldRole).isNull() && rangeOf_) range = rangeOf_(field.toStdString());
    const std::string accepted = range ? range->describe() + " (" + range->why + ")" : std::string();
    QString tip = QString::fromStdString(help.tooltip(accepted));
    if (isDefault) tip = "default (not in the scene file): edit to set it\n" + tip;
    if (item->text(1).size() > 40) tip = item->text(1) + "\n\n" + tip;  // shown cut in the cell
    item->setToolTip(0, tip);
    item->setToolTip(1, tip);
}

void PropertiesPanel::addChildren(QTreeWidgetItem* item, const QString& field, const Json::Value& v) {
    if (v.isObject()) {
        for (const auto& key : v.getMemberNames())
            addValue(item, QString::fromStdString(key), field + "." + QString::fromStdString(key), v[key]);
        if (field.startsWith("objects[") && v["type"].asString() == "disk") addDiskDefaults(item, field, v);
    } else {
        for (Json::ArrayIndex k = 0; k < v.size(); ++k) {
            const QString name =
                v[k].isObject() && v[k].isMember("name") ? " " + QString::fromStdString(v[k]["name"].asString()) : "";
            addValue(item, QString("[%1]%2").arg(k).arg(name), field + QString("[%1]").arg(k), v[k]);
            if (field == "objects" || field == "lights")
                item->child(item->childCount() - 1)->setData(0, kElementRole, field + QString("[%1]").arg(k));
        }
    }
    item->setExpanded(true);
}

// An accretion disk's settings the file leaves out (the inner edge stays the ISCO unless given).
void PropertiesPanel::addDiskDefaults(QTreeWidgetItem* item, const QString& field, const Json::Value& disk) {
    for (const Default& d : kDiskDefaults)
        if (!disk.isMember(d.name)) {
            const Json::Value v = fromJsonText(d.fallback);
            addDefault(item, d.name, field + "." + d.name, v.isNull() ? Json::Value(d.fallback) : v, defaultRange(d));
        }
}

void PropertiesPanel::addDefault(QTreeWidgetItem* parent, const QString& key, const QString& field,
                                 const Json::Value& fallback, std::optional<lc::input::Range> range) {
    auto* item = new QTreeWidgetItem(parent, {key});
    item->setText(1, format(fallback));
    item->setData(1, kFieldRole, field);
    item->setData(1, kValueRole, QString());  // not in the file
    describe(item, field, true, range ? &*range : nullptr);
    item->setForeground(1, QBrush(Qt::gray));
    item->setFlags(item->flags() | Qt::ItemIsEditable);
}

int PropertiesPanel::catalogueItemOf(const QString& metricFile, const QString& sceneFolder) const {
    const QString canonical = QFileInfo(QDir(sceneFolder).absoluteFilePath(metricFile)).canonicalFilePath();
    if (canonical.isEmpty()) return -1;
    for (int k = 0; k < metric_->count(); ++k)  // items hold canonical paths (metricCatalogueEntries)
        if (metric_->itemData(k).toInt() == kCatalogueItem && metric_->itemData(k, kPathRole).toString() == canonical)
            return k;
    return -1;
}

void PropertiesPanel::showMetricInChooser(const Json::Value& metric, const QString& sceneFolder) {
    // A typed metric is listed as the chooser's current item, just above "formula file..."; a
    // catalogue file is its own item.
    const int typed = metric_->findData(kTypedItem);
    if (typed >= 0) metric_->removeItem(typed);
    const int catalogued =
        metric.isMember("file") ? catalogueItemOf(QString::fromStdString(metric["file"].asString()), sceneFolder) : -1;
    if (metric.isMember("name")) {
        shownMetric_ = metric_->findText(QString::fromStdString(metric["name"].asString()));
    } else if (catalogued >= 0) {
        shownMetric_ = catalogued;
    } else {
        const QString what =
            metric.isMember("file")
                ? "formula: " + QFileInfo(QString::fromStdString(metric["file"].asString())).fileName()
                : "formula: " + QString::fromStdString(metric["formula"].get("name", "typed").asString());
        shownMetric_ = metric_->findData(kFormulaFileItem);
        metric_->insertItem(shownMetric_, what, kTypedItem);
        metric_->setItemData(shownMetric_, "The scene's metric, written as text (View > Metric editor)",
                             Qt::ToolTipRole);
    }
    metric_->setCurrentIndex(shownMetric_);
}

std::pair<QString, QString> PropertiesPanel::helpTarget() const {
    const QTreeWidgetItem* item = tree_->currentItem();
    const QString field = item ? item->data(0, kPathRole0).toString() : QString();
    if (field.isEmpty() || !document_) return {QString::fromStdString(chart_.page), QString()};
    const lc::io::FieldGuide help = lc::io::fieldGuide(field.toStdString(), chart_, *document_);
    return {QString::fromStdString(help.page), QString::fromStdString(help.section)};
}

QStringList PropertiesPanel::wordChoices(const QString& field) const {
    if (field.isEmpty()) return {};
    QStringList words;
    for (const std::string& choice :
         lc::io::fieldGuide(field.toStdString(), chart_, document_ ? *document_ : Json::Value::nullSingleton())
             .choices) {
        // "prograde (default)" -> "prograde"; "an image file", "{...}", "four numbers ..." are typed.
        const QString word = QString::fromStdString(choice).section(' ', 0, 0);
        if (!word.isEmpty() && word[0].isLetter() && !QStringList{"an", "a", "four"}.contains(word)) words << word;
    }
    return words;
}

void PropertiesPanel::setDocument(const Json::Value& scene, RangeOf rangeOf, const QString& sceneFolder,
                                  lc::io::ChartGuide chart) {
    rangeOf_ = std::move(rangeOf);
    chart_ = std::move(chart);
    filling_ = true;
    tree_->clear();
    unlisted_.clear();
    document_ = &scene;
    refusal_->clear();
    showMetricInChooser(scene["metric"], sceneFolder);
    QTreeWidgetItem* root = tree_->invisibleRootItem();
    auto topItem = [&](const QString& key) -> QTreeWidgetItem* {
        for (int k = 0; k < tree_->topLevelItemCount(); ++k)
            if (tree_->topLevelItem(k)->text(0) == key) return tree_->topLevelItem(k);
        return nullptr;
    };
    for (const char* key :
         {"description", "metric", "observer", "camera", "objects", "lights", "sky", "background", "render"})
        if (scene.isMember(key)) addValue(root, key, key, scene[key]);
    // Defaults the file leaves out: the metric's parameters and the render settings.
    if (QTreeWidgetItem* metric = topItem("metric"))
        for (const auto& d : lc::knownMetrics())
            if (d.name == scene["metric"]["name"].asString())
                for (const auto& p : d.parameters)
                    if (!scene["metric"].isMember(p.name))
                        addDefault(metric, QString::fromStdString(p.name), "metric." + QString::fromStdString(p.name),
                                   Json::Value(p.fallback), p.range());
    // The observer: an event and a 4-velocity (static when left out).
    QTreeWidgetItem* observer = topItem("observer");
    if (!observer) observer = new QTreeWidgetItem(tree_, {"observer"});
    if (!scene["observer"].isMember("position"))
        addDefault(observer, "position", "observer.position", fromJsonText("[0, 0, 0, 0]"), lc::input::kCoordinate);
    if (!scene["observer"].isMember("velocity"))
        addDefault(observer, "velocity", "observer.velocity", Json::Value("static"));
    QTreeWidgetItem* render = topItem("render");
    if (!render) render = new QTreeWidgetItem(tree_, {"render"});
    const bool godel = scene["metric"]["name"].asString().rfind("godel", 0) == 0;
    for (const Default& d : kRenderDefaults)
        if (!scene["render"].isMember(d.name) && (godel || std::string(d.name) != "windings")) {
            const Json::Value v = fromJsonText(d.fallback);
            addDefault(render, d.name, QString("render.") + d.name, v.isNull() ? Json::Value(d.fallback) : v,
                       defaultRange(d));
        }
    for (QTreeWidgetItemIterator it(tree_); *it; ++it)  // the long lists stay closed until asked for
        if ((*it)->childCount() > 0) (*it)->setExpanded(true);
    filling_ = false;
}

QTreeWidgetItem* PropertiesPanel::itemOf(const QString& field) const {
    for (QTreeWidgetItemIterator it(tree_); *it; ++it)
        if ((*it)->data(1, kFieldRole).toString() == field) return *it;
    return nullptr;
}

void PropertiesPanel::showRefusal(const QString& field, const QString& reason) {
    refusal_->setText(field + ": " + reason);
    if (QTreeWidgetItem* item = itemOf(field)) {
        filling_ = true;
        const QString current = item->data(1, kValueRole).toString();
        if (!current.isEmpty()) item->setText(1, format(fromJsonText(current)));
        item->setBackground(1, QBrush(QColor(255, 205, 210)));
        item->setToolTip(1, reason);
        filling_ = false;
        tree_->scrollToItem(item);
    }
}

QString PropertiesPanel::refusalText() const { return refusal_->text(); }

void PropertiesPanel::onItemChanged(QTreeWidgetItem* item, int column) {
    if (filling_ || column != 1) return;
    const QString field = item->data(1, kFieldRole).toString();
    if (field.isEmpty()) return;
    const QString current = item->data(1, kValueRole).toString();
    const Json::Value like = current.isEmpty() ? Json::Value() : fromJsonText(current);
    Json::Value value;
    if (!parse(item->text(1), like, value)) {
        showRefusal(field, "'" + item->text(1) + "' is not a value (numbers, [lists], text)");
        return;
    }
    refusal_->clear();
    emit editRequested(field, value);
}

}  // namespace lc::gui
