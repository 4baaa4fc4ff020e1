// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Help > Guide: the user guide (docs/guide/, one page per kind of scene) in a window beside the
// workbench. A search field lists the pages that hold the words, with how often, and marks them
// in the page shown (Enter: the next one, Shift+Enter: the one before); images are scaled to the
// window's width; a page opens at a section by its heading, which is how F1 on a property
// lands on the section that explains it. Modeless: renders and edits go on beside it.
#include <QDialog>
#include <QString>
#include <QStringList>

#include <vector>

class QLabel;
class QLineEdit;
class QListWidget;
class QTextBrowser;
class QTimer;

namespace lc::gui {

class GuideWindow : public QDialog {
    Q_OBJECT
public:
    // The guide window of `parent` (made on first use, raised after), at `page` ("godel.md") and
    // the section headed `section` (empty: the page's top).
    static GuideWindow* showGuide(QWidget* parent, const QString& page, const QString& section = {});

    void showPage(const QString& page, const QString& section = {});
    QString currentPage() const;  // its file name
    QTextBrowser* browser() const { return browser_; }
    QListWidget* pageList() const { return pages_; }
    QLineEdit* searchField() const { return search_; }
    QLabel* searchSummary() const { return summary_; }

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    explicit GuideWindow(QWidget* parent);
    struct Page {
        QString file, title, text;  // text: as the page shows it, for counting matches
    };
    void search(const QString& text);
    void findNext(bool backwards);
    void markMatches();
    void fitImages();
    void scrollToSection(const QString& section);
    void listPages();
    void pageShown();  // after any page change (a link, the list, showPage)

    QString folder_;  // docs/guide
    std::vector<Page> texts_;
    QTextBrowser* browser_ = nullptr;
    QListWidget* pages_ = nullptr;
    QLineEdit* search_ = nullptr;
    QLabel* summary_ = nullptr;
    QTimer* refit_ = nullptr;  // images refitted once a resize settles
    QString pendingSection_;   // scrolled to again after the first refit of a page opened there
};

}  // namespace lc::gui
