// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the bytes are a GUI session file (docs/SESSIONS.md), read by
// lc::io::parseSession and opened by lc::io::openSessionScene, which applies the session's edits
// to a real scene through the scene reader. An exception derived from std::exception is how
// hostile input is refused; a crash, a sanitizer report, a hang or any other exception is a finding.
//
// The session "lives" in a fixed temporary folder (never the project) holding scene.json (a small
// Goedel scene) and tri.obj, so sessions naming them reach the edit and mesh paths.
#include "readers/io/session_file.hpp"
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

std::string gSessionFile;
bool gVerbose = false;  // LIGHTCONE_FUZZ_VERBOSE set: why a session was refused

using lc::fuzz::writeFile;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const fs::path dir = fs::temp_directory_path() / "lightcone-fuzz-session";
    fs::create_directories(dir);
    writeFile(
        dir, "scene.json",
        "{\"metric\": {\"name\": \"godel\", \"a\": 1},\n"
        " \"camera\": {\"projection\": \"panorama\", \"width\": 8, \"height\": 4, \"fov\": [360, 120]},\n"
        " \"objects\": [{\"type\": \"sphere\", \"name\": \"ball\", \"centre\": [0, 1, 0, 0], \"radius\": 0.25}],\n"
        " \"render\": {\"windings\": 1}}\n");
    writeFile(dir, "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n");
    gSessionFile = (dir / "fuzz.lcsession").string();
    gVerbose = std::getenv("LIGHTCONE_FUZZ_VERBOSE") != nullptr;
    if (!gVerbose) vtkObject::GlobalWarningDisplayOff();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    lc::io::SceneReadOptions options;
    options.meshLoader = lc::io::loadMeshWithVtk;
    try {
        const lc::io::SessionFile session = lc::io::parseSession(text, gSessionFile);
        const lc::io::OpenedSession opened = lc::io::openSessionScene(session, gSessionFile, options);
        // Writing it back must not fail for anything that was read.
        (void)lc::io::sessionText(session);
        if (gVerbose)
            std::fprintf(stderr, "fuzz_session_reader: opened with %zu edits%s\n", opened.scene.edits().size(),
                         opened.notice.empty() ? "" : " (from the saved copy)");
    } catch (const std::exception& e) {
        if (gVerbose) std::fprintf(stderr, "fuzz_session_reader: refused: %s\n", e.what());
    }
    return 0;
}
