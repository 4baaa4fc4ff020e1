// SPDX-License-Identifier: BSD-3-Clause
#include "active_scene.hpp"

#include "readers/io/structural_edits.hpp"

#include <QDir>
#include <QFileInfo>
#include <QStringList>
#include <QUndoCommand>

#include <utility>

namespace lc::gui {

// One entry of the undo stack: the fields' new values and the values they had.
class SceneEditCommand : public QUndoCommand {
public:
    // `alreadyApplied`: an edit made as it was pushed, or a step of a reopened session's history,
    // which the scene holds already; its first redo (QUndoStack::push's) changes nothing.
    SceneEditCommand(ActiveScene* scene, std::vector<lc::io::SceneEdit> after, std::vector<lc::io::SceneEdit> before,
                     const QString& text, bool alreadyApplied = false)
        : QUndoCommand(text),
          scene_(scene),
          after_(std::move(after)),
          before_(std::move(before)),
          skipRedo_(alreadyApplied) {}
    void redo() override {
        if (std::exchange(skipRedo_, false)) return;
        scene_->applyNow(after_);
    }
    void undo() override { scene_->applyNow(before_); }
    const std::vector<lc::io::SceneEdit>& after() const { return after_; }
    const std::vector<lc::io::SceneEdit>& before() const { return before_; }

private:
    ActiveScene* scene_;
    std::vector<lc::io::SceneEdit> after_, before_;
    bool skipRedo_;
};

namespace {

QString editText(const std::vector<lc::io::SceneEdit>& edits) {
    QStringList fields;
    for (const auto& e : edits) fields << QString::fromStdString(e.field);
    return "edit " + fields.join(", ");
}

lc::io::SceneList listNamed(const QString& list) {
    if (list == "objects") return lc::io::SceneList::Objects;
    if (list == "lights") return lc::io::SceneList::Lights;
    throw std::invalid_argument("'" + list.toStdString() + "' is not a list of the scene (objects or lights)");
}

}  // namespace

ActiveScene::ActiveScene(QObject* parent) : QObject(parent) {}

void ActiveScene::setSaved(const QString& sessionPath) {
    sessionPath_ = sessionPath;
    undo_.setClean();
    emit pathsChanged();
}

void ActiveScene::adopt(lc::io::EditableScene scene, const QString& sceneFile, const QString& sessionFile) {
    scene_ = std::move(scene);
    sceneFile_ = sceneFile;
    sessionPath_ = sessionFile;
    undo_.clear();
    undo_.setClean();
    emit pathsChanged();
    emit replaced();
    emit changed();
}

std::vector<lc::io::SessionFile::HistoryStep> ActiveScene::history() const {
    std::vector<lc::io::SessionFile::HistoryStep> steps;
    for (int k = 0; k < undo_.index(); ++k)
        if (const auto* c = dynamic_cast<const SceneEditCommand*>(undo_.command(k)))
            steps.push_back({c->text().toStdString(), c->after(), c->before()});
    return steps;
}

void ActiveScene::restoreHistory(const std::vector<lc::io::SessionFile::HistoryStep>& steps) {
    if (!scene_) return;
    for (const auto& step : steps)
        undo_.push(new SceneEditCommand(this, step.after, step.before, QString::fromStdString(step.text), true));
    undo_.setClean();
}

bool ActiveScene::edit(const std::vector<lc::io::SceneEdit>& edits, const QString& description) {
    if (!scene_ || edits.empty()) return false;
    std::vector<lc::io::SceneEdit> before;
    try {
        for (const auto& e : edits) before.push_back(scene_->undoing(e.field));
        // All or nothing: a refused edit leaves the scene as it was. Applied once, here (a trial
        // copy then a second reading cost a 40 MB scene twice the time and a copy of itself).
        scene_->apply(edits);
    } catch (const lc::io::InputError& e) {
        emit refused(QString::fromStdString(e.field()), QString::fromStdString(e.reason()));
        return false;
    } catch (const std::exception& e) {
        emit refused(QString::fromStdString(edits.front().field), e.what());
        return false;
    }
    emit changed();  // before the stack moves, as when the command's redo applied it
    undo_.push(new SceneEditCommand(this, edits, before, description.isEmpty() ? editText(edits) : description, true));
    return true;
}

void ActiveScene::applyNow(const std::vector<lc::io::SceneEdit>& edits) {
    // Checked before the command was pushed, but the reader reads textures and meshes again: a
    // file moved since then is reported, never thrown out of Qt's event loop.
    try {
        scene_->apply(edits);
    } catch (const std::exception& e) {
        emit applyFailed(e.what());
        return;
    }
    emit changed();
}

bool ActiveScene::editStructure(const std::function<lc::io::SceneEdit()>& make, const QString& description) {
    if (!scene_) return false;
    lc::io::SceneEdit edit;
    try {
        edit = make();
    } catch (const std::invalid_argument& e) {
        emit refused(description, e.what());
        return false;
    }
    return this->edit({edit}, description);
}

bool ActiveScene::changeMetricBy(const std::function<lc::io::SceneEdit()>& make, const QString& description) {
    if (!scene_) return false;
    lc::io::MetricChangePlan plan;
    try {
        plan = lc::io::plannedMetricChange(*scene_, make());
    } catch (const lc::io::InputError& e) {
        emit refused(QString::fromStdString(e.field()), QString::fromStdString(e.reason()));
        return false;
    } catch (const std::exception& e) {
        emit refused(description, e.what());
        return false;
    }
    if (!edit(plan.edits, description)) return false;
    if (!plan.moved.empty()) emit adjusted(description + ": " + QString::fromStdString(plan.moved));
    return true;
}

bool ActiveScene::changeMetric(const QString& name) {
    if (scene_ && QString::fromStdString(scene_->scene().spacetime->name()) == name &&
        scene_->value("metric").isMember("name"))
        return true;  // the metric it has: nothing to change
    return changeMetricBy([&] { return lc::io::metricChange(name.toStdString()); }, "metric " + name);
}

bool ActiveScene::changeMetricToFile(const QString& path) {
    return changeMetricBy([&] { return lc::io::metricFileChange(path.toStdString(), scene_->baseDir()); },
                          "metric " + QFileInfo(path).fileName());
}

bool ActiveScene::changeMetricToBlock(const Json::Value& metric, const QString& description) {
    return changeMetricBy([&] { return lc::io::SceneEdit{"metric", metric}; }, description);
}

bool ActiveScene::addSphere() {
    return editStructure([&] { return lc::io::sphereAdded(scene_->document(), scene_->scene()); }, "add sphere");
}

bool ActiveScene::addLight() {
    return editStructure([&] { return lc::io::lightAdded(scene_->document(), scene_->scene()); }, "add light");
}

bool ActiveScene::duplicateElement(const QString& list, int index) {
    return editStructure(
        [&] { return lc::io::elementDuplicated(scene_->document(), scene_->scene(), listNamed(list), index); },
        QString("duplicate %1[%2]").arg(list).arg(index));
}

bool ActiveScene::removeElement(const QString& list, int index) {
    return editStructure([&] { return lc::io::elementRemoved(scene_->document(), listNamed(list), index); },
                         QString("remove %1[%2]").arg(list).arg(index));
}

QString ActiveScene::besideScene(const QString& name) const {
    const QString beside = !sessionPath_.isEmpty() ? sessionPath_ : sceneFile_;
    if (beside.isEmpty()) return name;
    const QString base = QFileInfo(beside).completeBaseName();
    const QString suffix = QFileInfo(name).suffix();
    // "kerr.png" beside kerr.json: the scene's name, the export's kind.
    return QFileInfo(beside).dir().filePath(suffix.isEmpty() ? base + "-" + name : base + "." + suffix);
}

}  // namespace lc::gui
