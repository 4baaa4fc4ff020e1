// SPDX-License-Identifier: BSD-3-Clause
// `lightcone diagram`: the r-phi or t-r diagram of a Goedel scene as SVG, PDF and/or PNG.
#include "app/commands/commands.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/file_extension.hpp"
#include "readers/io/scene_reader.hpp"
#include "vtkLightconeRPhiDiagram.h"
#include "vtkLightconeTRDiagram.h"

#include <vtkSmartPointer.h>

#include <cstdio>
#include <cstdlib>

namespace lc::cli {

int writeDiagrams(const Scene& scene, const std::vector<std::string>& outputs, int windings, int rays, int size,
                  DiagramKind kind) {
    vtkSmartPointer<vtkLightconeGodelDiagram> diagram;
    if (kind == DiagramKind::TR)
        diagram = vtkSmartPointer<vtkLightconeTRDiagram>::New();
    else
        diagram = vtkSmartPointer<vtkLightconeRPhiDiagram>::New();
    diagram->SetScene(scene);
    diagram->SetWindings(windings);
    diagram->SetFanRays(rays);
    diagram->SetSize(size);
    diagram->Build();
    // Every format is drawn before any file is replaced.
    io::OutputSet files;
    for (const auto& out : outputs) files.add(out, diagram->Encode(io::lowerCaseExtension(out)), "-o");
    files.commit();
    return diagram->GetNumberOfImagePaths();
}

int runDiagram(const std::vector<std::string>& argv) {
    const DiagramOptions o = parseDiagramOptions(argv);
    for (const auto& out : o.outputs) io::checkOutputPath(out, {".svg", ".pdf", ".png"}, "-o");
    if (!std::getenv("DISPLAY"))
        throw std::runtime_error("VTK draws through GLX and needs an X display (hint: run under xvfb-run -a)");
    const Scene scene = io::readScene(o.scene, sceneReadOptions());
    if (scene.settings.windings > 50 && !o.windings)
        throw std::invalid_argument("the scene follows " + std::to_string(scene.settings.windings) +
                                    " windings; the diagram draws at most 50 (give --windings)");
    const int paths =
        writeDiagrams(scene, o.outputs, o.windings.value_or(scene.settings.windings), o.rays, o.size, o.kind);
    for (const auto& out : o.outputs) std::printf("wrote %s (%d image paths)\n", out.c_str(), paths);
    return 0;
}

}  // namespace lc::cli
