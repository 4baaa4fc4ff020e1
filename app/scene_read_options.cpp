// The scene reader's options of this build: mesh files through VTK where available.
#include "app/commands.hpp"

#ifdef LIGHTCONE_WITH_VTK
#include "vtkLightconeMeshLoader.h"
#endif

namespace lc::cli {
io::SceneReadOptions sceneReadOptions() {
    io::SceneReadOptions o;
#ifdef LIGHTCONE_WITH_VTK
    o.meshLoader = io::loadMeshWithVtk;
#endif
    return o;
}
}  // namespace lc::cli
