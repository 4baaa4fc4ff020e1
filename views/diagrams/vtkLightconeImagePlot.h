// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeImagePlot_h
#define vtkLightconeImagePlot_h
// An RGB(A) image drawn as a chart plot over a rectangle of data coordinates (the figure of a
// render with angular axes, image_figure.hpp): the image's first row at the top of the rectangle.
// vtkPlotHistogram2D draws one scalar through a colour map; this draws the colours as they are.
#include <vtkPlot.h>
#include <vtkSmartPointer.h>

class vtkImageData;

class vtkLightconeImagePlot : public vtkPlot {
public:
    static vtkLightconeImagePlot* New();
    vtkTypeMacro(vtkLightconeImagePlot, vtkPlot)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    // 8-bit RGB or RGBA, VTK's row order (row 0 at the bottom), 2D.
    void SetImage(vtkImageData* image);
    vtkImageData* GetImage();
    // The data rectangle it covers: x0 (left edge) to x1 (right), y0 (bottom) to y1 (top).
    void SetExtent(double x0, double x1, double y0, double y1);

    bool Paint(vtkContext2D* painter) override;
    void GetBounds(double bounds[4]) override;

protected:
    vtkLightconeImagePlot();
    ~vtkLightconeImagePlot() override;

private:
    vtkSmartPointer<vtkImageData> Image;
    double Extent[4] = {0, 1, 0, 1};

    vtkLightconeImagePlot(const vtkLightconeImagePlot&) = delete;
    void operator=(const vtkLightconeImagePlot&) = delete;
};

#endif
