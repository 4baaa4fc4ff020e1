// SPDX-License-Identifier: BSD-3-Clause
#include "metric_editor.hpp"

#include "readers/io/scene_edits.hpp"  // fieldOf

#include <QDir>
#include <QFile>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QTextBlock>
#include <QVBoxLayout>

#include <memory>
#include <string>

namespace lc::gui {
namespace {

// What a built-in metric's scene starts from: Schwarzschild as docs/METRICS.md writes it.
const char* const kTemplate = R"json({
  "name": "my-metric",
  "summary": "Schwarzschild in Kerr-Schild form, to be changed",
  "coordinates": ["t", "x", "y", "z"],
  "signature": "-+++",
  "parameters": {
    "M": {"default": 1, "range": [1e-6, 1e6], "meaning": "mass; lengths are in units of M"}
  },
  "define": ["r = sqrt(x^2 + y^2 + z^2)"],
  "ds2": "-dt^2 + dx^2 + dy^2 + dz^2 + 2*M/r*(dt - (x*dx + y*dy + z*dz)/r)^2",
  "horizon": "r/(2*M) - 1",
  "radius": "r",
  "far_field": {"mass": "M", "size": "0", "capture": "4*M"}
}
)json";

QString pretty(const Json::Value& v) {
    Json::StreamWriterBuilder b;
    b["indentation"] = "  ";
    return QString::fromStdString(Json::writeString(b, v)) + "\n";
}

// A byte offset into the UTF-8 text -> a position in the QString (UTF-16).
int positionOf(const QString& text, std::size_t byteOffset) {
    const QByteArray utf8 = text.toUtf8();
    return QString::fromUtf8(utf8.left(static_cast<int>(std::min<std::size_t>(byteOffset, utf8.size())))).size();
}

}  // namespace

MetricEditor::MetricEditor(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    caption_ = new QLabel(this);
    caption_->setObjectName("metricEditorCaption");
    caption_->setWordWrap(true);
    layout->addWidget(caption_);
    text_ = new QPlainTextEdit(this);
    text_->setObjectName("metricEditorText");
    text_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    text_->setLineWrapMode(QPlainTextEdit::NoWrap);
    layout->addWidget(text_, 1);
    problem_ = new QLabel(this);
    problem_->setObjectName("metricEditorProblem");
    problem_->setWordWrap(true);
    problem_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    problem_->setStyleSheet("color: #b00020");
    problem_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    layout->addWidget(problem_);
    auto* buttons = new QHBoxLayout;
    open_ = new QPushButton("Open formula file...", this);
    open_->setObjectName("metricEditorOpen");
    open_->setToolTip("A metric file (docs/METRICS.md) becomes the scene's metric");
    apply_ = new QPushButton("Apply", this);
    apply_->setObjectName("metricEditorApply");
    apply_->setToolTip("The text becomes the scene's metric and the image is rendered again (Edit > Undo undoes it)");
    buttons->addWidget(open_);
    buttons->addStretch(1);
    buttons->addWidget(apply_);
    layout->addLayout(buttons);
    connect(apply_, &QPushButton::clicked, this, &MetricEditor::apply);
    connect(open_, &QPushButton::clicked, this, &MetricEditor::openFileRequested);
    caption_->setText("No scene.");
}

QString MetricEditor::problemText() const { return problem_->text(); }
QString MetricEditor::captionText() const { return caption_->text(); }

void MetricEditor::showMetric(const Json::Value& metric, const QString& sceneFolder) {
    if (!applied_.isNull() && metric == applied_) {  // the scene took the text: it stays as typed
        shown_ = metric;
        applied_ = Json::Value();
        clearProblem();
        caption_->setText("The scene's metric is this formula (docs/METRICS.md). Apply renders an edit.");
        return;
    }
    if (metric == shown_) return;
    shown_ = metric;
    applied_ = Json::Value();
    clearProblem();
    if (metric.isMember("formula")) {
        caption_->setText("The scene's metric is this formula (docs/METRICS.md). Apply renders an edit.");
        text_->setPlainText(pretty(metric["formula"]));
    } else if (metric.isMember("file")) {
        const QString name = QString::fromStdString(metric["file"].asString());
        QFile file(QDir(sceneFolder).filePath(name));
        if (file.open(QIODevice::ReadOnly)) {
            caption_->setText("The scene's metric is written in " + name +
                              ". Apply puts the edited formula in the scene; the file is not changed.");
            text_->setPlainText(QString::fromUtf8(file.readAll()));
        } else {
            caption_->setText("The scene's metric file " + name + " cannot be read. Below, a formula to start from.");
            text_->setPlainText(kTemplate);
        }
    } else {
        caption_->setText("The scene's metric is the built-in '" + QString::fromStdString(metric["name"].asString()) +
                          "'. Below, a formula to start from (docs/METRICS.md); Apply makes it the scene's metric.");
        text_->setPlainText(kTemplate);
    }
}

