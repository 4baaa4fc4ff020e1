// `lightcone diagram`: the r-phi diagram of a Goedel scene as SVG, PDF and/or PNG.
#include "app/commands.hpp"
#include "readers/io/scene_reader.hpp"
#include "vtkLightconeRPhiDiagram.h"

#include <cstdio>
#include <cstdlib>

namespace lc::cli {

int runDiagram(const Args& args) {
    args.allow({"-o", "--output", "--windings", "--rays", "--size"});
    if (args.positional().size() != 1) throw std::invalid_argument("diagram expects one scene file");
    if (!std::getenv("DISPLAY"))
        throw std::runtime_error("VTK draws through GLX and needs an X display (hint: run under xvfb-run -a)");
    auto outputs = args.all("-o");
    for (const auto& o : args.all("--output")) outputs.push_back(o);
    if (outputs.empty()) outputs.push_back("diagram.svg");
    const Scene scene = io::readScene(args.positional()[0], sceneReadOptions());
    vtkNew<vtkLightconeRPhiDiagram> diagram;
    diagram->SetScene(scene);
    diagram->SetWindings(static_cast<int>(args.number("--windings", scene.settings.windings)));
    diagram->SetFanRays(static_cast<int>(args.number("--rays", 24)));
    diagram->SetSize(static_cast<int>(args.number("--size", 900)));
    diagram->Build();
    for (const auto& o : outputs) {
        diagram->Write(o);
        std::printf("wrote %s (%d image paths)\n", o.c_str(), diagram->GetNumberOfImagePaths());
    }
    return 0;
}

}  // namespace lc::cli
