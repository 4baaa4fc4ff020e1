// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What every output says about the program that wrote it: images (the "Software" text of PNG,
// EXR and TIFF headers), VTK files (field data "lightcone_version") and session files
// ("written_by"), so a figure can be traced back to the build that made it.
#include <string>

namespace lc::io {

// The one reading of the version and the commit: `lightcone --version`, the workbench's About,
// Python's __version__, the man pages and every output take them from here.
std::string versionNumber();  // "0.1.0" (CMake's project())
std::string buildCommit();    // the short commit built (HEAD at the last build), or "unknown"
// "Lightcone 0.1.0 (commit abc1234)".
std::string softwareName();

}  // namespace lc::io
