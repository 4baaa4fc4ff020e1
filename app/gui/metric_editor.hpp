// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The metric editor dock: the scene's metric written as text (docs/METRICS.md), edited in place.
// It shows the formula the scene holds (inline, or the text of the file it names) or, for a
// built-in metric, a formula to start from. Apply proposes the text as the scene's metric
// (applyRequested: one undoable edit, which the scene reader accepts or refuses); a refusal comes
// back through showProblem and is marked where it is: a JSON syntax error at its line and column,
// a formula's error at its field and column, with the reader's words below. The text has its own
// undo (Ctrl+Z while it has the focus); an applied metric is undone by Edit > Undo.
#include <json/json.h>

#include <QString>
#include <QWidget>

class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace lc::gui {

class MetricEditor : public QWidget {
    Q_OBJECT
public:
    explicit MetricEditor(QWidget* parent = nullptr);

    // The scene's metric block ({"name": ...}, {"file": ...} or {"formula": ...} with parameter
    // values); `sceneFolder` resolves a file. The text is replaced unless it is the block this
    // editor applied last (the user's own text and layout stay).
    void showMetric(const Json::Value& metric, const QString& sceneFolder);
    // The reader refused the applied metric: `field` is the reader's ("metric.formula.ds2"),
    // `reason` its words ("column 32: unknown name 'rr' ...").
    void showProblem(const QString& field, const QString& reason);

    QPlainTextEdit* text() const { return text_; }
    QPushButton* applyButton() const { return apply_; }
    QPushButton* openButton() const { return open_; }
    QString problemText() const;
    QString captionText() const;
    // Where the problem is marked: a character offset into text(), -1 when none is.
    int problemOffset() const { return problemOffset_; }

signals:
    void applyRequested(const Json::Value& metric);
    void openFileRequested();

private:
    void apply();
    void markProblem(int offset, int length, const QString& message);
    void clearProblem();

    QLabel* caption_ = nullptr;
    QPlainTextEdit* text_ = nullptr;
    QPushButton *apply_ = nullptr, *open_ = nullptr;
    QLabel* problem_ = nullptr;
    Json::Value shown_;    // the scene's metric block the text came from
    Json::Value applied_;  // the block last proposed, and its formula as parsed (with offsets)
    Json::Value parsed_;
    int problemOffset_ = -1;
};

}  // namespace lc::gui
