// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `lightcone --version`: the program's version, the git commit it was built from, the build
// type and the versions of the libraries it was built with (VTK, Qt, OpenImageIO, Eigen, Boost,
// the compiler). Known at build time, so printing it loads nothing.
#include <string>

namespace lc::cli {

std::string versionNumber();  // "0.1.0"
std::string buildCommit();    // the short commit built (HEAD at the last build), or "unknown"
std::string versionText();    // several lines, the first "lightcone 0.1.0 (commit abc1234, Release)"

}  // namespace lc::cli
