#pragma once
// JSON scene files -> lc::Scene. Schema in docs/SCENES.md. Every error is an InputError naming
// the file, line and field.
#include "core/scene/scene.hpp"
#include "readers/io/json_document.hpp"

#include <functional>

namespace lc::io {

// Reads a triangle mesh file into a MeshObject's geometry (positions, normals, triangles);
// throws std::runtime_error saying what is wrong. VTK-enabled programs supply one
// (readers/vtk); without it a scene with a mesh file is refused with a clear message.
using MeshLoader = std::function<void(const std::string& path, MeshObject& into)>;

struct SceneReadOptions {
    MeshLoader meshLoader;
};

Scene readScene(const std::string& file, const SceneReadOptions& options = {});
// A document already parsed (readers that keep the JSON tree, e.g. io::EditableScene).
Scene sceneFromDocument(const JsonDocument& doc, const std::string& baseDir, const SceneReadOptions& options = {});
Scene parseScene(const std::string& text, const std::string& nameForMessages, const std::string& baseDir = ".",
                 const SceneReadOptions& options = {});

// Where Debian's xplanet-images puts its maps; "earth" and "earth-night" textures name them.
std::string builtinTexturePath(const std::string& name);

}  // namespace lc::io
