// SPDX-License-Identifier: BSD-3-Clause
#include "metric_catalogue_entries.hpp"

#include "readers/io/install_layout.hpp"
#include "readers/io/metric_file.hpp"

#include <json/json.h>

#include <QFileInfo>
#include <QPixmap>

#include <fstream>

namespace lc::gui {
namespace {

// Where scripts/catalogue_gallery puts the thumbnails: installed with the docs, or the checkout's.
QString galleryFolder() {
    for (const char* relative : {"share/doc/lightcone/docs/images/catalogue", "docs/images/catalogue"})
        if (const auto found = lc::io::findAboveProgram(relative)) return QString::fromStdString(found->string());
    return {};
}

QString summaryOf(const std::filesystem::path& file) {
    std::ifstream in(file);
    Json::Value root;
    Json::CharReaderBuilder reader;
    std::string errors;
    if (!Json::parseFromStream(reader, in, &root, &errors) || !root.isObject())
        return "not readable as a metric file: " + QString::fromStdString(errors).trimmed();
    return QString::fromStdString(root.get("summary", "").asString());
}

}  // namespace

std::vector<MetricCatalogueEntry> metricCatalogueEntries() {
    std::vector<MetricCatalogueEntry> entries;
    const QString gallery = galleryFolder();
    for (const std::filesystem::path& file : lc::io::catalogueFiles()) {
        MetricCatalogueEntry e;
        e.path = QFileInfo(QString::fromStdString(file.string())).canonicalFilePath();
        e.label = QString::fromStdString(file.filename().string());
        e.summary = summaryOf(file);
        const QString thumbnail = gallery + "/" + QString::fromStdString(file.stem().string()) + ".png";
        if (!gallery.isEmpty() && QFileInfo::exists(thumbnail)) e.thumbnail = QIcon(QPixmap(thumbnail));
        entries.push_back(std::move(e));
    }
    return entries;
}

}  // namespace lc::gui
