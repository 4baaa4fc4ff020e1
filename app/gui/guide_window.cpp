// SPDX-License-Identifier: BSD-3-Clause
#include "guide_window.hpp"

#include "help_dialogs.hpp"

#include "readers/io/field_guide.hpp"

#include <QAbstractTextDocumentLayout>
#include <QDir>
#include <QFile>
#include <QHBoxLayout>
#include <QImage>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPixmap>
#include <QRegularExpression>
#include <QScrollBar>
#include <QSplitter>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <functional>
#include <utility>

namespace lc::gui {
namespace {

constexpr int kFileRole = Qt::UserRole;

// Enter and Shift+Enter in the search field step through the matches.
class SearchKeys : public QObject {
public:
    SearchKeys(QObject* parent, std::function<void(bool)> step) : QObject(parent), step_(std::move(step)) {}
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::KeyPress) {
            auto* key = static_cast<QKeyEvent*>(event);
            if (key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter) {
                step_(key->modifiers() & Qt::ShiftModifier);
                return true;
            }
        }
        return QObject::eventFilter(watched, event);
    }

private:
    std::function<void(bool)> step_;
};

QSize naturalSize(const QVariant& resource) {
    if (resource.canConvert<QImage>() && !resource.value<QImage>().isNull()) return resource.value<QImage>().size();
    if (resource.canConvert<QPixmap>() && !resource.value<QPixmap>().isNull()) return resource.value<QPixmap>().size();
    if (resource.type() == QVariant::ByteArray) return QImage::fromData(resource.toByteArray()).size();
    return {};
}

}  // namespace

GuideWindow::GuideWindow(QWidget* parent) : QDialog(parent) {
    setObjectName("guideDialog");
    setWindowTitle("Lightcone guide");
    folder_ = QDir(guideDocsFolder()).filePath("guide");
    auto* layout = new QVBoxLayout(this);
    search_ = new QLineEdit(this);
    search_->setObjectName("guideSearch");
    search_->setPlaceholderText("Search the guide (Enter: next match, Shift+Enter: previous)");
    search_->setClearButtonEnabled(true);
    layout->addWidget(search_);
    summary_ = new QLabel(this);
    summary_->setObjectName("guideSearchSummary");
    layout->addWidget(summary_);
    auto* split = new QSplitter(this);
    pages_ = new QListWidget(split);
    pages_->setObjectName("guidePages");
    browser_ = new QTextBrowser(split);
    browser_->setObjectName("guideBrowser");
    browser_->setOpenExternalLinks(true);
    split->setStretchFactor(1, 1);
    layout->addWidget(split, 1);
    refit_ = new QTimer(this);
    refit_->setSingleShot(true);
    refit_->setInterval(100);
    connect(refit_, &QTimer::timeout, this, &GuideWindow::fitImages);

    for (const std::string& name : io::guidePages()) {
        Page page;
        page.file = QString::fromStdString(name);
        QFile file(QDir(folder_).filePath(page.file));
        if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) continue;
        const QString markdown = QString::fromUtf8(file.readAll());
        page.title = markdown.section('\n', 0, 0).remove(QRegularExpression("^#+ *"));
        QTextDocument shown;  // counted as the page shows it (no link targets, no markup)
        shown.setMarkdown(markdown);
        page.text = shown.toPlainText();
        texts_.push_back(page);
    }
    listPages();
    // The list shows each title whole, with a search's count after it.
    int widest = 0;
    for (const Page& page : texts_)
        widest = std::max(widest, pages_->fontMetrics().horizontalAdvance(page.title + " (000)"));
    pages_->setMinimumWidth(widest + 2 * pages_->frameWidth() + 8);
    split->setSizes({widest + 16, 900 - widest});
    connect(pages_, &QListWidget::currentItemChanged, this, [this](QListWidgetItem* item) {
        if (item && item->data(kFileRole).toString() != currentPage()) showPage(item->data(kFileRole).toString());
    });
    connect(browser_, &QTextBrowser::sourceChanged, this, [this] { pageShown(); });
    connect(search_, &QLineEdit::textChanged, this, &GuideWindow::search);
    search_->installEventFilter(new SearchKeys(this, [this](bool backwards) { findNext(backwards); }));
    resize(900, 700);
    if (texts_.empty())
        browser_->setPlainText(
            "The guide is not at " + folder_ +
            " (looked for share/doc/lightcone/docs/guide and docs/guide beside the program and above "
            "it).");
}

GuideWindow* GuideWindow::showGuide(QWidget* parent, const QString& page, const QString& section) {
    auto* window = parent ? parent->findChild<GuideWindow*>(QString(), Qt::FindDirectChildrenOnly) : nullptr;
    if (!window) window = new GuideWindow(parent);
    window->showPage(page, section);
    window->show();  // modeless: the workbench stays usable beside it
    window->raise();
    window->activateWindow();
    return window;
}

QString GuideWindow::currentPage() const { return browser_->source().fileName(); }

void GuideWindow::showPage(const QString& page, const QString& section) {
    if (texts_.empty()) return;
    QString file = page;
    if (std::none_of(texts_.begin(), texts_.end(), [&](const Page& p) { return p.file == file; }))
        file = texts_.front().file;
    if (currentPage() != file)
        browser_->setSource(QUrl::fromLocalFile(QDir(folder_).filePath(file)), QTextDocument::MarkdownResource);
    else
        pageShown();
    scrollToSection(section);
    pendingSection_ = section;  // again once the images have their size (a window just shown)
    refit_->start();
}

