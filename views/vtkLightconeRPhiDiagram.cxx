#include "vtkLightconeRPhiDiagram.h"

#include "core/godel/images.hpp"
#include "core/godel/isometry.hpp"
#include "core/metrics/godel.hpp"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkObjectFactory.h>
#include <vtkPDFExporter.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSVGExporter.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <cstdlib>

#include "readers/io/atomic_output.hpp"
#include "readers/io/file_extension.hpp"
#include "readers/io/input_file.hpp"

vtkStandardNewMacro(vtkLightconeRPhiDiagram);

namespace {
namespace fs = std::filesystem;

// Distinct colours for the image paths (colour-blind safe, Okabe-Ito).
const double kImageColours[][3] = {{0.90, 0.62, 0.0}, {0.34, 0.71, 0.91}, {0.0, 0.62, 0.45},  {0.80, 0.47, 0.65},
                                   {0.84, 0.37, 0.0}, {0.0, 0.45, 0.70},  {0.94, 0.89, 0.26}, {0.5, 0.5, 0.5}};
}  // namespace

vtkLightconeRPhiDiagram::vtkLightconeRPhiDiagram() = default;
vtkLightconeRPhiDiagram::~vtkLightconeRPhiDiagram() = default;

void vtkLightconeRPhiDiagram::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Windings: " << this->Windings << "\n"
       << indent << "FanRays: " << this->FanRays << "\n"
       << indent << "Size: " << this->Size << "\n"
       << indent << "ImagePaths: " << this->ImagePaths << "\n";
}

void vtkLightconeRPhiDiagram::SetScene(const lc::Scene& scene) {
    if (!dynamic_cast<const lc::GodelCartesian*>(scene.spacetime.get()))
        throw std::invalid_argument("the r-phi diagram needs a scene with the 'godel' metric");
    this->Scene = scene;
    this->HasScene = true;
    this->Modified();
}

vtkContextView* vtkLightconeRPhiDiagram::GetView() {
    if (!this->View) this->Build();
    return this->View;
}

void vtkLightconeRPhiDiagram::AddCurve(const std::vector<double>& x, const std::vector<double>& y, const double rgb[3],
                                       float width, const std::string& label, int lineType) {
    vtkNew<vtkTable> table;
    vtkNew<vtkDoubleArray> xs, ys;
    const std::string id = std::to_string(this->CurveCount++);
    xs->SetName(("x" + id).c_str());
    ys->SetName(("y" + id).c_str());
    xs->SetNumberOfValues(static_cast<vtkIdType>(x.size()));
    ys->SetNumberOfValues(static_cast<vtkIdType>(y.size()));
    for (std::size_t i = 0; i < x.size(); ++i) {
        xs->SetValue(static_cast<vtkIdType>(i), x[i]);
        ys->SetValue(static_cast<vtkIdType>(i), y[i]);
    }
    table->AddColumn(xs);
    table->AddColumn(ys);
    vtkPlot* plot = this->Chart->AddPlot(vtkChart::LINE);
    plot->SetInputData(table, 0, 1);
    plot->SetColor(rgb[0], rgb[1], rgb[2]);
    plot->SetWidth(width);
    plot->GetPen()->SetLineType(lineType);
    plot->SetLabel(label);
    plot->SetLegendVisibility(!label.empty());
}

