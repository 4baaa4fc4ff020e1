// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the first byte picks the file type (byte % 4: 0 .obj, 1 .ply, 2 .stl,
// 3 .vtp), the remaining bytes are written to a temporary file of that type, which
// lc::io::loadMeshWithVtk reads (our OBJ/PLY/STL walkers, VTK for VTP). A std::exception is a refusal (expected for bad
// files); a mesh it returns must be usable: every triangle index within [0, positions.size()) and every position
// finite, else the target aborts (a finding), as it does on crashes, sanitizer reports, hangs and other exceptions.
#include "vtkLightconeMeshLoader.h"

#include <vtkObject.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace {
namespace fs = std::filesystem;

const char* const kExtensions[] = {".obj", ".ply", ".stl", ".vtp"};
bool gVerbose = false;  // LIGHTCONE_FUZZ_VERBOSE set: VTK's messages and what became of the input

[[noreturn]] void finding(const char* what, std::size_t index) {
    std::fprintf(stderr, "fuzz_mesh_loader: loaded mesh is invalid: %s (index %zu)\n", what, index);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // VTK readers report bad files on stderr; silent unless asked (reproducing an artifact).
    gVerbose = std::getenv("LIGHTCONE_FUZZ_VERBOSE") != nullptr;
    if (!gVerbose) vtkObject::GlobalWarningDisplayOff();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    const fs::path path =
        fs::temp_directory_path() / ("lightcone-fuzz-mesh-" + std::to_string(::getpid()) + kExtensions[data[0] % 4]);
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    }
    lc::MeshObject mesh;
    bool loaded = false;
    try {
        lc::io::loadMeshWithVtk(path.string(), mesh);
        loaded = true;
    } catch (const std::exception& e) {
        // Refused: the expected outcome for bad files.
        if (gVerbose) std::fprintf(stderr, "fuzz_mesh_loader: %s refused: %s\n", kExtensions[data[0] % 4], e.what());
    }
    std::error_code ignored;
    fs::remove(path, ignored);
    if (!loaded) return 0;
    if (gVerbose)
        std::fprintf(stderr, "fuzz_mesh_loader: %s loaded: %zu points, %zu triangles\n", kExtensions[data[0] % 4],
                     mesh.positions.size(), mesh.triangles.size());

    const std::size_t n = mesh.positions.size();
    for (std::size_t i = 0; i < n; ++i)
        if (!mesh.positions[i].allFinite()) finding("position not finite", i);
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
        for (const int v : mesh.triangles[i])
            if (v < 0 || static_cast<std::size_t>(v) >= n) finding("triangle index out of range", i);
    return 0;
}
