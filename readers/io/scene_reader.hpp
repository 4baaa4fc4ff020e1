#pragma once
// JSON scene files -> lc::Scene. Schema in docs/SCENES.md. Every error is an InputError naming
// the file, line and field.
#include "core/scene.hpp"
#include "readers/io/json_document.hpp"

namespace lc::io {

Scene readScene(const std::string& file);
Scene parseScene(const std::string& text, const std::string& nameForMessages, const std::string& baseDir = ".");

// Where Debian's xplanet-images puts its maps; "earth" and "earth-night" textures name them.
std::string builtinTexturePath(const std::string& name);

}  // namespace lc::io
