// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeGodelDiagram_h
#define vtkLightconeGodelDiagram_h
// What every diagram of a Goedel scene shares (vtkLightconeRPhiDiagram, vtkLightconeTRDiagram):
// the scene and its check, the settings, building the chart (diagram_chart.hpp: legend
// outside the plot area), and the export to SVG, PDF or PNG through the atomic writer. A
// subclass draws its content in Draw() and names itself in DiagramName().
#include "core/godel/images.hpp"
#include "core/scene/scene.hpp"

#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <memory>
#include <string>
#include <vector>

class vtkContextView;
namespace lc::views {
class DiagramChart;
}

class vtkLightconeGodelDiagram : public vtkObject {
public:
    vtkTypeMacro(vtkLightconeGodelDiagram, vtkObject)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // The scene must use the 'godel' metric (std::invalid_argument otherwise); the observer may
    // be anywhere (static).
    void SetScene(const lc::Scene& scene);

    // Bounds as lc::input::kDiagramWindings, kRays and kDiagramSize (the CLI refuses the rest).
    vtkSetClampMacro(Windings, int, 0, 50);
    vtkGetMacro(Windings, int);
    vtkSetClampMacro(FanRays, int, 0, 720);
    vtkGetMacro(FanRays, int);
    // Window height in px; encoding widens the window by the legend's column.
    vtkSetClampMacro(Size, int, 200, 8000);
    vtkGetMacro(Size, int);
    // An index into the scene's spheres whose image paths are drawn emphasised (wider, their
    // colours) and the other objects' greyed, for a linked selection; -1 (default): all alike.
    vtkSetMacro(HighlightedObject, int);
    vtkGetMacro(HighlightedObject, int);

    // Crowded scenes: only the first MaxObjectsDrawn spheres and the highlighted one are drawn
    // one by one (outline or world line, light paths, legend entries); the others share one grey
    // plot of line segments without light paths (3000 spheres, one plot each, took the
    // workbench's r-phi diagram to 8 GB in llvmpipe's draw calls). Default 24.
    vtkSetClampMacro(MaxObjectsDrawn, int, 0, 1000000);
    vtkGetMacro(MaxObjectsDrawn, int);
    // How many spheres the last Build() drew in the shared plot only.
    int GetNumberOfObjectsSummarised() const { return this->ObjectsSummarised; }

    // Rebuilds the chart from the scene and the settings.
    void Build();
    int GetNumberOfImagePaths() const { return this->ImagePaths; }
    int GetNumberOfHighlightedImagePaths() const { return this->HighlightedImagePaths; }
    // The chart is item 0 of the view's scene.
    vtkContextView* GetView();

    // The file's bytes for a format (".svg", ".pdf", ".png"), the plot area at the subclass's
    // aspect ratio. Needs an X display (Xvfb).
    std::string Encode(const std::string& format);
    // Format from the extension, written through the atomic writer (readers/io/atomic_output.hpp).
    void Write(const std::string& path);

protected:
    vtkLightconeGodelDiagram();
    ~vtkLightconeGodelDiagram() override;

    // "r-phi", "t-r": in error messages and the exported document's title.
    virtual std::string DiagramName() const = 0;
    // Width / height of the plot area in the exported files.
    virtual double PlotAspect() const { return 1.0; }
    // Draws the scene into a fresh chart; a = the Goedel scale, view = the observer's chart.
    virtual void Draw(lc::views::DiagramChart& chart, double a, const lc::godel::ObserverView& view) = 0;
    // The light path of one image of sphere `object`, styled by the highlight; counts it.
    void AddImagePath(lc::views::DiagramChart& chart, const std::vector<double>& x, const std::vector<double>& y,
                      int object, const lc::godel::Image& image);

    // Whether sphere `object` is drawn one by one (see MaxObjectsDrawn).
    bool DrawnOneByOne(std::size_t object) const;
    // The outlines (or world lines) of the spheres not drawn one by one, each a polyline, as one
    // plot of segments labelled with their count; counts them.
    void AddSummarisedObjects(lc::views::DiagramChart& chart, const std::vector<std::vector<double>>& x,
                              const std::vector<std::vector<double>>& y, const std::string& what);

    lc::Scene Scene;
    int Windings = 1;
    int FanRays = 24;
    int Size = 900;
    int HighlightedObject = -1;
    int ImagePaths = 0;  // AddImagePath() counts the image paths drawn
    int HighlightedImagePaths = 0;
    int MaxObjectsDrawn = 24;
    int ObjectsSummarised = 0;

private:
    vtkLightconeGodelDiagram(const vtkLightconeGodelDiagram&) = delete;
    void operator=(const vtkLightconeGodelDiagram&) = delete;

    bool HasScene = false;
    std::unique_ptr<lc::views::DiagramChart> Chart;
};

#endif
