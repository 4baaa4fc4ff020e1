// SPDX-License-Identifier: BSD-3-Clause
#include "scene_read_job.hpp"

#include "app/commands/commands.hpp"

#include <QMetaObject>
#include <QPointer>

namespace lc::gui {

SceneReadJob::SceneReadJob(QObject* parent) : QObject(parent) {
    qRegisterMetaType<std::shared_ptr<lc::io::EditableScene>>("std::shared_ptr<lc::io::EditableScene>");
}

SceneReadJob::~SceneReadJob() {
    if (worker_.joinable()) worker_.join();  // a read cannot be interrupted: seconds at most
    for (std::thread& t : abandoned_) t.join();
}

void SceneReadJob::start(const QString& path) {
    if (worker_.joinable()) abandoned_.push_back(std::move(worker_));  // ignored from now on
    const int generation = ++generation_;
    running_ = true;
    path_ = path;
    emit started(path);
    QPointer<SceneReadJob> self(this);
    // Delivered only while this read is still the one wanted.
    auto post = [self, generation](auto fn) {
        QMetaObject::invokeMethod(
            self.data(),
            [self, generation, fn] {
                if (!self || generation != self->generation_) return;
                self->running_ = false;
                fn(*self);
            },
            Qt::QueuedConnection);
    };
    worker_ = std::thread([path, post] {
        try {
            auto scene = std::make_shared<lc::io::EditableScene>(
                lc::io::EditableScene::load(path.toStdString(), lc::cli::sceneReadOptions()));
            post([scene, path](SceneReadJob& job) { emit job.finished(scene, path); });
        } catch (const std::exception& e) {
            const QString message = QString::fromStdString(e.what());
            post([path, message](SceneReadJob& job) { emit job.failed(path, message); });
        }
    });
}

void SceneReadJob::cancel() {
    if (!running_) return;
    ++generation_;
    running_ = false;
    emit cancelled(path_);
}

}  // namespace lc::gui
