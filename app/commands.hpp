#pragma once
#include "app/cli_args.hpp"
#include "readers/io/scene_reader.hpp"

namespace lc::cli {
// Scene-reading options of this build (mesh files through VTK where available).
io::SceneReadOptions sceneReadOptions();

int runRender(const Args& args);
int runTrace(const Args& args);
int runImages(const Args& args);
int runShade(const Args& args);
int runDiagram(const Args& args);  // VTK builds only
int runExport(const Args& args);   // VTK builds only
int renderWithShaders(const Scene& scene, const std::string& output, int orbitFrames, bool polygonDistortion);  // VTK builds only
}  // namespace lc::cli
