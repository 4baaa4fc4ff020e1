#ifndef vtkLightconeRPhiDiagram_h
#define vtkLightconeRPhiDiagram_h
// The r-phi diagram of a Goedel scene (seed 000 Fig. 1, seed 001 Figs. 1-2): the observer at
// the centre, its fan of light rays in the plane z = 0 (closed curves), the Goedel horizon
// r = 2a, the objects, and the light path of every image of each object, drawn as a VTK chart
// in the observer's own chart (x = r cos phi, y = r sin phi) and exported to SVG, PDF or PNG.
#include "core/scene/scene.hpp"

#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <string>

class vtkChartXY;
class vtkContextView;

class vtkLightconeRPhiDiagram : public vtkObject {
public:
    static vtkLightconeRPhiDiagram* New();
    vtkTypeMacro(vtkLightconeRPhiDiagram, vtkObject)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // The scene must use the 'godel' metric; the observer may be anywhere (static).
    void SetScene(const lc::Scene& scene);

    // Bounds as lc::input::kDiagramWindings, kRays and kDiagramSize (the CLI refuses the rest).
    vtkSetClampMacro(Windings, int, 0, 50);
    vtkGetMacro(Windings, int);
    vtkSetClampMacro(FanRays, int, 0, 720);
    vtkGetMacro(FanRays, int);
    vtkSetClampMacro(Size, int, 200, 8000);
    vtkGetMacro(Size, int);

    // Rebuilds the chart from the scene and the settings.
    void Build();
    int GetNumberOfImagePaths() const { return this->ImagePaths; }
    vtkContextView* GetView();

    // The file's bytes for a format (".svg", ".pdf", ".png"). Needs an X display (Xvfb).
    std::string Encode(const std::string& format);
    // Format from the extension, written through the atomic writer (readers/io/atomic_output.hpp).
    void Write(const std::string& path);

protected:
    vtkLightconeRPhiDiagram();
    ~vtkLightconeRPhiDiagram() override;

private:
    vtkLightconeRPhiDiagram(const vtkLightconeRPhiDiagram&) = delete;
    void operator=(const vtkLightconeRPhiDiagram&) = delete;

    void AddCurve(const std::vector<double>& x, const std::vector<double>& y, const double rgb[3], float width,
                  const std::string& label, int lineType);

    lc::Scene Scene;
    bool HasScene = false;
    int Windings = 1;
    int FanRays = 24;
    int Size = 900;
    int ImagePaths = 0;
    int CurveCount = 0;
    vtkSmartPointer<vtkContextView> View;
    vtkSmartPointer<vtkChartXY> Chart;
};

#endif
