// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reads a scene file on a worker thread (io::EditableScene::load), so that a big scene (tens of
// MB, seconds to parse and check) leaves the window responsive. One read at a time: a new start
// or cancel() makes whatever the running worker still delivers ignored.
#include "readers/io/scene_edits.hpp"

#include <QObject>
#include <QString>

#include <memory>
#include <thread>
#include <vector>

namespace lc::gui {

class SceneReadJob : public QObject {
    Q_OBJECT
public:
    explicit SceneReadJob(QObject* parent = nullptr);
    ~SceneReadJob() override;

    void start(const QString& path);
    void cancel();  // the current scene stays; emits cancelled
    bool running() const { return running_; }
    QString path() const { return path_; }

signals:
    void started(const QString& path);
    void finished(std::shared_ptr<lc::io::EditableScene> scene, const QString& path);
    void failed(const QString& path, const QString& message);
    void cancelled(const QString& path);

private:
    std::thread worker_;
    // Reads left running by a newer start(): their results are ignored; joined in the destructor
    // (a parse cannot be interrupted), never on the way to the next read.
    std::vector<std::thread> abandoned_;
    int generation_ = 0;
    bool running_ = false;
    QString path_;
};

}  // namespace lc::gui
