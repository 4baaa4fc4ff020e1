// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The scene the workbench shows (ParaView's "active source"): the scene file read through
// io::EditableScene, where it came from (scene file, session), and the undo stack of its edits.
// Every edit goes through edit(): the scene reader accepts or refuses it before anything changes;
// accepted edits are undoable. Views listen to changed(); a refusal is told through refused().
#include "readers/io/scene_edits.hpp"
#include "readers/io/session_file.hpp"

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <functional>
#include <optional>
#include <vector>

namespace lc::gui {

class ActiveScene : public QObject {
    Q_OBJECT
public:
    explicit ActiveScene(QObject* parent = nullptr);

    bool hasScene() const { return scene_.has_value(); }
    const lc::io::EditableScene& scene() const { return *scene_; }
    QUndoStack* undoStack() { return &undo_; }
    QString sceneFile() const { return sceneFile_; }
    QString sessionPath() const { return sessionPath_; }
    // After a save: the session is now the window's, its edits saved.
    void setSaved(const QString& sessionPath);
    // The scene becomes this one (Open): the undo stack starts empty; replaced() then changed().
    void adopt(lc::io::EditableScene scene, const QString& sceneFile, const QString& sessionFile);

    // One undoable edit of one or more fields, checked by the scene reader. A refusal returns
    // false and emits refused(field, reason) with the reader's words.
    bool edit(const std::vector<lc::io::SceneEdit>& edits, const QString& description);
    // Edits that change what the scene holds (readers/io/structural_edits), each one undoable edit.
    // The undo steps up to the current one, oldest first (what a session keeps), and the same
    // pushed back on a reopened scene that already holds them; the stack is then clean.
    std::vector<lc::io::SessionFile::HistoryStep> history() const;
    void restoreHistory(const std::vector<lc::io::SessionFile::HistoryStep>& steps);
    bool changeMetric(const QString& name);
    bool changeMetricToFile(const QString& path);  // a metric written as text (docs/METRICS.md)
    // A metric block as a scene file writes it (the metric editor's), planned the same way.
    bool changeMetricToBlock(const Json::Value& metric, const QString& description);
    bool addSphere();
    bool addLight();
    bool duplicateElement(const QString& list, int index);  // list: "objects" or "lights"
    bool removeElement(const QString& list, int index);

    // Where File > Export and Save session start: `name` beside the session, or else the scene file
    // ("image.png" -> "<folder>/<scene>.png"; a folder name -> "<folder>/<scene>-<name>").
    QString besideScene(const QString& name) const;

signals:
    void replaced();      // another scene was opened (before changed())
    void pathsChanged();  // opened or saved: the scene file or the session is another
    void changed();       // the scene is new or edited: every view shows it again
    void refused(const QString& field, const QString& reason);
    void applyFailed(const QString& message);  // an undo or redo the reader no longer accepts
    void adjusted(const QString& what);        // what a metric change moved besides the metric

private:
    friend class SceneEditCommand;
    void applyNow(const std::vector<lc::io::SceneEdit>& edits);
    bool editStructure(const std::function<lc::io::SceneEdit()>& make, const QString& description);
    // The metric `make` gives, with the observer moved where the reader refuses it there
    // (lc::io::plannedMetricChange), as one undoable edit; adjusted() says what moved.
    bool changeMetricBy(const std::function<lc::io::SceneEdit()>& make, const QString& description);

    std::optional<lc::io::EditableScene> scene_;
    QString sceneFile_, sessionPath_;
    QUndoStack undo_;
};

}  // namespace lc::gui
