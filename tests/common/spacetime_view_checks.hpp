// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the tests of vtkLightconeSpacetimeView (tests/views) and of its dock (tests/gui) read off
// the view: executions per filter, the points an actor draws, and where to click on a ray.
#include "vtkLightconeSpacetimeView.h"

#include <vtkActor.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lc::test {

inline std::vector<int> executions(vtkLightconeSpacetimeView* view) {
    std::vector<int> c;
    for (int a = 0; a < vtkLightconeSpacetimeView::NUMBER_OF_ALGORITHMS; ++a) c.push_back(view->GetExecutionCount(a));
    return c;
}

// Executions of each algorithm since `before` (an earlier executions()).
inline std::vector<int> runsSince(vtkLightconeSpacetimeView* view, const std::vector<int>& before) {
    std::vector<int> c = executions(view);
    for (std::size_t a = 0; a < c.size(); ++a) c[a] -= before[a];
    return c;
}

// The points of what an actor's mapper draws (every block of a composite).
inline vtkIdType drawnPoints(vtkActor* actor) {
    vtkDataObject* input = actor->GetMapper()->GetInputDataObject(0, 0);
    if (auto* composite = vtkCompositeDataSet::SafeDownCast(input)) return composite->GetNumberOfPoints();
    auto* data = vtkDataSet::SafeDownCast(input);
    return data ? data->GetNumberOfPoints() : -1;
}

// The point of one polyline of the view's rays that lies farthest from every other ray (the planar
// Goedel rays are loops through the observer that cross each other): the pick tests click there.
// False for a cell without points.
inline bool isolatedPointOfRay(vtkPolyData* lines, vtkIdType cell, double p[3]) {
    if (cell < 0 || cell >= lines->GetNumberOfCells()) return false;
    vtkIdType npts = 0;
    const vtkIdType* ids = nullptr;
    lines->GetCellPoints(cell, npts, ids);
    double best = -1;
    for (vtkIdType k = 0; k < npts; k += 4) {
        double q[3];
        lines->GetPoint(ids[k], q);
        double nearest = std::numeric_limits<double>::infinity();
        for (vtkIdType other = 0; other < lines->GetNumberOfCells(); ++other) {
            if (other == cell) continue;
            vtkIdType m = 0;
            const vtkIdType* oids = nullptr;
            lines->GetCellPoints(other, m, oids);
            for (vtkIdType l = 0; l < m; ++l) {
                const double* o = lines->GetPoint(oids[l]);
                nearest = std::min(nearest, std::hypot(q[0] - o[0], q[1] - o[1], q[2] - o[2]));
            }
        }
        if (nearest > best) {
            best = nearest;
            std::copy(q, q + 3, p);
        }
    }
    return best >= 0;
}

}  // namespace lc::test
