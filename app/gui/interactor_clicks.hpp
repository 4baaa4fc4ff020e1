// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A left click on a VTK view: press and release within 3 px of each other (a longer move is the
// interactor style's drag: the chart's pan, the trackball's turn).
#include <functional>

class vtkRenderWindowInteractor;

namespace lc::gui {

// Calls `clicked(x, y)` (VTK display pixels, y up) for each click on `interactor`. The observers
// are passive: interactor styles grab the press, and only passive observers still see the release.
void observeClicks(vtkRenderWindowInteractor* interactor, std::function<void(int x, int y)> clicked);

}  // namespace lc::gui
