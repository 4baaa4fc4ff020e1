#pragma once
#include "app/command_options.hpp"
#include "readers/io/scene_reader.hpp"

namespace lc::cli {
// Scene-reading options of this build (mesh files through VTK where available).
io::SceneReadOptions sceneReadOptions();

// argv: the arguments after the command name (parsed by app/command_options.hpp).
int runRender(const std::vector<std::string>& argv);
int runTrace(const std::vector<std::string>& argv);
int runImages(const std::vector<std::string>& argv);
int runShade(const std::vector<std::string>& argv);
int runDiagram(const std::vector<std::string>& argv);  // VTK builds only
int runExport(const std::vector<std::string>& argv);   // VTK builds only
int renderWithShaders(const Scene& scene, const std::string& output, int orbitFrames, bool polygonDistortion);  // VTK builds only
}  // namespace lc::cli
