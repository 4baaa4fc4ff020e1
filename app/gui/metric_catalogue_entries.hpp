// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The catalogue's metric files as the metric chooser lists them (issue #43): each file that
// `lightcone metric list` finds (io::catalogueFiles: LIGHTCONE_DATA_PATH, the installed or the
// checkout's data/metrics), with its summary (what it is, its reference) and the gallery's
// thumbnail (docs/images/catalogue/NAME.png, scripts/catalogue_gallery) when the docs are beside
// the program (installed, or a build tree in the checkout).
#include <QIcon>
#include <QString>

#include <vector>

namespace lc::gui {

struct MetricCatalogueEntry {
    QString path;     // the metric file, absolute with links resolved (the chooser compares files by it)
    QString label;    // its file name, "ellis_wormhole.json"
    QString summary;  // the file's "summary"; the reader's complaint for a file it refuses
    QIcon thumbnail;  // null where the gallery is not found
};

// Read once per call: the files' summaries only (no formula is compiled), a few milliseconds.
std::vector<MetricCatalogueEntry> metricCatalogueEntries();

}  // namespace lc::gui
