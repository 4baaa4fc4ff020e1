// SPDX-License-Identifier: BSD-3-Clause
// The scene reader's options of this build (mesh files through VTK where available), and the
// scene of a command: a file or a session.
#include "app/commands/commands.hpp"
#include "readers/io/session_file.hpp"

#include <cstdio>

#ifdef LIGHTCONE_WITH_VTK
#include "vtkLightconeMeshLoader.h"
#endif

namespace lc::cli {
io::SceneReadOptions sceneReadOptions() {
    // One texture cache for the process: a sweep's frames and the GUI's edits share the images.
    static const auto textures = std::make_shared<io::TextureCache>();
    io::SceneReadOptions o;
    o.textures = textures;
#ifdef LIGHTCONE_WITH_VTK
    o.meshLoader = io::loadMeshWithVtk;
#endif
    return o;
}

io::EditableScene loadEditableScene(const RenderOptions& opt) {
    if (opt.session.empty()) return io::EditableScene::load(opt.scene, sceneReadOptions());
    io::OpenedSession opened = io::openSessionScene(io::readSession(opt.session), opt.session, sceneReadOptions());
    if (!opened.notice.empty()) std::fprintf(stderr, "note: %s\n", opened.notice.c_str());
    return std::move(opened.scene);
}
}  // namespace lc::cli
