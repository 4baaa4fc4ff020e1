// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Where an installed (or built) Lightcone finds its own files: the image codec module and the
// scenes and metrics of data/. Every place is found from the running program's own file, never
// from a path fixed at build time, so an installed tree may be moved (relocatable) and holds no
// path of the build tree.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lc::io {

// The file that holds this code: the lightcone executable, the workbench, a test program or the
// Python module (dladdr), made absolute.
std::filesystem::path programFile();

// The first `folder / relative` that exists, for the program's folder and each folder above it.
std::optional<std::filesystem::path> findAboveProgram(const std::filesystem::path& relative);

// The folders a scene or metric file given by a bare name is looked for in, in order:
// each folder of $LIGHTCONE_DATA_PATH (colon separated), then the installed data
// (PREFIX/share/lightcone/data, after its metrics/ for metric files), or for a program in a build
// tree inside the checkout, the checkout's data/.
std::vector<std::filesystem::path> dataSearchPath(bool metricFiles);

// `given` itself when it names a file (relative to the working folder, or absolute); else the
// first file of that relative name in dataSearchPath() (a metric also by its name without
// ".json"). Unchanged when found nowhere, so that the
// reader's "no such file" names what the user typed; `searchedNote` then says where it looked.
std::string findDataFile(const std::string& given, bool metricFile, std::string* searchedNote = nullptr);

}  // namespace lc::io
