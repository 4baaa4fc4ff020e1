// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeImagePlot.h"

#include <vtkContext2D.h>
#include <vtkImageData.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkRect.h>

#include <stdexcept>
#include <string>

vtkStandardNewMacro(vtkLightconeImagePlot);

vtkLightconeImagePlot::vtkLightconeImagePlot() = default;
vtkLightconeImagePlot::~vtkLightconeImagePlot() = default;

void vtkLightconeImagePlot::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Extent: " << this->Extent[0] << " " << this->Extent[1] << " " << this->Extent[2] << " "
       << this->Extent[3] << "\n"
       << indent << "Image: " << (this->Image ? "set" : "none") << "\n";
}

void vtkLightconeImagePlot::SetImage(vtkImageData* image) {
    if (image) {
        vtkDataArray* colours = image->GetPointData()->GetScalars();
        const int components = colours ? colours->GetNumberOfComponents() : 0;
        if (!colours || colours->GetDataType() != VTK_UNSIGNED_CHAR || (components != 3 && components != 4) ||
            image->GetDimensions()[2] != 1)
            throw std::invalid_argument("vtkLightconeImagePlot: the image must be 2D, 8-bit RGB or RGBA (got " +
                                        std::to_string(components) + " components)");
    }
    this->Image = image;
    this->Modified();
}

vtkImageData* vtkLightconeImagePlot::GetImage() { return this->Image; }

void vtkLightconeImagePlot::SetExtent(double x0, double x1, double y0, double y1) {
    if (!(x1 > x0 && y1 > y0))
        throw std::invalid_argument("vtkLightconeImagePlot: the extent must have x1 > x0 and y1 > y0");
    this->Extent[0] = x0;
    this->Extent[1] = x1;
    this->Extent[2] = y0;
    this->Extent[3] = y1;
    this->Modified();
}

bool vtkLightconeImagePlot::Paint(vtkContext2D* painter) {
    if (!this->Image || !this->Visible) return true;
    painter->DrawImage(vtkRectf(static_cast<float>(this->Extent[0]), static_cast<float>(this->Extent[2]),
                                static_cast<float>(this->Extent[1] - this->Extent[0]),
                                static_cast<float>(this->Extent[3] - this->Extent[2])),
                       this->Image);
    return true;
}

void vtkLightconeImagePlot::GetBounds(double bounds[4]) {
    for (int k = 0; k < 4; ++k) bounds[k] = this->Extent[k];
}
