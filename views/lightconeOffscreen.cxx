#include "lightconeOffscreen.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCullerCollection.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

namespace lc::views {

vtkSmartPointer<vtkPolyData> clipSpaceQuad() {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    const double corners[4][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    vtkNew<vtkFloatArray> tcoords;
    tcoords->SetName("TCoords");
    tcoords->SetNumberOfComponents(2);
    for (const auto& c : corners) {
        points->InsertNextPoint(c);
        tcoords->InsertNextTuple2(0.5 * (c[0] + 1), 0.5 * (c[1] + 1));
    }
    vtkNew<vtkCellArray> cells;
    const vtkIdType t0[3] = {0, 1, 2}, t1[3] = {0, 2, 3};
    cells->InsertNextCell(3, t0);
    cells->InsertNextCell(3, t1);
    auto quad = vtkSmartPointer<vtkPolyData>::New();
    quad->SetPoints(points);
    quad->SetPolys(cells);
    quad->GetPointData()->SetTCoords(tcoords);
    return quad;
}

vtkSmartPointer<vtkRenderWindow> offscreenWindow(int width, int height, vtkActor* actor) {
    vtkNew<vtkRenderer> renderer;
    renderer->GetCullers()->RemoveAllItems();  // the quad is in clip space, not in the camera's view
    renderer->SetUseDepthPeeling(false);
    renderer->SetUseFXAA(false);
    renderer->SetBackground(0, 0, 0);
    renderer->AddActor(actor);
    auto window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);  // one sample per pixel: one ray per pixel, exact ids
    window->SetSize(width, height);
    window->AddRenderer(renderer);
    return window;
}

}  // namespace lc::views
