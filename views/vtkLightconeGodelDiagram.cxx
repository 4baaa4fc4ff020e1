#include "vtkLightconeGodelDiagram.h"

#include "core/metrics/godel.hpp"
#include "lightconeDiagramChart.h"
#include "readers/io/atomic_output.hpp"
#include "readers/io/file_extension.hpp"

#include <stdexcept>

vtkLightconeGodelDiagram::vtkLightconeGodelDiagram() = default;
vtkLightconeGodelDiagram::~vtkLightconeGodelDiagram() = default;

void vtkLightconeGodelDiagram::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    os << indent << "Windings: " << this->Windings << "\n"
       << indent << "FanRays: " << this->FanRays << "\n"
       << indent << "Size: " << this->Size << "\n"
       << indent << "ImagePaths: " << this->ImagePaths << "\n";
}

void vtkLightconeGodelDiagram::SetScene(const lc::Scene& scene) {
    if (!dynamic_cast<const lc::GodelCartesian*>(scene.spacetime.get()))
        throw std::invalid_argument("the " + this->DiagramName() + " diagram needs a scene with the 'godel' metric");
    this->Scene = scene;
    this->HasScene = true;
    this->Modified();
}

void vtkLightconeGodelDiagram::Build() {
    if (!this->HasScene) throw std::logic_error(std::string(this->GetClassName()) + ": SetScene() first");
    const double a = static_cast<const lc::GodelCartesian&>(*this->Scene.spacetime).a();
    this->Chart = std::make_unique<lc::views::DiagramChart>(this->Size);
    this->ImagePaths = 0;
    this->Draw(*this->Chart, a, lc::godel::ObserverView(a, this->Scene.observer));
}

vtkContextView* vtkLightconeGodelDiagram::GetView() {
    if (!this->Chart) this->Build();
    return this->Chart->view();
}

std::string vtkLightconeGodelDiagram::Encode(const std::string& format) {
    if (!this->Chart) this->Build();
    return this->Chart->encode(format, "Lightcone " + this->DiagramName() + " diagram", this->PlotAspect());
}

void vtkLightconeGodelDiagram::Write(const std::string& path) {
    lc::io::writeFileAtomically(path, this->Encode(lc::io::lowerCaseExtension(path)));
}
