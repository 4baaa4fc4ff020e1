// SPDX-License-Identifier: BSD-3-Clause
#include "interactor_clicks.hpp"

#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkRenderWindowInteractor.h>

#include <cstdlib>

namespace lc::gui {

namespace {
class ClickObserver : public vtkCommand {
public:
    static ClickObserver* New() { return new ClickObserver; }
    void Execute(vtkObject* caller, unsigned long event, void*) override {
        const int* at = static_cast<vtkRenderWindowInteractor*>(caller)->GetEventPosition();
        if (event == vtkCommand::LeftButtonPressEvent) {
            pressX_ = at[0];
            pressY_ = at[1];
        } else if (std::abs(at[0] - pressX_) + std::abs(at[1] - pressY_) <= 3 && clicked_)
            clicked_(at[0], at[1]);
    }
    std::function<void(int, int)> clicked_;

private:
    int pressX_ = 0, pressY_ = 0;
};
}  // namespace

void observeClicks(vtkRenderWindowInteractor* interactor, std::function<void(int x, int y)> clicked) {
    vtkNew<ClickObserver> observer;
    observer->clicked_ = std::move(clicked);
    observer->PassiveObserverOn();
    interactor->AddObserver(vtkCommand::LeftButtonPressEvent, observer);
    interactor->AddObserver(vtkCommand::LeftButtonReleaseEvent, observer);
}

}  // namespace lc::gui
