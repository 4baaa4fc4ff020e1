// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What every output says about the program that wrote it: images (the "Software" text of PNG,
// EXR and TIFF headers), VTK files (field data "lightcone_version") and session files
// ("written_by"), so a figure can be traced back to the build that made it.
#include <string>

namespace lc::io {

// "Lightcone 0.1.0 (commit abc1234)": the version and the commit CMake was configured from.
std::string softwareName();

}  // namespace lc::io