void GuideWindow::pageShown() {
    const QString file = currentPage();
    for (int k = 0; k < pages_->count(); ++k)
        if (pages_->item(k)->data(kFileRole).toString() == file && pages_->currentRow() != k) {
            const QSignalBlocker quiet(pages_);
            pages_->setCurrentRow(k);
        }
    fitImages();
    markMatches();
}

void GuideWindow::scrollToSection(const QString& section) {
    if (section.isEmpty()) return;
    QTextDocument* doc = browser_->document();
    for (QTextBlock block = doc->begin(); block.isValid(); block = block.next()) {
        if (block.blockFormat().headingLevel() == 0 || block.text().trimmed() != section) continue;
        QTextCursor at(block);
        browser_->setTextCursor(at);
        browser_->verticalScrollBar()->setValue(
            static_cast<int>(doc->documentLayout()->blockBoundingRect(block).top()));
        return;
    }
}

void GuideWindow::listPages() {
    const QString query = search_->text().trimmed();
    const QSignalBlocker quiet(pages_);
    pages_->clear();
    for (const Page& page : texts_) {
        const int hits = query.isEmpty() ? 0 : page.text.count(query, Qt::CaseInsensitive);
        if (!query.isEmpty() && hits == 0) continue;
        auto* item = new QListWidgetItem(query.isEmpty() ? page.title : QString("%1 (%2)").arg(page.title).arg(hits));
        item->setData(kFileRole, page.file);
        pages_->addItem(item);
        if (page.file == currentPage()) pages_->setCurrentItem(item);
    }
}

void GuideWindow::search(const QString& text) {
    listPages();
    const QString query = text.trimmed();
    // The page shown has no match: the first page that has one.
    if (!query.isEmpty() && pages_->count() > 0) {
        bool here = false;
        for (int k = 0; k < pages_->count(); ++k) here |= pages_->item(k)->data(kFileRole).toString() == currentPage();
        if (!here) showPage(pages_->item(0)->data(kFileRole).toString());
    }
    markMatches();
    browser_->moveCursor(QTextCursor::Start);
    if (!query.isEmpty()) findNext(false);
}

void GuideWindow::markMatches() {
    const QString query = search_->text().trimmed();
    QList<QTextEdit::ExtraSelection> marks;
    if (!query.isEmpty()) {
        QTextCursor at(browser_->document());
        while (!(at = browser_->document()->find(query, at)).isNull()) {
            QTextEdit::ExtraSelection mark;
            mark.cursor = at;
            mark.format.setBackground(QColor(255, 230, 120));
            marks.append(mark);
        }
    }
    browser_->setExtraSelections(marks);
    if (query.isEmpty())
        summary_->clear();
    else if (pages_->count() == 0)
        summary_->setText("\"" + query + "\" is in no page of the guide");
    else
        summary_->setText(QString("\"%1\": %2 in this page, in %3 of the %4 pages")
                              .arg(query)
                              .arg(marks.size())
                              .arg(pages_->count())
                              .arg(texts_.size()));
}

void GuideWindow::findNext(bool backwards) {
    const QString query = search_->text().trimmed();
    if (query.isEmpty()) return;
    const QTextDocument::FindFlags flags = backwards ? QTextDocument::FindBackward : QTextDocument::FindFlags();
    if (browser_->find(query, flags)) return;
    browser_->moveCursor(backwards ? QTextCursor::End : QTextCursor::Start);  // wrap around
    browser_->find(query, flags);
}

// Each image at its own size where it fits, else scaled down to the text's width.
void GuideWindow::fitImages() {
    QTextDocument* doc = browser_->document();
    const int room = std::max(64, browser_->viewport()->width() - 2 * static_cast<int>(doc->documentMargin()) - 8);
    struct Fit {
        int position, length;
        QTextImageFormat format;
    };
    std::vector<Fit> fits;
    for (QTextBlock block = doc->begin(); block.isValid(); block = block.next())
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            if (!fragment.charFormat().isImageFormat()) continue;
            QTextImageFormat image = fragment.charFormat().toImageFormat();
            const QSize natural = naturalSize(doc->resource(QTextDocument::ImageResource, QUrl(image.name())));
            if (natural.isEmpty()) continue;
            const double scale = std::min(1.0, double(room) / natural.width());
            image.setWidth(natural.width() * scale);
            image.setHeight(natural.height() * scale);
            fits.push_back({fragment.position(), fragment.length(), image});
        }
    for (const Fit& fit : fits) {
        QTextCursor cursor(doc);
        cursor.setPosition(fit.position);
        cursor.setPosition(fit.position + fit.length, QTextCursor::KeepAnchor);
        cursor.setCharFormat(fit.format);
    }
    if (!pendingSection_.isEmpty()) scrollToSection(std::exchange(pendingSection_, QString()));
}

void GuideWindow::resizeEvent(QResizeEvent* event) {
    QDialog::resizeEvent(event);
    refit_->start();
}

}  // namespace lc::gui