void vtkLightconeRPhiDiagram::Build() {
    if (!this->HasScene) throw std::logic_error("vtkLightconeRPhiDiagram: SetScene() first");
    const double a = static_cast<const lc::GodelCartesian&>(*this->Scene.spacetime).a();
    const lc::godel::ObserverView view(a, this->Scene.observer);

    this->View = vtkSmartPointer<vtkContextView>::New();
    this->View->GetRenderWindow()->SetSize(this->Size, this->Size);
    this->View->GetRenderer()->SetBackground(1, 1, 1);
    this->Chart = vtkSmartPointer<vtkChartXY>::New();
    this->View->GetScene()->AddItem(this->Chart);
    this->CurveCount = 0;
    this->ImagePaths = 0;
    this->Chart->SetTitle("Goedel universe, r-phi plane of the observer (a = " + std::to_string(a).substr(0, 4) + ")");
    const double extent = 2.3 * a;
    for (int axis : {vtkAxis::BOTTOM, vtkAxis::LEFT}) {
        vtkAxis* ax = this->Chart->GetAxis(axis);
        ax->SetBehavior(vtkAxis::FIXED);
        ax->SetRange(-extent, extent);
        ax->SetTitle(axis == vtkAxis::BOTTOM ? "x = r cos(phi)" : "y = r sin(phi)");
    }
    this->Chart->SetShowLegend(true);

    // Fan of light rays in the plane z = 0 (k3 = 0): closed curves through the observer that
    // touch the horizon. One winding retraces the same curve.
    const double grey[3] = {0.75, 0.75, 0.75};
    for (int k = 0; k < this->FanRays; ++k) {
        const double phi0 = 2 * lc::kPi * k / this->FanRays;
        const auto ray = lc::godel::OriginGeodesic::null(a, lc::kPi / 2, phi0, -1);
        std::vector<double> x, y;
        for (int s = 0; s <= 200; ++s) {
            const lc::Vec4 p = ray.cartesian(2 * lc::kPi * a * s / 200);
            x.push_back(p(1));
            y.push_back(p(2));
        }
        this->AddCurve(x, y, grey, 1.0f, k == 0 ? "light rays from the observer (z = 0)" : "", vtkPen::SOLID_LINE);
    }

    // The horizon r = 2a.
    {
        std::vector<double> x, y;
        for (int s = 0; s <= 360; ++s) {
            x.push_back(2 * a * std::cos(lc::kPi * s / 180));
            y.push_back(2 * a * std::sin(lc::kPi * s / 180));
        }
        const double red[3] = {0.8, 0.1, 0.1};
        this->AddCurve(x, y, red, 2.0f, "Goedel horizon r = 2a", vtkPen::DASH_LINE);
    }

    // Objects (outline of the equatorial circle of each sphere in its own frame) and the light
    // path of every image of its centre.
    int colour = 0;
    for (const auto& s : this->Scene.spheres) {
        const lc::godel::Isometry fromCentre = lc::godel::Isometry::movingOriginTo(a, s.centre);
        std::vector<double> x, y;
        for (int k = 0; k <= 72; ++k) {
            const double th = 2 * lc::kPi * k / 72;
            const lc::Vec4 w = fromCentre.apply(lc::Vec4(0, s.radius * std::cos(th), s.radius * std::sin(th), 0));
            const lc::Vec4 o = view.event(w);
            x.push_back(o(1));
            y.push_back(o(2));
        }
        const double black[3] = {0.1, 0.1, 0.1};
        this->AddCurve(x, y, black, 2.0f, "object '" + s.name + "'", vtkPen::SOLID_LINE);

        const lc::godel::ImageSet images = view.images(s.centre.tail<3>(), this->Windings);
        for (const auto& im : images.images) {
            const auto ray = im.ray(a);
            std::vector<double> px, py;
            const int n = 400;
            for (int k = 0; k <= n; ++k) {
                const lc::Vec4 p = ray.cartesian(im.lambda * k / n);
                px.push_back(p(1));
                py.push_back(p(2));
            }
            char label[160];
            std::snprintf(label, sizeof label, "image of '%s': winding %d, %s, emitted t = %.3f", s.name.c_str(),
                          im.winding, lc::godel::branchName(im.branch).c_str(), im.emissionTime);
            // Later windings retrace earlier paths in this plane: draw the earlier ones wider so
            // that every path stays visible underneath.
            const float width = std::max(1.5f, 7.0f - 2.0f * static_cast<float>(im.winding));
            this->AddCurve(px, py, kImageColours[colour++ % 8], width, label, vtkPen::SOLID_LINE);
            ++this->ImagePaths;
        }
    }
}

std::string vtkLightconeRPhiDiagram::Encode(const std::string& format) {
    if (format != ".svg" && format != ".pdf" && format != ".png")
        throw std::invalid_argument("diagram: unknown format '" + format + "' (use .svg, .pdf or .png)");
    if (!this->View) this->Build();
    vtkRenderWindow* win = this->View->GetRenderWindow();
    win->SetOffScreenRendering(1);
    win->Render();
    if (format == ".png") {
        vtkNew<vtkWindowToImageFilter> grab;
        grab->SetInput(win);
        grab->ReadFrontBufferOff();
        grab->Update();
        vtkNew<vtkPNGWriter> png;
        png->SetInputConnection(grab->GetOutputPort());
        png->WriteToMemoryOn();
        png->Write();
        vtkUnsignedCharArray* bytes = png->GetResult();
        if (!bytes || bytes->GetNumberOfValues() == 0)
            throw std::runtime_error("diagram: PNG encoding failed (is there an X display?)");
        return std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)),
                           static_cast<std::size_t>(bytes->GetNumberOfValues()));
    }
    // The GL2PS exporters write only to files: a private scratch folder, read back and removed,
    // so the output itself goes through the atomic writer like every other file.
    std::string scratch = (fs::temp_directory_path() / "lightcone-diagram-XXXXXX").string();
    if (!::mkdtemp(scratch.data()))
        throw std::runtime_error("diagram: cannot create a scratch folder in " + fs::temp_directory_path().string());
    const fs::path file = fs::path(scratch) / ("diagram" + format);
    std::string bytes;
    try {
        if (format == ".svg") {
            vtkNew<vtkSVGExporter> svg;
            svg->SetRenderWindow(win);
            svg->SetFileName(file.string().c_str());
            svg->SetTitle("Lightcone r-phi diagram");
            svg->TextAsPathOff();  // keep labels searchable and editable
            svg->Write();
        } else {
            vtkNew<vtkPDFExporter> pdf;
            pdf->SetRenderWindow(win);
            pdf->SetFileName(file.string().c_str());
            pdf->SetTitle("Lightcone r-phi diagram");
            pdf->Write();
        }
        bytes = lc::io::readInputFile(file.string(), lc::input::kSceneFileBytes);
    } catch (const std::exception& e) {
        std::error_code ec;
        fs::remove_all(scratch, ec);
        throw std::runtime_error(std::string("diagram: the exporter wrote no file (is there an X display?): ") +
                                 e.what());
    }
    std::error_code ec;
    fs::remove_all(scratch, ec);
    return bytes;
}

void vtkLightconeRPhiDiagram::Write(const std::string& path) {
    lc::io::writeFileAtomically(path, this->Encode(lc::io::lowerCaseExtension(path)));
}
