// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the bytes are a scene file's JSON text, read by lc::io::parseScene with the
// VTK mesh loader. An exception derived from std::exception is how hostile input is refused;
// a crash, a sanitizer report, a hang or any other exception is a finding.
//
// Relative mesh and texture paths resolve against a fixed, otherwise empty temporary folder
// (never the project), in which a few small files are written so that scenes naming them
// (tests/fuzz/corpus/scene) reach the mesh and image readers: tri.obj, tri.ply, tri.stl,
// tri.vtp and tex.ppm.
#include "readers/io/scene_reader.hpp"
#include "tests/fuzz/fuzz_files.hpp"
#include "vtkLightconeMeshLoader.h"

#include <vtkObject.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace {
namespace fs = std::filesystem;

std::string gBaseDir;
bool gVerbose = false;  // LIGHTCONE_FUZZ_VERBOSE set: VTK's messages and why a scene was refused

using lc::fuzz::writeFile;

void makeBaseDir() {
    const fs::path dir = fs::temp_directory_path() / "lightcone-fuzz-scene";
    fs::create_directories(dir);
    writeFile(dir, "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n");
    writeFile(dir, "tri.ply",
              "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
              "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    writeFile(dir, "tri.stl",
              "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
              "endsolid t\n");
    writeFile(dir, "tri.vtp",
              "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
              "<PolyData><Piece NumberOfPoints=\"3\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
              "NumberOfPolys=\"1\">\n<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">"
              "0 0 0 1 0 0 0 1 0</DataArray></Points>\n<Polys><DataArray type=\"Int32\" Name=\"connectivity\" "
              "format=\"ascii\">0 1 2</DataArray><DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3"
              "</DataArray></Polys>\n</Piece></PolyData></VTKFile>\n");
    writeFile(dir, "tex.ppm", "P3\n2 2\n255\n255 0 0  0 255 0\n0 0 255  255 255 255\n");
    gBaseDir = dir.string();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    makeBaseDir();
    // VTK readers report bad files on stderr; silent unless asked (reproducing an artifact).
    gVerbose = std::getenv("LIGHTCONE_FUZZ_VERBOSE") != nullptr;
    if (!gVerbose) vtkObject::GlobalWarningDisplayOff();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    lc::io::SceneReadOptions options;
    options.meshLoader = lc::io::loadMeshWithVtk;
    try {
        const lc::Scene scene = lc::io::parseScene(text, "fuzz.json", gBaseDir, options);
        if (gVerbose)
            std::fprintf(stderr, "fuzz_scene_reader: read: %zu spheres, %zu meshes, %zu lights\n", scene.spheres.size(),
                         scene.meshes.size(), scene.lights.size());
    } catch (const std::exception& e) {
        // Refused: the expected outcome for bad input.
        if (gVerbose) std::fprintf(stderr, "fuzz_scene_reader: refused: %s\n", e.what());
    }
    return 0;
}
