// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeRPhiDiagram_h
#define vtkLightconeRPhiDiagram_h
// The r-phi diagram of a Goedel scene (seed 000 Fig. 1, seed 001 Figs. 1-2): the observer at
// the centre, its fan of light rays in the plane z = 0 (closed curves), the Goedel horizon
// r = 2a, the objects, and the light path of every image of each object, drawn as a VTK chart
// in the observer's own chart (x = r cos phi, y = r sin phi) and exported to SVG, PDF or PNG
// with equal scales on both axes (vtkLightconeGodelDiagram: settings, legend, export).
#include "vtkLightconeGodelDiagram.h"

class vtkLightconeRPhiDiagram : public vtkLightconeGodelDiagram {
public:
    static vtkLightconeRPhiDiagram* New();
    vtkTypeMacro(vtkLightconeRPhiDiagram, vtkLightconeGodelDiagram)
    void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
    vtkLightconeRPhiDiagram();
    ~vtkLightconeRPhiDiagram() override;

    std::string DiagramName() const override { return "r-phi"; }
    void Draw(lc::views::DiagramChart& chart, double a, const lc::godel::ObserverView& view) override;

private:
    vtkLightconeRPhiDiagram(const vtkLightconeRPhiDiagram&) = delete;
    void operator=(const vtkLightconeRPhiDiagram&) = delete;
};

#endif
