// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Counts the events (ErrorEvent, ModifiedEvent, ...) a VTK object fires: the filter tests check
// that invalid input is reported exactly once, and what it says (while an object has an
// ErrorEvent observer, VTK hands the message to it instead of printing it), and that pipelines
// re-execute only when needed. Use text only with events whose call data is a message.
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkObject.h>

#include <string>

namespace lc::test {

struct EventCounter {
    int count = 0;
    std::string text;  // what the events carried (an ErrorEvent: VTK's error message), joined
    static void Callback(vtkObject*, unsigned long, void* clientData, void* callData) {
        auto* self = static_cast<EventCounter*>(clientData);
        ++self->count;
        if (callData) self->text += static_cast<const char*>(callData);
    }

    EventCounter() = default;
    EventCounter(const EventCounter&) = delete;
    EventCounter& operator=(const EventCounter&) = delete;
    // A counter that watch()ed stops counting when it goes away (the object may live on).
    ~EventCounter() {
        if (watched_) watched_->RemoveObserver(tag_);
    }
    // Counts `event` of `object` from now on; one object per counter.
    void watch(vtkObject* object, unsigned long event = vtkCommand::ErrorEvent) {
        vtkNew<vtkCallbackCommand> cb;
        cb->SetCallback(&EventCounter::Callback);
        cb->SetClientData(this);
        tag_ = object->AddObserver(event, cb);
        watched_ = object;
    }

private:
    vtkObject* watched_ = nullptr;
    unsigned long tag_ = 0;
};

}  // namespace lc::test
