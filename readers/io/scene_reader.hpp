// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// JSON scene files -> lc::Scene. Schema in docs/SCENES.md. Every error is an InputError naming
// the file, line and field.
#include "core/scene/scene.hpp"
#include "readers/io/json_document.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>

namespace lc::io {

// Reads a triangle mesh file into a MeshObject's geometry (positions, normals, triangles);
// throws std::runtime_error saying what is wrong. VTK-enabled programs supply one
// (readers/vtk); without it a scene with a mesh file is refused with a clear message.
using MeshLoader = std::function<void(const std::string& path, MeshObject& into)>;

// Image textures already read, by path: a scene read again (an edit in the GUI, every frame of
// a sweep) reuses them while the file's size and modification time are unchanged. Held weakly:
// a texture no scene uses any more is freed, not kept for later.
class TextureCache {
public:
    // The texture of `path`, from `load` when it is not held or the file has changed.
    TexturePtr get(const std::string& path, const std::function<TexturePtr()>& load);

private:
    struct Entry {
        std::filesystem::file_time_type modified;
        std::uintmax_t size = 0;
        std::weak_ptr<const Texture> texture;
    };
    std::mutex mutex_;
    std::map<std::string, Entry> entries_;
};

struct SceneReadOptions {
    MeshLoader meshLoader;
    std::shared_ptr<TextureCache> textures;  // none: every read loads its textures
};

Scene readScene(const std::string& file, const SceneReadOptions& options = {});
// A document already parsed (readers that keep the JSON tree, e.g. io::EditableScene).
Scene sceneFromDocument(const JsonDocument& doc, const std::string& baseDir, const SceneReadOptions& options = {});
Scene parseScene(const std::string& text, const std::string& nameForMessages, const std::string& baseDir = ".",
                 const SceneReadOptions& options = {});

// An event as messages show it: "(0, -24, 0, 0)", each number as the ranges print bounds.
std::string formatEvent(const Vec4& x);

// A scene's "metric" block read alone, as the scene reader reads it (a built-in by name and its
// parameters, or a formula file found relative to baseDir). Throws InputError.
SpacetimePtr metricFromBlock(const Json::Value& metric, const std::string& nameForMessages, const std::string& baseDir);

// A texture named as scene files name it in short: "checker", "earth", "earth-night" or an
// image file (relative to baseDir). Throws std::runtime_error saying why it cannot be loaded.
TexturePtr textureFromName(const std::string& name, const std::string& baseDir, const SceneReadOptions& options = {});

// Where Debian's xplanet-images puts its maps; "earth" and "earth-night" textures name them.
std::string builtinTexturePath(const std::string& name);

}  // namespace lc::io