void MetricEditor::apply() {
    clearProblem();
    const QString text = text_->toPlainText();
    const std::string utf8 = text.toStdString();
    Json::CharReaderBuilder builder;
    builder["collectComments"] = false;
    const std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
    Json::Value formula;
    std::string errors;
    if (!reader->parse(utf8.data(), utf8.data() + utf8.size(), &formula, &errors)) {
        // "* Line 3, Column 5\n  Syntax error: ...": the place, then the words.
        const QRegularExpressionMatch m =
            QRegularExpression(R"(Line (\d+), Column (\d+)\s*(.*))", QRegularExpression::DotMatchesEverythingOption)
                .match(QString::fromStdString(errors));
        int offset = 0;
        if (m.hasMatch()) {
            const QTextBlock line = text_->document()->findBlockByNumber(m.captured(1).toInt() - 1);
            offset = line.isValid() ? line.position() + m.captured(2).toInt() - 1 : 0;
        }
        markProblem(offset, 1,
                    "not JSON: " + (m.hasMatch() ? "line " + m.captured(1) + ", column " + m.captured(2) + ": " +
                                                       m.captured(3).simplified()
                                                 : QString::fromStdString(errors).simplified()));
        return;
    }
    if (!formula.isObject()) {
        markProblem(0, 1, "a metric is a JSON object { ... } (docs/METRICS.md)");
        return;
    }
    Json::Value block(Json::objectValue);
    block["formula"] = formula;
    // The scene's parameter values, for the parameters the formula still declares.
    for (const std::string& key : shown_.getMemberNames())
        if (key != "name" && key != "file" && key != "formula" && formula["parameters"].isMember(key))
            block[key] = shown_[key];
    parsed_ = formula;
    applied_ = block;
    problem_->setText("applied: the scene reader is checking it...");
    emit applyRequested(block);
}

void MetricEditor::showProblem(const QString& field, const QString& reason) {
    if (applied_.isNull()) return;  // another edit's refusal: the properties dock shows it
    applied_ = Json::Value();
    const QString prefix = "metric.formula.";
    const QString message = field + ": " + reason;
    if (!field.startsWith(prefix)) {
        markProblem(-1, 0, message);
        return;
    }
    const Json::Value* node = nullptr;
    try {
        node = lc::io::fieldOf(parsed_, field.mid(prefix.size()).toStdString(), false);
    } catch (const std::invalid_argument&) {
        node = nullptr;
    }
    if (!node || node->isNull()) {
        markProblem(-1, 0, message);
        return;
    }
    const QString text = text_->toPlainText();
    const int start = positionOf(text, node->getOffsetStart()), end = positionOf(text, node->getOffsetLimit());
    const QRegularExpressionMatch column = QRegularExpression(R"(^column (\d+):)").match(reason);
    if (node->isString() && column.hasMatch()) {
        // Inside the string, after its opening quote; the name or number there is underlined.
        const int at = std::min(start + column.captured(1).toInt(), std::max(end - 1, start));
        int length = 1;
        while (at + length < end - 1 && (text[at + length].isLetterOrNumber() || text[at + length] == '_')) ++length;
        markProblem(at, length, message);
    } else {
        markProblem(start, std::max(end - start, 1), message);
    }
}

void MetricEditor::markProblem(int offset, int length, const QString& message) {
    problem_->setText(message);
    problemOffset_ = offset;
    if (offset < 0) return;
    QTextEdit::ExtraSelection mark;
    mark.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
    mark.format.setUnderlineColor(QColor(0xb0, 0x00, 0x20));
    mark.format.setBackground(QColor(0xff, 0xe0, 0xe0));
    mark.cursor = QTextCursor(text_->document());
    mark.cursor.setPosition(offset);
    mark.cursor.setPosition(std::min(offset + length, text_->document()->characterCount() - 1),
                            QTextCursor::KeepAnchor);
    text_->setExtraSelections({mark});
    QTextCursor cursor(text_->document());
    cursor.setPosition(offset);
    text_->setTextCursor(cursor);
    text_->ensureCursorVisible();
}

void MetricEditor::clearProblem() {
    problem_->clear();
    problemOffset_ = -1;
    text_->setExtraSelections({});
}

}  // namespace lc::gui
